#include "core/session/surface_spec.hpp"

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"

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

} // namespace

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
    reader.rejectUnknown(
        {"mesh", "tile_size", "tiles", "metric_correction", "cross_term", "scale", "view"});
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
    if (const nlohmann::json* scale = reader.find("scale")) {
        FieldReader s(*scale, top.source(), "surface.scale");
        s.rejectUnknown({"by", "strength"});
        spec.scaleBy = s.choice("by", spec.scaleBy, parseSurfaceScaleBy, surfaceScaleByNames());
        spec.scaleStrength = s.number("strength", spec.scaleStrength, 0, kMaxSurfaceScaleStrength);
    }
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
    if (spec.scaleBy != SurfaceScaleBy::None)
        j["scale"] = {{"by", toString(spec.scaleBy)}, {"strength", spec.scaleStrength}};
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
