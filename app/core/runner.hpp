#pragma once

#include <atomic>
#include <functional>

#include "core/simulator.hpp"

namespace morphogen {

struct RunOptions {
    // Steps between read-backs. Each chunk ends with a blow-up check and a
    // progress report; nothing is read back inside a chunk.
    int chunk = 250;
    std::function<void(int done, int total)> progress;
    // Set (e.g. by SIGINT) to stop after the current chunk.
    const std::atomic<bool>* cancel = nullptr;
};

struct RunResult {
    int stepsDone = 0;
    bool cancelled = false;
    State state;
};

// Runs session.steps steps on the simulator from its current state. Throws
// BlowUpError naming the step range and a dt to try if a value leaves the
// model's sane range.
RunResult runSimulation(Simulator& simulator, const Session& session, const RunOptions& options);

} // namespace morphogen
