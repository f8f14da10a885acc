#include "bench/bench_backends.hpp"

#include "bench/bench_timing.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::bench {

std::vector<std::pair<std::string, Make>> simulatorBackends(bool gpu, bool cpu) {
    std::vector<std::pair<std::string, Make>> backends;
    if (gpu)
        backends.emplace_back(
            "gpu", [](const Session& s) { return std::make_unique<gl::GpuSimulator>(s); });
    if (cpu)
        backends.emplace_back("cpu",
                              [](const Session& s) { return std::make_unique<CpuSimulator>(s); });
    return backends;
}

double sessionStepsPerSecond(const Session& s, const Make& make, bool gpu, double seconds) {
    std::unique_ptr<Simulator> sim = make(s);
    sim->setState(initialState(s));
    return measureStepsPerSecond([&](int n) { sim->run(n); },
                                 [gpu] {
                                     if (gpu)
                                         glFinish();
                                 },
                                 seconds, 20);
}

} // namespace morphogen::bench
