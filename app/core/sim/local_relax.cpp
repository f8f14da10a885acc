#include "core/sim/local_relax.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/sim/local_regrowth.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

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

RelaxResult relaxAdaptively(Simulator& sim, LocalRegrowth& regrowth, const RelaxOptions& options) {
    using Clock = std::chrono::steady_clock;
    RelaxResult result;
    std::vector<int> stepped;
    while (!regrowth.over() && result.iterations < options.maxSteps) {
        if (result.phases.empty() || stepped != regrowth.tiles()) {
            stepped = regrowth.tiles();
            result.phases.push_back({regrowth.phase(), int(stepped.size()), 0, 0});
            sim.setActiveTiles(stepped);
        }
        const int n = std::max(
            1, std::min(regrowth.stepsBeforeChange(), options.maxSteps - result.iterations));
        const auto start = Clock::now();
        sim.run(n);
        bool read = false;
        regrowth.stepped(n, [&] {
            read = true;
            return sim.state(); // waits for the device
        });
        if (!read && options.sync)
            options.sync();
        result.phases.back().seconds += std::chrono::duration<double>(Clock::now() - start).count();
        result.phases.back().iterations += n;
        result.iterations += n;
    }
    sim.setActiveTiles({});
    result.settled = regrowth.settled();
    result.finalTiles = stepped;
    if (!regrowth.over() || regrowth.settled()) {
        for (const RelaxPhase& p : result.phases)
            result.seconds += p.seconds;
        return result;
    }
    // Past the threshold: the rest globally.
    RelaxOptions rest = options;
    rest.maxSteps = std::max(1, options.maxSteps - result.iterations);
    const RelaxResult global = relaxLocally(sim, nullptr, regrowth.tileCount(), rest);
    result.phases.insert(result.phases.end(), global.phases.begin(), global.phases.end());
    result.iterations += global.iterations;
    result.settled = global.settled;
    result.global = true;
    result.finalTiles.clear();
    for (const RelaxPhase& p : result.phases)
        result.seconds += p.seconds;
    return result;
}

} // namespace morphogen
