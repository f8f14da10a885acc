#include "core/session/param_map.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/random.hpp"
#include "core/io/image_io.hpp"
#include "core/models/reaction_model.hpp"
#include "core/session/session.hpp"

namespace morphogen {

using nlohmann::json;

namespace {

const EnumName<ParamMapSpec::Field> kFields[] = {{ParamMapSpec::Field::LinearX, "linear_x"},
                                                 {ParamMapSpec::Field::LinearY, "linear_y"},
                                                 {ParamMapSpec::Field::Radial, "radial"},
                                                 {ParamMapSpec::Field::Noise, "noise"},
                                                 {ParamMapSpec::Field::Image, "image"}};

std::optional<ParamMapSpec::Field> parseField(std::string_view name) {
    return valueNamed(kFields, name);
}

// Value noise: random values on a lattice `scale` cells apart, smoothstep-
// interpolated; the lattice wraps so the field tiles on a periodic grid.
float valueNoise(double x, double y, int cellsX, int cellsY, std::uint64_t seed) {
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const double fx = x - x0, fy = y - y0;
    auto lattice = [&](int i, int j) {
        i = ((i % cellsX) + cellsX) % cellsX;
        j = ((j % cellsY) + cellsY) % cellsY;
        return uniform01(seed, 3000, std::uint64_t(j) * std::uint64_t(cellsX) + std::uint64_t(i));
    };
    auto smooth = [](double t) { return t * t * (3 - 2 * t); };
    const double sx = smooth(fx), sy = smooth(fy);
    const double top = lattice(x0, y0) * (1 - sx) + lattice(x0 + 1, y0) * sx;
    const double bottom = lattice(x0, y0 + 1) * (1 - sx) + lattice(x0 + 1, y0 + 1) * sx;
    return float(top * (1 - sy) + bottom * sy);
}

// Value noise in space: random values on the integer lattice, smoothstep-
// interpolated along each axis (no wrap: a surface has no period).
double valueNoise3(double x, double y, double z, std::uint64_t seed) {
    const double f[3] = {std::floor(x), std::floor(y), std::floor(z)};
    const std::int64_t i0[3] = {std::int64_t(f[0]), std::int64_t(f[1]), std::int64_t(f[2])};
    auto smooth = [](double t) { return t * t * (3 - 2 * t); };
    const double s[3] = {smooth(x - f[0]), smooth(y - f[1]), smooth(z - f[2])};
    auto lattice = [&](int dx, int dy, int dz) {
        // 21 bits per axis, offset so negative coordinates stay distinct.
        const auto bits = [](std::int64_t v) { return std::uint64_t(v + (1 << 20)) & 0x1FFFFF; };
        return uniform01(seed, 3001,
                         (bits(i0[2] + dz) << 42) | (bits(i0[1] + dy) << 21) | bits(i0[0] + dx));
    };
    double value = 0;
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
        value += lattice(dx, dy, dz) * (dx ? s[0] : 1 - s[0]) * (dy ? s[1] : 1 - s[1]) *
                 (dz ? s[2] : 1 - s[2]);
    }
    return value;
}

} // namespace

std::vector<float> evaluateSurfaceParamMap(const ParamMapSpec& spec, const std::string& param,
                                           const std::vector<std::array<float, 3>>& positions,
                                           const std::vector<bool>& used, double unitsPerMesh,
                                           std::uint64_t seed) {
    assert(positions.size() == used.size());
    if (spec.field == ParamMapSpec::Field::Image)
        throw InputError("param_maps." + param +
                         ": an image field cannot vary a parameter over a mesh (the image's x and "
                         "y are not the surface's); accepted on a mesh: linear_x, linear_y (along "
                         "the model's x and y), radial, noise");
    std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (used[i])
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], double(positions[i][a]));
                hi[a] = std::max(hi[a], double(positions[i][a]));
            }
    const std::array<double, 3> extent{std::max(hi[0] - lo[0], 1e-30),
                                       std::max(hi[1] - lo[1], 1e-30),
                                       std::max(hi[2] - lo[2], 1e-30)};
    const std::array<double, 3> centre{lo[0] + spec.centreX * extent[0],
                                       lo[1] + spec.centreY * extent[1], lo[2] + 0.5 * extent[2]};
    const double halfDiagonal =
        0.5 * std::sqrt(extent[0] * extent[0] + extent[1] * extent[1] + extent[2] * extent[2]);
    const double lattice = unitsPerMesh / double(spec.scale); // noise cells per mesh unit
    std::vector<float> values(positions.size(), spec.min);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (!used[i])
            continue;
        const auto& p = positions[i];
        double t = 0;
        switch (spec.field) {
        case ParamMapSpec::Field::LinearX:
            t = (p[0] - lo[0]) / extent[0];
            break;
        case ParamMapSpec::Field::LinearY:
            t = (p[1] - lo[1]) / extent[1];
            break;
        case ParamMapSpec::Field::Radial:
            t = std::sqrt((p[0] - centre[0]) * (p[0] - centre[0]) +
                          (p[1] - centre[1]) * (p[1] - centre[1]) +
                          (p[2] - centre[2]) * (p[2] - centre[2])) /
                halfDiagonal;
            break;
        case ParamMapSpec::Field::Noise:
            t = valueNoise3(p[0] * lattice, p[1] * lattice, p[2] * lattice, seed);
            break;
        case ParamMapSpec::Field::Image:
            break;
        }
        values[i] = float(spec.min + (spec.max - spec.min) * std::clamp(t, 0.0, 1.0));
    }
    return values;
}

