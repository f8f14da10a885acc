#include "core/sim/local_relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

namespace {

float maxChangePerStep(const State& a, const State& b, int steps) {
    float worst = 0;
    for (int c = 0; c < a.channels(); ++c) {
        const float* pa = a.plane(c);
        const float* pb = b.plane(c);
        for (std::size_t i = 0; i < a.cellCount(); ++i)
            worst = std::max(worst, std::fabs(pa[i] - pb[i]));
    }
    return worst / float(steps);
}

} // namespace

RelaxResult relaxLocally(Simulator& sim, ActiveTileSchedule* schedule, int tileCount,
                         const RelaxOptions& options) {
    if (options.checkEvery < 1 || options.maxSteps < 1 || !(options.settledBelow > 0))
        throw InputError("relax options: checkEvery and maxSteps must be at least 1 and "
                         "settledBelow positive");
    using Clock = std::chrono::steady_clock;
    RelaxResult result;
    State previous = sim.state();
    int sinceCheck = 0;
    std::vector<int> stepped; // the set the simulator runs with now (empty: all)
    while (!result.settled && result.iterations < options.maxSteps) {
        const bool global = !schedule || schedule->global();
        const int tiles = global ? tileCount : int(schedule->tiles().size());
        const int phase = global ? 0 : schedule->phase();
        if (result.phases.empty() || result.phases.back().phase != phase ||
            result.phases.back().tiles != tiles) {
            result.phases.push_back({phase, tiles, 0, 0});
            stepped = global ? std::vector<int>{} : schedule->tiles();
            sim.setActiveTiles(stepped);
        }
        int n = options.checkEvery - sinceCheck;
        if (!global)
            n = std::min(n, schedule->iterationsLeft());
        n = std::max(1, std::min(n, options.maxSteps - result.iterations));
        const auto start = Clock::now();
        sim.run(n);
        sinceCheck += n;
        if (sinceCheck >= options.checkEvery) {
            const State now = sim.state(); // waits for the device
            result.settled = maxChangePerStep(now, previous, sinceCheck) < options.settledBelow;
            previous = now;
            sinceCheck = 0;
        } else if (options.sync) {
            options.sync();
        }
        result.phases.back().seconds += std::chrono::duration<double>(Clock::now() - start).count();
        result.phases.back().iterations += n;
        result.iterations += n;
        if (schedule)
            schedule->advance(n);
    }
    for (const RelaxPhase& p : result.phases)
        result.seconds += p.seconds;
    // The set the last steps ran with (advance may have grown it since).
    result.global = result.phases.empty() || result.phases.back().phase == 0;
    if (!result.global)
        result.finalTiles = stepped; // not schedule->tiles(): the last advance may have grown it
    sim.setActiveTiles({});
    return result;
}

} // namespace morphogen
