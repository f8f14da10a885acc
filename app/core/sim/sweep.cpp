#include "core/sim/sweep.hpp"

#include <algorithm>

#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"

namespace morphogen {

namespace {

// The first Tiles map of a batched session (all of them share the tiling).
const ParamMapSpec& tilesOf(const Session& batched) {
    for (const auto& [name, spec] : batched.paramMaps)
        if (spec.field == ParamMapSpec::Field::Tiles)
            return spec;
    throw InputError("session '" + batched.name + "' is not a batched sweep (no tiles param map)");
}

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
    return n > 1 ? axis.min + (axis.max - axis.min) * (float(i) / float(n - 1)) : axis.min;
}

Session batchedSession(const SweepSpec& spec) {
    Session s = spec.base;
    s.width = spec.columns * spec.tile;
    s.height = spec.rows * spec.tile;
    s.schedule.clear();
    s.stages.clear();
    for (const SweepAxis* axis : {&spec.x, &spec.y}) {
        ParamMapSpec map;
        map.field = ParamMapSpec::Field::Tiles;
        map.tilesX = spec.columns;
        map.tilesY = spec.rows;
        for (int row = 0; row < spec.rows; ++row)
            for (int column = 0; column < spec.columns; ++column)
                map.tileValues.push_back(axis == &spec.x ? sweepValue(*axis, column, spec.columns)
                                                         : sweepValue(*axis, row, spec.rows));
        map.min = axis->min;
        map.max = axis->max;
        s.paramMaps[axis->param] = map;
    }
    return s;
}

bool isBatchedSweep(const Session& session) {
    for (const auto& [name, spec] : session.paramMaps)
        if (spec.field == ParamMapSpec::Field::Tiles)
            return true;
    return false;
}

int tileColumns(const Session& batched) {
    return tilesOf(batched).tilesX;
}
int tileRows(const Session& batched) {
    return tilesOf(batched).tilesY;
}

Session tileSession(const Session& batched, int column, int row) {
    const ParamMapSpec& tiles = tilesOf(batched);
    Session s = batched;
    s.width = batched.width / tiles.tilesX;
    s.height = batched.height / tiles.tilesY;
    s.paramMaps.clear();
    for (const auto& [name, spec] : batched.paramMaps) {
        if (spec.field != ParamMapSpec::Field::Tiles)
            throw InputError("a sweep's param maps must all be tiles ('" + name + "' is " +
                             toString(spec.field) + ")");
        s.params[name] = spec.tileValues[std::size_t(row) * spec.tilesX + column];
    }
    return s;
}

State batchedInitialState(const Session& batched) {
    const ReactionModel& model = batched.reactionModel();
    const int columns = tileColumns(batched), rows = tileRows(batched);
    State state(batched.width, batched.height, int(model.chemicals().size()));
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Session t = tileSession(batched, column, row);
            pasteTile(state, makeInitialState(t.init, model, t.params, t.width, t.height, t.seed),
                      column, row);
        }
    return state;
}

State runBatched(const Session& batched, const SimulatorFactory& make, const RunOptions& options) {
    std::unique_ptr<Simulator> simulator = make(batched);
    return runFrom(*simulator, batchedInitialState(batched), batched.steps, options);
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
