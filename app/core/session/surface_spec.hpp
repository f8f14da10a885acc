#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class FieldReader;

// What sets the local feature size on a surface besides the metric (Lo et al.
// section 5.2): nothing, or the mean curvature (features shrink where the
// surface bends sharply).
enum class SurfaceScaleBy { None, MeanCurvature };
std::string toString(SurfaceScaleBy by);
std::optional<SurfaceScaleBy> parseSurfaceScaleBy(std::string_view name);
std::string surfaceScaleByNames();

// The camera of a surface screenshot: it looks at the model's bounding-sphere
// centre from `azimuth` degrees around the vertical (+y) axis and `elevation`
// degrees above the horizontal plane, at `distance` bounding-sphere radii
// (0: framed, the sphere just fits the picture).
struct SurfaceView {
    double azimuth = 30;
    double elevation = 20;
    double distance = 0;
    int width = 1024;
    int height = 1024;
    int turntable = 0; // frames around the model (0: one picture)

    bool operator==(const SurfaceView& o) const {
        return azimuth == o.azimuth && elevation == o.elevation && distance == o.distance &&
               width == o.width && height == o.height && turntable == o.turntable;
    }
};

// A session's "surface" block: grow the pattern on a triangle mesh (issue 11:
// surface tiles after Lo et al.) instead of a flat canvas. Its length is then
// the square root of the model's area in model units: the surface holds as
// much pattern as the flat canvas of the same session.
struct SurfaceSpec {
    // A mesh file (OBJ, glTF, GLB), relative to the session's folder, or
    // "sample:NAME" for a mesh the program generates (mesh_samples.hpp).
    std::string mesh;
    int tileSize = 0; // texels per tile side; 0: chosen from the pattern's scale
    int tiles = 0;    // tile budget; 0: automatic
    bool metricCorrection = true;
    // With metricCorrection: the 9-point stencil's cross term (SurfaceWeightOptions).
    bool crossTerm = true;
    SurfaceScaleBy scaleBy = SurfaceScaleBy::None;
    double scaleStrength = 1.0;
    SurfaceView view;

    bool active() const { return !mesh.empty(); }
};

// The "sample:" prefix of SurfaceSpec::mesh.
constexpr std::string_view kSampleMeshPrefix = "sample:";

// The "surface" block; errors name `top`'s source and the field.
SurfaceSpec surfaceSpecFromJson(const FieldReader& top, const nlohmann::json& block);
nlohmann::json surfaceSpecToJson(const SurfaceSpec& spec);

} // namespace morphogen
