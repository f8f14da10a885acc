#include "core/sim/initial_state.hpp"

#include "core/models/initial_condition.hpp"
#include "core/sim/sweep.hpp"

namespace morphogen {

State initialState(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    if (!session.tiles.active())
        return makeInitialState(session.init, model, session.params, session.width, session.height,
                                session.seed, session.layoutCellSize());
    State state(session.width, session.height, int(model.chemicals().size()));
    for (int row = 0; row < session.tiles.rows; ++row)
        for (int column = 0; column < session.tiles.columns; ++column) {
            const Session t = tileSession(session, column, row);
            pasteTile(state, makeInitialState(t.init, model, t.params, t.width, t.height, t.seed),
                      column, row);
        }
    return state;
}

} // namespace morphogen
