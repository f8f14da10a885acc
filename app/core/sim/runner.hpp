#pragma once

#include <atomic>
#include <functional>
#include <memory>

#include "core/sim/simulator.hpp"

namespace morphogen {

struct RunOptions {
    // Steps between read-backs. Each chunk ends with a blow-up check and a
    // progress report; nothing is read back inside a chunk.
    int chunk = 250;
    std::function<void(int done, int total)> progress;
    // Set (e.g. by SIGINT) to stop after the current chunk.
    const std::atomic<bool>* cancel = nullptr;
    // Until settled (SessionRun::setSettleCheck): asked every settleEvery
    // session steps of the session's last stage or level, from settleAfter on.
    int settleEvery = 0;
    int settleAfter = 0;
    std::function<bool(const State&)> settled;
};

struct RunResult {
    int stepsDone = 0;
    bool cancelled = false;
    bool settled = false; // the settle check ended the run's last stage or level
    State state;
    // runSession: the session that reproduces `state` (on cancel: the steps
    // and schedule levels actually run).
    Session completed;
};

// Makes the simulator for one level (its size, steps and grid spacing set).
using SimulatorFactory = std::function<std::unique_ptr<Simulator>(const Session& level)>;

// Runs session.steps steps on the simulator from its current state. Throws
// BlowUpError naming the step range and a dt to try if a value leaves the
// model's sane range.
RunResult runSimulation(Simulator& simulator, const Session& session, const RunOptions& options);

// The session each stage or schedule level runs as (its model, params, dt,
// size, steps and grid spacing), in order.
std::vector<Session> segmentSessions(const Session& session);

// Runs a whole session from its initial condition: one level, or its
// coarse-to-fine schedule, each level starting from the previous one's state
// resampled bilinearly, with diffusion scaled to the level's cell size so the
// pattern keeps its size in the image. Progress counts steps over all levels.
RunResult runSession(const Session& session, const SimulatorFactory& makeSimulator,
                     const RunOptions& options);

} // namespace morphogen
