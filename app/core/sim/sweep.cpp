#include "core/sim/sweep.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/sim/initial_state.hpp"

namespace morphogen {

namespace {

// Runs `steps` in chunks so progress can be reported and a cancel honoured.
State runFrom(Simulator& simulator, const State& start, int steps, const RunOptions& options) {
    simulator.setState(start);
    const int chunk = std::max(1, options.chunk);
    for (int done = 0; done < steps;) {
        if (options.cancel && options.cancel->load())
            break;
        const int n = std::min(chunk, steps - done);
        simulator.run(n);
        done += n;
        if (options.progress)
            options.progress(done, steps);
    }
    return simulator.state();
}

} // namespace

float sweepValue(const SweepAxis& axis, int i, int n) {
    const float v = n > 1 ? axis.min + (axis.max - axis.min) * (float(i) / float(n - 1)) : axis.min;
    // Rounding may pass max by an ulp: the written session must stay within
    // the parameter's range to read back.
    return std::clamp(v, std::min(axis.min, axis.max), std::max(axis.min, axis.max));
}

Session batchedSession(const SweepSpec& spec) {
    Session s = spec.base;
    s.width = spec.columns * spec.tile;
    s.height = spec.rows * spec.tile;
    s.schedule.clear();
    s.stages.clear();
    s.paramMaps.clear();
    s.tiles = TileGrid{};
    s.tiles.columns = spec.columns;
    s.tiles.rows = spec.rows;
    for (const SweepAxis* axis : {&spec.x, &spec.y}) {
        std::vector<float>& values = s.tiles.params[axis->param];
        for (int row = 0; row < spec.rows; ++row)
            for (int column = 0; column < spec.columns; ++column)
                values.push_back(axis == &spec.x ? sweepValue(*axis, column, spec.columns)
                                                 : sweepValue(*axis, row, spec.rows));
    }
    return s;
}

Session tileSession(const Session& batched, int column, int row) {
    if (!batched.tiles.active())
        throw InputError("session '" + batched.name + "' is not a batched sweep (no tiles)");
    Session s = batched;
    s.width = batched.width / batched.tiles.columns;
    s.height = batched.height / batched.tiles.rows;
    s.tiles = TileGrid{};
    s.length = 0; // tiles run at one unit per cell
    for (const auto& [name, values] : batched.tiles.params)
        s.params[name] = batched.tiles.value(name, column, row);
    return s;
}

State runBatched(const Session& batched, const SimulatorFactory& make, const RunOptions& options) {
    std::unique_ptr<Simulator> simulator = make(batched);
    return runFrom(*simulator, initialState(batched), batched.steps, options);
}

State runTile(const Session& tile, const SimulatorFactory& make, const RunOptions& options) {
    const State start = makeInitialState(tile.init, tile.reactionModel(), tile.params, tile.width,
                                         tile.height, tile.seed);
    std::unique_ptr<Simulator> simulator = make(tile);
    return runFrom(*simulator, start, tile.steps, options);
}

State extractTile(const State& batched, int column, int row, int tile) {
    const int rows = batched.height() / tile;
    const int y0 = (rows - 1 - row) * tile, x0 = column * tile; // row 0 at the bottom
    State t(tile, tile, batched.channels());
    for (int c = 0; c < batched.channels(); ++c)
        for (int y = 0; y < tile; ++y)
            for (int x = 0; x < tile; ++x)
                t.at(c, x, y) = batched.at(c, x0 + x, y0 + y);
    return t;
}

void pasteTile(State& batched, const State& tileState, int column, int row) {
    const int tile = tileState.width();
    const int rows = batched.height() / tileState.height();
    const int y0 = (rows - 1 - row) * tileState.height(), x0 = column * tile;
    for (int c = 0; c < batched.channels(); ++c)
        for (int y = 0; y < tileState.height(); ++y)
            for (int x = 0; x < tile; ++x)
                batched.at(c, x0 + x, y0 + y) = tileState.at(c, x, y);
}

} // namespace morphogen
