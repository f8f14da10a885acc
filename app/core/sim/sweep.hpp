#pragma once

#include <string>
#include <vector>

#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

namespace morphogen {

// A parameter swept along one axis of a sweep's grid of tiles.
struct SweepAxis {
    std::string param;
    float min = 0, max = 0;
};

// A grid of independent simulations, one per (x, y) parameter pair: x varies
// along the columns, y along the rows, row 0 at the bottom as in a plot. Every
// tile is `tile` x `tile` cells, periodic on its own, and starts from `base`'s
// initial condition at that size.
struct SweepSpec {
    Session base; // everything but the swept parameters and the size
    SweepAxis x, y;
    int columns = 1, rows = 1;
    int tile = 128;
};

// The axis value of column (or row) i of n: min + (max - min) i / (n - 1).
float sweepValue(const SweepAxis& axis, int i, int n);

// The whole sweep as one session of columns*tile x rows*tile cells on a
// tiled grid domain whose tiles carry the swept values (session.tiles). Any
// session with active tiles is a batched sweep for the functions below (e.g.
// with one tile's values edited).
Session batchedSession(const SweepSpec& spec);

// Tile (column, row) of a batched session as a standalone session: its size,
// its parameter values, no tiles.
Session tileSession(const Session& batched, int column, int row);

// Runs a batched session (steps from session.steps) on one simulator, from
// initialState (initial_state.hpp). There is no blow-up check: a tile that leaves the
// model's range is reported by its stats, not by stopping the others.
State runBatched(const Session& batched, const SimulatorFactory& make,
                 const RunOptions& options = {});
// Runs one standalone session from its initial state, likewise.
State runTile(const Session& tile, const SimulatorFactory& make, const RunOptions& options = {});

// Tile (column, row) cut out of a batched state, or pasted into one.
State extractTile(const State& batched, int column, int row, int tile);
void pasteTile(State& batched, const State& tileState, int column, int row);

} // namespace morphogen
