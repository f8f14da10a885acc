#pragma once

#include <chrono>

namespace morphogen::bench {

// Runs batches of `batch` steps until `seconds` have passed; returns steps/s.
// `finish` must wait for the work to complete (glFinish on the GPU).
template <typename Run, typename Finish>
double measureStepsPerSecond(Run&& run, Finish&& finish, double seconds, int batch) {
    using Clock = std::chrono::steady_clock;
    run(batch); // warm-up: shader compilation, first-touch allocation
    finish();
    int steps = 0;
    const auto start = Clock::now();
    double elapsed = 0;
    do {
        run(batch);
        finish();
        steps += batch;
        elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < seconds);
    return steps / elapsed;
}

} // namespace morphogen::bench
