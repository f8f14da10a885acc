#include "core/session/surface_spec.hpp"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/mesh/mesh_repair.hpp"

namespace morphogen {

namespace {

constexpr EnumName<SurfaceScaleBy> kScaleByNames[] = {
    {SurfaceScaleBy::None, "none"},
    {SurfaceScaleBy::MeanCurvature, "mean_curvature"},
};

SurfaceView viewFromJson(const FieldReader& surface, const nlohmann::json& block) {
    FieldReader reader(block, surface.source(), "surface.view");
    reader.rejectUnknown({"azimuth", "elevation", "distance", "resolution", "turntable"});
    SurfaceView view;
    view.azimuth = reader.number("azimuth", view.azimuth, -360, 360);
    view.elevation = reader.number("elevation", view.elevation, -90, 90);
    view.distance = reader.number("distance", view.distance, 0, kMaxViewDistance);
    if (view.distance != 0 && view.distance < kMinViewDistance)
        reader.failField("distance",
                         "is " + std::to_string(view.distance) + ", accepted are 0 (framed) or " +
                             std::to_string(kMinViewDistance) + ".." +
                             std::to_string(kMaxViewDistance) + " bounding-sphere radii");
    if (const nlohmann::json* resolution = reader.find("resolution")) {
        const std::string expected = "must be an array [width, height] of integers in " +
                                     std::to_string(kMinViewSide) + ".." +
                                     std::to_string(kMaxViewSide);
        if (!resolution->is_array() || resolution->size() != 2)
            reader.failField("resolution", expected);
        for (std::size_t i = 0; i < 2; ++i) {
            const nlohmann::json& side = (*resolution)[i];
            if (!side.is_number_integer())
                reader.failField("resolution", expected);
            const long long v = side.get<long long>();
            if (v < kMinViewSide || v > kMaxViewSide || (side.is_number_unsigned() && v < 0))
                reader.failField("resolution", expected + ", got " + side.dump());
            (i == 0 ? view.width : view.height) = int(v);
        }
    }
    view.turntable = int(reader.integer("turntable", view.turntable, 0, kMaxTurntableFrames));
    return view;
}

// An [x, y, z] of finite numbers within kMaxSurfacePoint.
std::array<double, 3> vectorField(const FieldReader& reader, const std::string& key) {
    const nlohmann::json* v = reader.find(key);
    std::ostringstream limit;
    limit << kMaxSurfacePoint;
    const std::string expected = "must be an array [x, y, z] of numbers in -" + limit.str() + ".." +
                                 limit.str() + " (mesh units)";
    if (!v || !v->is_array() || v->size() != 3)
        reader.failField(key, expected);
    std::array<double, 3> out{};
    for (std::size_t i = 0; i < 3; ++i) {
        if (!(*v)[i].is_number())
            reader.failField(key, expected + ", got " + v->dump());
        out[i] = (*v)[i].get<double>();
        if (!(std::abs(out[i]) <= kMaxSurfacePoint))
            reader.failField(key, expected + ", got " + v->dump());
    }
    return out;
}

SurfaceDirection directionFromJson(const FieldReader& surface, const nlohmann::json& block) {
    FieldReader reader(block, surface.source(), "surface.direction");
    reader.rejectUnknown({"along", "around", "through"});
    SurfaceDirection d;
    const bool along = reader.find("along") != nullptr, around = reader.find("around") != nullptr;
    if (along == around)
        reader.failField(along ? "around" : "along",
                         std::string(along ? "cannot be given with \"along\"" : "is missing") +
                             ": give one of {\"along\": [x, y, z]} (a world axis projected onto "
                             "the surface) or {\"around\": [x, y, z], \"through\": [x, y, z]} "
                             "(circles about an axis)");
    d.type = along ? SurfaceDirection::Type::Along : SurfaceDirection::Type::Around;
    const std::string key = along ? "along" : "around";
    d.axis = vectorField(reader, key);
    if (d.axis[0] == 0 && d.axis[1] == 0 && d.axis[2] == 0)
        reader.failField(key, "is [0, 0, 0]: an axis needs a length");
    if (reader.find("through")) {
        if (along)
            reader.failField("through", "applies to \"around\" only");
        d.through = vectorField(reader, "through");
    }
    return d;
}

nlohmann::json vectorJson(const std::array<double, 3>& v) {
    return nlohmann::json::array({v[0], v[1], v[2]});
}

} // namespace

std::string toString(const SurfaceDirection& d) {
    const auto text = [](const std::array<double, 3>& v) {
        return nlohmann::json(vectorJson(v)).dump();
    };
    if (d.type == SurfaceDirection::Type::Along)
        return "along " + text(d.axis);
    return "around " + text(d.axis) + " through " + text(d.through);
}

std::string toString(SurfaceScaleBy by) {
    return nameOf(kScaleByNames, by);
}

std::optional<SurfaceScaleBy> parseSurfaceScaleBy(std::string_view name) {
    return valueNamed(kScaleByNames, name);
}

std::string surfaceScaleByNames() {
    return nameList(kScaleByNames);
}

SurfaceSpec surfaceSpecFromJson(const FieldReader& top, const nlohmann::json& block) {
    FieldReader reader(block, top.source(), "surface");
    reader.rejectUnknown({"mesh", "tile_size", "tiles", "metric_correction", "cross_term", "scale",
                          "direction", "view", "repair", "merge_distance", "wrap"});
    SurfaceSpec spec;
    spec.mesh = reader.string("mesh", "");
    if (spec.mesh.empty())
        reader.failField("mesh", "is missing or empty: give a mesh file (OBJ, glTF, GLB) or "
                                 "sample:NAME");
    const long long tileSize = reader.integer("tile_size", 0, 0, kMaxSurfaceTileSize);
    if (tileSize != 0 && tileSize < kMinSurfaceTileSize)
        reader.failField("tile_size", "is " + std::to_string(tileSize) + ", accepted are 0 " +
                                          "(automatic) or " + std::to_string(kMinSurfaceTileSize) +
                                          ".." + std::to_string(kMaxSurfaceTileSize));
    spec.tileSize = int(tileSize);
    const long long tiles = reader.integer("tiles", 0, 0, kMaxSurfaceTiles);
    if (tiles != 0 && tiles < kMinSurfaceTiles)
        reader.failField("tiles", "is " + std::to_string(tiles) + ", accepted are 0 (automatic) " +
                                      "or " + std::to_string(kMinSurfaceTiles) + ".." +
                                      std::to_string(kMaxSurfaceTiles));
    spec.tiles = int(tiles);
    spec.metricCorrection = reader.boolean("metric_correction", spec.metricCorrection);
    spec.crossTerm = reader.boolean("cross_term", spec.crossTerm);
    spec.repair = reader.boolean("repair", spec.repair);
    spec.mergeDistance = reader.number("merge_distance", spec.mergeDistance, 0, kMaxMergeDistance);
    spec.wrap = reader.choice("wrap", spec.wrap, parseWrapMode, wrapModeNames());
    if (const nlohmann::json* scale = reader.find("scale")) {
        FieldReader s(*scale, top.source(), "surface.scale");
        s.rejectUnknown({"by", "strength"});
        spec.scaleBy = s.choice("by", spec.scaleBy, parseSurfaceScaleBy, surfaceScaleByNames());
        spec.scaleStrength = s.number("strength", spec.scaleStrength, 0, kMaxSurfaceScaleStrength);
    }
    if (const nlohmann::json* direction = reader.find("direction"))
        spec.direction = directionFromJson(reader, *direction);
    if (const nlohmann::json* view = reader.find("view"))
        spec.view = viewFromJson(reader, *view);
    return spec;
}

nlohmann::json surfaceSpecToJson(const SurfaceSpec& spec) {
    nlohmann::json j;
    j["mesh"] = spec.mesh;
    j["tile_size"] = spec.tileSize;
    j["tiles"] = spec.tiles;
    j["metric_correction"] = spec.metricCorrection;
    j["cross_term"] = spec.crossTerm;
    // The defaults stay unwritten: sessions written before them read back the same.
    if (!spec.repair)
        j["repair"] = false;
    if (spec.mergeDistance != SurfaceSpec().mergeDistance)
        j["merge_distance"] = spec.mergeDistance;
    if (spec.wrap != WrapMode::Automatic)
        j["wrap"] = toString(spec.wrap);
    if (spec.scaleBy != SurfaceScaleBy::None)
        j["scale"] = {{"by", toString(spec.scaleBy)}, {"strength", spec.scaleStrength}};
    // The default stays unwritten: sessions written before it read back the same.
    if (spec.direction != SurfaceDirection()) {
        const SurfaceDirection& d = spec.direction;
        if (d.type == SurfaceDirection::Type::Along)
            j["direction"] = {{"along", vectorJson(d.axis)}};
        else
            j["direction"] = {{"around", vectorJson(d.axis)}, {"through", vectorJson(d.through)}};
    }
    const SurfaceView& v = spec.view;
    j["view"] = {{"azimuth", v.azimuth},
                 {"elevation", v.elevation},
                 {"distance", v.distance},
                 {"resolution", {v.width, v.height}}};
    if (v.turntable > 0)
        j["view"]["turntable"] = v.turntable;
    return j;
}

} // namespace morphogen
