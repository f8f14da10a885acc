#include "core/sim/exploration_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/models/reaction_model.hpp"

namespace morphogen {

namespace {

const EnumName<ExplorationStart> kStarts[] = {{ExplorationStart::Noise, "noise"},
                                              {ExplorationStart::Preset, "preset"}};

bool seeded(InitialCondition::Type type) {
    return type != InitialCondition::Type::Noise;
}

std::string formatValue(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

// Within the axis, with slack for float rounding at its ends.
bool onAxis(float value, const SweepAxis& axis) {
    const float slack = 1e-6f * (axis.max - axis.min);
    return value >= axis.min - slack && value <= axis.max + slack;
}

} // namespace

std::string toString(ExplorationStart start) {
    return nameOf(kStarts, start);
}

std::optional<ExplorationStart> parseExplorationStart(std::string_view name) {
    return valueNamed(kStarts, name);
}

std::string explorationStartNames() {
    return nameList(kStarts);
}

InitialCondition noiseStart(const InitialCondition& own, const ReactionModel& model) {
    const InitialCondition& fallback = model.defaultInit();
    if (!seeded(fallback.type)) {
        // `own`'s background (a preset's homogeneous state for its parameters) with the
        // model's noise where `own` has none.
        InitialCondition start = own;
        if (seeded(own.type)) {
            start.type = InitialCondition::Type::Noise;
            start.noise.insert(fallback.noise.begin(), fallback.noise.end());
        }
        return start;
    }
    // Grows from seeds: a seeded start lends its values, a noise start (no
    // background to seed into) the model's.
    const InitialCondition& from = seeded(own.type) ? own : fallback;
    InitialCondition start = from;
    start.type = InitialCondition::Type::JitteredGrid;
    const bool hasRadius = from.type == InitialCondition::Type::SeedSpots ||
                           from.type == InitialCondition::Type::JitteredGrid;
    start.spotRadius = hasRadius && from.spotRadius >= 1.0f ? from.spotRadius
                                                            : std::max(1.0f, fallback.spotRadius);
    // A diamond lattice of spacing s holds 2 / s^2 discs per cell: one per (4 r)^2.
    start.spacing = 4.0f * std::sqrt(2.0f) * start.spotRadius;
    start.jitter = 1.0f; // displacements up to a whole spacing: no lattice left to see
    return start;
}

TilePick parseTilePick(const std::string& flag, const std::string& text, int columns, int rows) {
    std::smatch m;
    if (!std::regex_match(text, m, std::regex(R"(\s*(-?[0-9]{1,6})\s*,\s*(-?[0-9]{1,6})\s*)")))
        throw InputError(flag + " '" + text +
                         "': expected COL,ROW, e.g. 2,5 (integers from 0: the column from the "
                         "left, the row from the bottom)");
    const TilePick pick{std::stoi(m[1]), std::stoi(m[2])};
    const std::string grid = std::to_string(columns) + "x" + std::to_string(rows);
    const std::string accepted = " (columns 0.." + std::to_string(columns - 1) +
                                 " from the left, rows 0.." + std::to_string(rows - 1) +
                                 " from the bottom)";
    if (pick.column < 0 || pick.column >= columns)
        throw InputError(flag + " '" + text + "': column " + std::to_string(pick.column) +
                         " is outside the " + grid + " grid" + accepted);
    if (pick.row < 0 || pick.row >= rows)
        throw InputError(flag + " '" + text + "': row " + std::to_string(pick.row) +
                         " is outside the " + grid + " grid" + accepted);
    return pick;
}

PointPick parsePointPick(const std::string& flag, const std::string& text, const SweepAxis& x,
                         const SweepAxis& y) {
    const std::size_t comma = text.find(',');
    const std::string xs = text.substr(0, comma);
    const std::string ys = comma == std::string::npos ? "" : text.substr(comma + 1);
    char* endX = nullptr;
    char* endY = nullptr;
    PointPick pick{std::strtof(xs.c_str(), &endX), std::strtof(ys.c_str(), &endY)};
    if (xs.empty() || ys.empty() || *endX || *endY || !std::isfinite(pick.x) ||
        !std::isfinite(pick.y))
        throw InputError(flag + " '" + text + "': expected X,Y, values of " + x.param + " and " +
                         y.param + " as the axes show them, e.g. " +
                         formatValue((x.min + x.max) / 2) + "," + formatValue((y.min + y.max) / 2));
    const auto check = [&](float value, const SweepAxis& axis, const std::string& name) {
        if (!onAxis(value, axis))
            throw InputError(flag + " '" + text + "': " + axis.param + " = " + formatValue(value) +
                             " is outside the map's " + name + " axis (" + axis.param + " " +
                             formatValue(axis.min) + ".." + formatValue(axis.max) + ")");
    };
    check(pick.x, x, "x");
    check(pick.y, y, "y");
    pick.x = std::clamp(pick.x, x.min, x.max);
    pick.y = std::clamp(pick.y, y.min, y.max);
    return pick;
}

Session pickTile(const Session& batched, TilePick pick, int size) {
    return pickedAtSize(tileSession(batched, pick.column, pick.row), size);
}

Session pickPoint(const Session& map, const SweepAxis& x, const SweepAxis& y, PointPick pick,
                  int size) {
    Session s = map;
    const auto setUniformly = [&s](const SweepAxis& axis, float value) {
        s.paramMaps.erase(axis.param);
        s.params[axis.param] = value;
        for (Stage& stage : s.stages)
            stage.params.erase(axis.param);
    };
    setUniformly(x, pick.x);
    setUniformly(y, pick.y);
    return pickedAtSize(s, size);
}

Session pickedAtSize(Session s, int size) {
    const double area = double(size) * size / (double(s.width) * s.height);
    const auto denser = [area](InitialCondition& init) {
        if (init.type == InitialCondition::Type::SeedSpots && init.spotCount > 0)
            init.spotCount = std::max(1, int(std::lround(init.spotCount * area)));
    };
    denser(s.init);
    for (Stage& stage : s.stages)
        if (stage.init)
            denser(*stage.init);
    s.width = s.height = size;
    s.length = size;
    return s;
}

} // namespace morphogen
