#pragma once

#include "core/base/state.hpp"
#include "core/session/session.hpp"

namespace morphogen {

// A session's starting state on its domain: the model's initial condition on
// a grid; on a tiled grid (a batched sweep) each tile's own standalone
// initial state, side by side, so that every tile runs exactly as its own
// session would.
State initialState(const Session& session);

} // namespace morphogen
