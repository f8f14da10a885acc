#include "core/runner.hpp"

#include <algorithm>
#include <sstream>

#include "core/errors.hpp"
#include "core/initial_condition.hpp"
#include "core/resample.hpp"
#include "core/stability.hpp"

namespace morphogen {

RunResult runSimulation(Simulator& simulator, const Session& session, const RunOptions& options) {
    const ReactionModel& model = session.reactionModel();
    RunResult result;
    const int chunk = std::max(1, options.chunk);
    while (result.stepsDone < session.steps) {
        if (options.cancel && options.cancel->load()) {
            result.cancelled = true;
            break;
        }
        const int n = std::min(chunk, session.steps - result.stepsDone);
        simulator.run(n);
        const int before = result.stepsDone;
        result.stepsDone += n;
        result.state = simulator.state();
        if (auto problem = findInsaneValue(result.state, model)) {
            const float dt = suggestDt(session);
            std::ostringstream os;
            os << "the simulation blew up between step " << before + 1 << " and step "
               << result.stepsDone << " (" << *problem << ", backend " << simulator.backendName()
               << ", dt " << session.dt << "); try a smaller time step such as --dt " << dt;
            throw BlowUpError(os.str(), result.stepsDone, dt);
        }
        if (options.progress)
            options.progress(result.stepsDone, session.steps);
    }
    if (result.stepsDone == 0 || result.state.cellCount() == 0)
        result.state = simulator.state();
    return result;
}

RunResult runSession(const Session& session, const SimulatorFactory& makeSimulator,
                     const RunOptions& options) {
    std::vector<ScheduleLevel> levels = session.schedule;
    if (levels.empty())
        levels.push_back({session.width, session.height, session.steps});
    const ReactionModel& model = session.reactionModel();

    RunResult total;
    total.completed = session;
    std::vector<ScheduleLevel> done;
    State state;
    int stepsBefore = 0;
    for (std::size_t i = 0; i < levels.size(); ++i) {
        Session level = session;
        level.schedule.clear();
        level.width = levels[i].width;
        level.height = levels[i].height;
        level.steps = levels[i].steps;
        level.gridSpacing = double(session.width) / level.width;
        std::unique_ptr<Simulator> simulator = makeSimulator(level);
        if (i == 0)
            state = makeInitialState(level.init, model, level.params, level.width, level.height,
                                     level.seed);
        else
            state = resampleBilinear(state, level.width, level.height, level.edges);
        simulator->setState(state);

        RunOptions levelOptions = options;
        if (options.progress)
            levelOptions.progress = [&](int d, int) {
                options.progress(stepsBefore + d, session.steps);
            };
        RunResult r = runSimulation(*simulator, level, levelOptions);
        state = std::move(r.state);
        stepsBefore += r.stepsDone;
        total.stepsDone += r.stepsDone;
        done.push_back({level.width, level.height, r.stepsDone});
        if (r.cancelled) {
            total.cancelled = true;
            break;
        }
    }
    // A cancelled coarse level leaves a coarse state: bring it to the final size.
    if (state.width() != session.width || state.height() != session.height)
        state = resampleBilinear(state, session.width, session.height, session.edges);
    total.state = std::move(state);
    total.completed.steps = total.stepsDone;
    if (!session.schedule.empty()) {
        total.completed.schedule = done;
        if (done.back().width != session.width || done.back().height != session.height)
            total.completed.schedule.push_back({session.width, session.height, 0});
    }
    return total;
}

} // namespace morphogen