std::string toString(ParamMapSpec::Field field) {
    return nameOf(kFields, field);
}

std::vector<float> evaluateParamMap(const ParamMapSpec& spec, int width, int height,
                                    std::uint64_t seed, const std::string& baseDir,
                                    double cellSize) {
    std::vector<float> t(std::size_t(width) * height);
    if (spec.field == ParamMapSpec::Field::Image) {
        std::string path = spec.image;
        if (!baseDir.empty() && !std::filesystem::path(path).is_absolute())
            path = (std::filesystem::path(baseDir) / path).string();
        t = loadLuminance(path, width, height);
    } else {
        const double units = cellSize > 0 ? cellSize : 1.0;
        const int cellsX = std::max(1, int(std::lround(width * units / spec.scale)));
        const int cellsY = std::max(1, int(std::lround(height * units / spec.scale)));
        const double halfDiagonal = 0.5 * std::hypot(width, height);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double v = 0;
                switch (spec.field) {
                case ParamMapSpec::Field::LinearX:
                    v = width > 1 ? double(x) / (width - 1) : 0.0;
                    break;
                case ParamMapSpec::Field::LinearY:
                    v = height > 1 ? double(height - 1 - y) / (height - 1) : 0.0;
                    break;
                case ParamMapSpec::Field::Radial:
                    v = std::hypot(x + 0.5 - spec.centreX * width,
                                   y + 0.5 - spec.centreY * height) /
                        halfDiagonal;
                    break;
                case ParamMapSpec::Field::Noise:
                    v = valueNoise(double(x) * cellsX / width, double(y) * cellsY / height, cellsX,
                                   cellsY, seed);
                    break;
                case ParamMapSpec::Field::Image:
                    break;
                }
                t[std::size_t(y) * width + x] = float(v);
            }
    }
    std::vector<float> values(t.size());
    for (std::size_t i = 0; i < t.size(); ++i)
        values[i] = spec.min + (spec.max - spec.min) * std::clamp(t[i], 0.0f, 1.0f);
    return values;
}

std::map<std::string, ParamMapSpec> paramMapsFromJson(const json& j, const std::string& source,
                                                      const ReactionModel& model) {
    FieldReader maps(j, source, "param_maps");
    std::map<std::string, ParamMapSpec> result;
    for (auto it = j.begin(); it != j.end(); ++it) {
        const ParamSpec* param = model.param(it.key());
        if (!param)
            maps.failField(it.key(), "is not a parameter of model '" + model.name() +
                                         "' (parameters: " + model.paramNames() + ")" +
                                         didYouMean(it.key(), splitNameList(model.paramNames())));
        FieldReader reader(*it, source, maps.path(it.key()));
        reader.rejectUnknown({"field", "range", "scale", "centre", "image"});
        ParamMapSpec spec;
        spec.field = reader.choice("field", spec.field, parseField, nameList(kFields));
        const json* range = reader.find("range");
        if (!range || !range->is_array() || range->size() != 2)
            reader.failField("range", "must be [min, max] within the parameter's range");
        spec.min = float(reader.numberValue((*range)[0], "range[0]", param->min, param->max));
        spec.max = float(reader.numberValue((*range)[1], "range[1]", param->min, param->max));
        spec.scale = float(reader.number("scale", spec.scale, 1.0, 1e5));
        if (const json* centre = reader.find("centre")) {
            if (!centre->is_array() || centre->size() != 2)
                reader.failField("centre", "must be [x, y], fractions of the grid");
            spec.centreX = float(reader.numberValue((*centre)[0], "centre[0]", -10, 10));
            spec.centreY = float(reader.numberValue((*centre)[1], "centre[1]", -10, 10));
        }
        spec.image = reader.string("image", "");
        if (spec.field == ParamMapSpec::Field::Image && spec.image.empty())
            reader.failField("image", "is required for an image field");
        result[it.key()] = spec;
    }
    return result;
}

json paramMapsToJson(const std::map<std::string, ParamMapSpec>& maps) {
    json j = json::object();
    for (const auto& [name, spec] : maps) {
        json m;
        m["field"] = toString(spec.field);
        m["range"] = {spec.min, spec.max};
        if (spec.field == ParamMapSpec::Field::Noise)
            m["scale"] = spec.scale;
        if (spec.field == ParamMapSpec::Field::Radial)
            m["centre"] = {spec.centreX, spec.centreY};
        if (!spec.image.empty())
            m["image"] = spec.image;
        j[name] = m;
    }
    return j;
}

} // namespace morphogen
