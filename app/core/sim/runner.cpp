#include "core/sim/runner.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <sstream>

#include "core/session/cascade.hpp"
#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/numerics/resample.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/initial_state.hpp"

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

namespace {

// One segment of a session: a schedule level or a cascade stage.
struct Segment {
    Session session; // its model, size, steps, params, dt and grid spacing
    std::optional<FreezeRule> freeze;
    std::map<std::string, float> reset;
    bool newModel = false; // starts session.model afresh from session.init
};

std::vector<Segment> segmentsOf(const Session& session) {
    std::vector<Segment> segments;
    Session base = session;
    base.schedule.clear();
    base.stages.clear();
    if (!session.stages.empty()) {
        for (const Stage& stage : session.stages) {
            const bool newModel = !stage.model.empty();
            if (newModel) {
                // The new model starts from its own defaults, not the old model's values.
                const ReactionModel& model = *findModel(stage.model);
                base.model = stage.model;
                base.params.clear();
                for (const ParamSpec& p : model.params())
                    base.params[p.name] = p.defaultValue;
                base.init = stage.init ? *stage.init : model.defaultInit();
                base.dt = model.defaultDt();
                base.paramMaps.clear(); // sessionFromJson refuses maps with a model change
            }
            if (stage.dt)
                base.dt = *stage.dt;
            for (const auto& [name, value] : stage.params)
                base.params[name] = value; // cumulative, as Turk's cascades change s
            Segment segment{base, stage.freeze, stage.reset, newModel};
            segment.session.steps = stage.steps;
            segments.push_back(segment);
        }
        return segments;
    }
    std::vector<ScheduleLevel> levels = session.schedule;
    if (levels.empty())
        levels.push_back({session.width, session.height, session.steps});
    for (const ScheduleLevel& level : levels) {
        Segment segment{base, std::nullopt, {}, false};
        segment.session.width = level.width;
        segment.session.height = level.height;
        segment.session.steps = level.steps;
        segment.session.gridSpacing = double(session.width) / level.width;
        segments.push_back(segment);
    }
    return segments;
}

} // namespace

std::vector<Session> segmentSessions(const Session& session) {
    std::vector<Session> sessions;
    for (const Segment& segment : segmentsOf(session))
        sessions.push_back(segment.session);
    return sessions;
}

RunResult runSession(const Session& session, const SimulatorFactory& makeSimulator,
                     const RunOptions& options) {
    const std::vector<Segment> segments = segmentsOf(session);

    RunResult total;
    total.completed = session;
    std::vector<int> stepsPerSegment;
    State state;
    std::vector<std::uint8_t> frozen;
    const ReactionModel* stateModel = &session.reactionModel(); // the model `state` holds
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Session& part = segments[i].session;
        const ReactionModel& model = part.reactionModel();
        if (i == 0)
            state = initialState(part);
        else if (state.width() != part.width || state.height() != part.height)
            state = resampleBilinear(state, part.width, part.height, part.edges);
        // The rule reads the previous stage's result, with that stage's model.
        if (segments[i].freeze)
            frozen = applyFreezeRule(*segments[i].freeze, state, *stateModel, std::move(frozen));
        if (segments[i].newModel && i > 0) {
            // A new model: a fresh start of its own; only the frozen mask carries over.
            state =
                makeInitialState(part.init, model, part.params, part.width, part.height, part.seed);
            stateModel = &model;
        }
        if (!segments[i].reset.empty() && !frozen.empty())
            resetFrozenCells(state, frozen, segments[i].reset, model);

        std::unique_ptr<Simulator> simulator = makeSimulator(part);
        simulator->setState(state);
        simulator->setFrozen(frozen);
        RunOptions partOptions = options;
        const int before = total.stepsDone;
        if (options.progress)
            partOptions.progress = [&](int d, int) { options.progress(before + d, session.steps); };
        RunResult r = runSimulation(*simulator, part, partOptions);
        state = std::move(r.state);
        total.stepsDone += r.stepsDone;
        stepsPerSegment.push_back(r.stepsDone);
        if (r.cancelled) {
            total.cancelled = true;
            break;
        }
    }
    // A cancelled coarse level leaves a coarse state: bring it to the final size.
    if (state.width() != session.width || state.height() != session.height)
        state = resampleBilinear(state, session.width, session.height, session.edges);
    total.state = std::move(state);

    // What reproduces this state: the segments run, with the steps they ran.
    Session& done = total.completed;
    done.steps = total.stepsDone;
    if (!session.schedule.empty()) {
        done.schedule.resize(stepsPerSegment.size());
        for (std::size_t i = 0; i < stepsPerSegment.size(); ++i)
            done.schedule[i].steps = stepsPerSegment[i];
        if (done.schedule.back().width != session.width ||
            done.schedule.back().height != session.height)
            done.schedule.push_back({session.width, session.height, 0});
    }
    if (!session.stages.empty()) {
        done.stages.resize(stepsPerSegment.size());
        for (std::size_t i = 0; i < stepsPerSegment.size(); ++i)
            done.stages[i].steps = stepsPerSegment[i];
    }
    return total;
}

} // namespace morphogen
