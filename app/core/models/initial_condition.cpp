#include "core/models/initial_condition.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/noise_field.hpp"
#include "core/base/random.hpp"
#include "core/models/reaction_model.hpp"

namespace morphogen {

namespace {

const EnumName<InitialCondition::Type> kTypes[] = {
    {InitialCondition::Type::Noise, "noise"},
    {InitialCondition::Type::CentreSquare, "centre_square"},
    {InitialCondition::Type::SeedSpots, "seed_spots"},
    {InitialCondition::Type::JitteredGrid, "jittered_grid"}};

const EnumAlias<InitialCondition::Type> kTypeAliases[] = {
    {"center_square", InitialCondition::Type::CentreSquare},
    {"square", InitialCondition::Type::CentreSquare},
    {"spots", InitialCondition::Type::SeedSpots},
    {"seeds", InitialCondition::Type::SeedSpots},
    {"grid", InitialCondition::Type::JitteredGrid}};

std::optional<InitialCondition::Type> parseType(std::string_view name) {
    return valueNamed(kTypes, kTypeAliases, name);
}

} // namespace

std::string toString(InitialCondition::Type type) {
    return nameOf(kTypes, type);
}

namespace {
float lookup(const std::map<std::string, float>& values, const std::string& key, float fallback) {
    auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
}
} // namespace

namespace {

using nlohmann::json;

std::map<std::string, float> chemicalValues(const FieldReader& parent, const std::string& key,
                                            const ReactionModel& model) {
    std::map<std::string, float> values;
    const json* j = parent.find(key);
    if (!j)
        return values;
    FieldReader reader(*j, parent.source(), parent.path(key));
    for (auto it = j->begin(); it != j->end(); ++it) {
        if (model.chemicalIndex(it.key()) < 0)
            reader.fail("field '" + reader.path(it.key()) + "'",
                        "is not a chemical of model '" + model.name() +
                            "' (chemicals: " + model.chemicalNames() + ")" +
                            didYouMean(it.key(), splitNameList(model.chemicalNames())));
        values[it.key()] = float(reader.numberValue(*it, it.key(), -1e6, 1e6));
    }
    return values;
}

} // namespace

InitialCondition initialConditionFromJson(const nlohmann::json& j, const std::string& source,
                                          const std::string& path, const ReactionModel& model) {
    InitialCondition init;
    FieldReader reader(j, source, path);
    reader.rejectUnknown(
        {"type", "base", "noise", "inside", "fraction", "count", "radius", "spacing", "jitter"});
    init.type = reader.choice("type", init.type, parseType, nameList(kTypes));
    if (reader.find("base"))
        init.base = chemicalValues(reader, "base", model);
    if (reader.find("noise"))
        init.noise = chemicalValues(reader, "noise", model);
    if (reader.find("inside"))
        init.inside = chemicalValues(reader, "inside", model);
    init.squareFraction = float(reader.number("fraction", init.squareFraction, 0.0, 1.0));
    init.spotCount = int(reader.integer("count", init.spotCount, 0, 100000));
    init.spotRadius = float(reader.number("radius", init.spotRadius, 0.0, 10000.0));
    init.spacing = float(reader.number("spacing", init.spacing, 2.0, 100000.0));
    init.jitter = float(reader.number("jitter", init.jitter, 0.0, 1.0));
    return init;
}

nlohmann::json initialConditionToJson(const InitialCondition& init) {
    json j;
    j["type"] = toString(init.type);
    j["base"] = init.base;
    j["noise"] = init.noise;
    if (init.type != InitialCondition::Type::Noise)
        j["inside"] = init.inside;
    if (init.type == InitialCondition::Type::CentreSquare)
        j["fraction"] = init.squareFraction;
    if (init.type == InitialCondition::Type::SeedSpots) {
        j["count"] = init.spotCount;
        j["radius"] = init.spotRadius;
    }
    if (init.type == InitialCondition::Type::JitteredGrid) {
        j["spacing"] = init.spacing;
        j["jitter"] = init.jitter;
        j["radius"] = init.spotRadius;
    }
    return j;
}

namespace {

// Marks every cell (x, y) with an offset (dx, dy) from a centre's cell such
// that dx^2 + dy^2 <= r^2, wrapping around the edges as a periodic grid
// would. Row by row: in one row a disc is a run of cells (the widest of the
// rows that wrap onto it), so the cost is the centres times the rows they
// reach, plus the cells, however large r is (a radius of 10000 cells on a
// 32 x 32 grid covers every cell once, not 4e8 times).
void markDiscs(std::vector<unsigned char>& marked, int width, int height,
               const std::vector<std::pair<double, double>>& centres, float r) {
    if (centres.empty() || !(r >= 0.0f))
        return;
    const float r2 = r * r;
    // Every cell is within r of any centre once r passes the grid's diagonal.
    if (double(r2) >= double(width) * width + double(height) * height) {
        std::fill(marked.begin(), marked.end(), 1);
        return;
    }
    const int reach = int(std::ceil(r)); // below width + height here
    // Half-width of the run in the row dy away: the largest dx with
    // float(dx^2 + dy^2) <= r^2, the comparison a cell-by-cell test makes.
    auto halfWidth = [&](long long dy) {
        auto inside = [&](long long dx) { return float(dx * dx + dy * dy) <= r2; };
        long long dx =
            (long long)std::floor(std::sqrt(std::max(0.0, double(r2) - double(dy * dy))));
        while (dx > 0 && !inside(dx))
            --dx;
        while (inside(dx + 1))
            ++dx;
        return dx;
    };
    auto wrap = [](long long v, int n) { return int(((v % n) + n) % n); };
    // A sweep down the rows with the centres whose discs reach the row: each
    // centre reaches `rows` rows from cy - reach (wrapping), so at most the
    // centres are active at once, and one row's runs are summed at a time.
    const int rows = std::min(2 * reach + 1, height);
    struct Active {
        std::size_t centre;
        int left; // rows still to mark
    };
    std::vector<std::vector<std::size_t>> startsAt(static_cast<std::size_t>(height));
    std::vector<Active> active;
    std::vector<std::pair<long long, long long>> cells(centres.size());
    for (std::size_t i = 0; i < centres.size(); ++i) {
        cells[i] = {(long long)std::floor(centres[i].first),
                    (long long)std::floor(centres[i].second)};
        const int first = wrap(cells[i].second - reach, height);
        startsAt[std::size_t(first)].push_back(i);
        if (first + rows > height) // the rows past the last one wrap to the top
            active.push_back({i, first + rows - height});
    }
    std::vector<int> edges(std::size_t(width) + 1);
    for (int y = 0; y < height; ++y) {
        for (std::size_t i : startsAt[std::size_t(y)])
            active.push_back({i, std::min(rows, height - y)});
        if (active.empty())
            continue;
        std::fill(edges.begin(), edges.end(), 0);
        auto run = [&](int a, int b) {
            ++edges[std::size_t(a)];
            --edges[std::size_t(b)];
        };
        for (std::size_t k = 0; k < active.size();) {
            const auto [cx, cy] = cells[active[k].centre];
            // When rows wrap onto one another, the offset nearest the centre
            // gives the widest run.
            long long dy = ((y - cy) % height + height) % height;
            if (dy > height - dy)
                dy -= height;
            if (dy >= -reach && dy <= reach && float(dy * dy) <= r2) {
                const long long half = halfWidth(dy);
                if (2 * half + 1 >= width) {
                    run(0, width);
                } else {
                    const int x0 = wrap(cx - half, width);
                    const int end = x0 + int(2 * half + 1);
                    if (end <= width) {
                        run(x0, end);
                    } else {
                        run(x0, width);
                        run(0, end - width);
                    }
                }
            }
            if (--active[k].left == 0) {
                active[k] = active.back();
                active.pop_back();
            } else {
                ++k;
            }
        }
        int covering = 0;
        for (int x = 0; x < width; ++x) {
            covering += edges[std::size_t(x)];
            if (covering > 0)
                marked[std::size_t(y) * width + x] = 1;
        }
    }
}

} // namespace

State makeInitialState(const InitialCondition& init, const ReactionModel& model,
                       const std::map<std::string, float>& params, int width, int height,
                       std::uint64_t seed, double cellSize) {
    const int channels = int(model.chemicals().size());
    State state(width, height, channels);
    // Radii and spacings are in model units: cells at one cell per unit.
    const double cellsPerUnit = cellSize > 0 ? 1.0 / cellSize : 1.0;

    // Which cells take the `inside` values.
    std::vector<unsigned char> marked(state.cellCount(), 0);
    if (init.type == InitialCondition::Type::CentreSquare) {
        const int side =
            std::max(1, int(std::lround(init.squareFraction * std::min(width, height))));
        const int x0 = (width - side) / 2, y0 = (height - side) / 2;
        for (int y = y0; y < y0 + side; ++y)
            for (int x = x0; x < x0 + side; ++x)
                marked[std::size_t(y) * width + x] = 1;
    } else if (init.type == InitialCondition::Type::SeedSpots ||
               init.type == InitialCondition::Type::JitteredGrid) {
        // Spot centres: random, or a diamond lattice (rows spacing/2 apart,
        // every other row shifted by half a spacing) displaced by the jitter.
        std::vector<std::pair<double, double>> centres;
        if (init.type == InitialCondition::Type::SeedSpots) {
            for (int s = 0; s < init.spotCount; ++s)
                centres.emplace_back(uniform01(seed, 2000, 2 * s) * width,
                                     uniform01(seed, 2000, 2 * s + 1) * height);
        } else {
            const double step = std::max(2.0, init.spacing * cellsPerUnit);
            const int rows = std::max(1, int(std::lround(2.0 * height / step)));
            const int columns = std::max(1, int(std::lround(width / step)));
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < columns; ++i) {
                    const std::uint64_t k = std::uint64_t(j) * columns + i;
                    const double dx = init.jitter * step * uniformSigned(seed, 2001, 2 * k);
                    const double dy = init.jitter * step * uniformSigned(seed, 2001, 2 * k + 1);
                    centres.emplace_back((i + 0.5 * (j % 2)) * width / double(columns) + dx,
                                         (j + 0.5) * height / double(rows) + dy);
                }
        }
        markDiscs(marked, width, height, centres, float(init.spotRadius * cellsPerUnit));
    }

    const NoiseField field(seed, width, height, cellSize, true);
    for (int c = 0; c < channels; ++c) {
        const std::string& name = model.chemicals()[std::size_t(c)].name;
        const float base = lookup(init.base, name, 0.0f);
        const float inside = lookup(init.inside, name, base);
        const float noise = lookup(init.noise, name, 0.0f);
        float* plane = state.plane(c);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + x;
                const float value = marked[i] ? inside : base;
                plane[i] =
                    noise == 0.0f ? value : float(value + noise * field.at(std::uint64_t(c), x, y));
            }
    }
    model.prepareState(state, params, field);
    return state;
}

} // namespace morphogen
