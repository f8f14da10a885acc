#include "core/sim/runner.hpp"

#include <algorithm>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/session_run.hpp"

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
            // Not a time-step matter there: the operator itself has growing modes.
            if (session.atlasWeights && session.atlasWeights->tensor &&
                session.diffusion.type == DiffusionType::Anisotropic)
                os << "; on a mesh, anisotropy on badly shaped tiles can also grow by itself: "
                      "try more tiles (--tiles) or lower the tensors' a1/a2";
            throw BlowUpError(os.str(), result.stepsDone, dt);
        }
        if (options.progress)
            options.progress(result.stepsDone, session.steps);
    }
    if (result.stepsDone == 0 || result.state.cellCount() == 0)
        result.state = simulator.state();
    return result;
}

std::vector<Session> segmentSessions(const Session& session) {
    std::vector<Session> sessions;
    for (const Segment& segment : segmentsOf(session))
        sessions.push_back(segment.session);
    return sessions;
}

RunResult runSession(const Session& session, const SimulatorFactory& makeSimulator,
                     const RunOptions& options) {
    const int chunk = std::max(1, options.chunk);
    SessionRun run(session, makeSimulator, chunk);
    run.setSettleCheck(options.settleEvery, options.settleAfter, options.settled);
    bool cancelled = false;
    while (!run.finished()) {
        if (options.cancel && options.cancel->load()) {
            cancelled = true;
            break;
        }
        // One chunk, ending where the segment does: a blow-up check, then progress.
        run.advance(std::min(chunk, run.segmentRemaining()));
        if (options.progress)
            options.progress(run.position().stepsDone, run.position().totalSteps);
    }
    RunResult result = run.takeResult();
    result.cancelled = cancelled;
    result.settled = run.settledEarly();
    return result;
}

} // namespace morphogen
