#pragma once

#include <functional>
#include <vector>

namespace morphogen {

class ActiveTileSchedule;
class LocalRegrowth;
class Simulator;

// Running a disturbed pattern back to equilibrium, globally or with localized
// reaction-diffusion (Lo et al. section 4, localized_rd.hpp).
//
// Re-equilibrium: every `checkEvery` steps the largest change of any texel of
// any chemical since the previous check, per step, is below `settledBelow`.
// A settled Turing pattern drifts by far less (under 1e-6 per step); one still
// re-forming after a perturbation changes by 1e-3 or more per step.
struct RelaxOptions {
    int checkEvery = 25;
    float settledBelow = 2e-5f;
    int maxSteps = 40000; // gives up unsettled past this many steps
    // Called after a run of steps that ends without a read-back, so a phase's
    // time is the device's, not the queue's (GPU: glFinish). May be empty.
    std::function<void()> sync;
};

// One active set of the run: A1, A2, ... then the global phase.
struct RelaxPhase {
    int phase = 0; // k of A_k; 0: global
    int tiles = 0; // tiles stepped (every tile when global)
    int iterations = 0;
    double seconds = 0;
    double iterationsPerSecond() const { return seconds > 0 ? iterations / seconds : 0; }
};

struct RelaxResult {
    std::vector<RelaxPhase> phases;
    bool settled = false;
    int iterations = 0;
    double seconds = 0;
    // The last active set (ascending); empty when the run went global (or was
    // global throughout). Tiles outside it kept their values bit for bit.
    std::vector<int> finalTiles;
    bool global = false;
};

// Steps `sim` until re-equilibrium, the active set following `schedule`
// (null: global throughout), checking every options.checkEvery steps. The
// simulator steps every tile again when it returns. `tileCount`: the atlas's
// tiles (what a global phase reports).
RelaxResult relaxLocally(Simulator& sim, ActiveTileSchedule* schedule, int tileCount,
                         const RelaxOptions& options = {});

// The same with the set grown where the change reaches its edge (a
// LocalRegrowth started from the disturbed tiles, its checks every
// options.checkEvery steps with options.settledBelow): until it settles, or
// until the set passes its threshold, then globally as relaxLocally. The
// result's phases are the sets it ran with.
RelaxResult relaxAdaptively(Simulator& sim, LocalRegrowth& regrowth,
                            const RelaxOptions& options = {});

} // namespace morphogen
