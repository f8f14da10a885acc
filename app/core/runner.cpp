#include "core/runner.hpp"

#include <algorithm>
#include <sstream>

#include "core/errors.hpp"
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

} // namespace morphogen
