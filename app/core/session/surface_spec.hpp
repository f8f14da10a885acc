#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "core/mesh/wrap_mode.hpp"

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

// Where anisotropic diffusion's 0-degree direction points on a surface: a
// Witkin-Kass tensor's theta turns from it, counter-clockwise about the outward
// normal. Along: a world axis projected onto the tangent plane (meridians of a
// sphere for the y axis). Around: circles about an axis through a point
// (latitude lines, a torus's rings). Where the direction is undefined (the axis
// along the normal, a point on the axis) the anisotropy fades to isotropic over
// a neighbourhood (core/surface/surface_tensor.hpp).
struct SurfaceDirection {
    enum class Type { Along, Around };
    Type type = Type::Along;
    std::array<double, 3> axis{0.0, 1.0, 0.0};    // mesh units; any length but 0
    std::array<double, 3> through{0.0, 0.0, 0.0}; // Around: a point on the axis (mesh units)

    bool operator==(const SurfaceDirection& o) const {
        return type == o.type && axis == o.axis && (type == Type::Along || through == o.through);
    }
    bool operator!=(const SurfaceDirection& o) const { return !(*this == o); }
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
    // Mend the mesh before tiling it (mesh_repair.hpp): merge open-boundary
    // vertices within mergeDistance of the box diagonal, remove duplicate
    // triangles and specks, cut fins and bowtie vertices apart.
    bool repair = true;
    double mergeDistance = 1e-5; // kDefaultMergeDistance
    // "auto": a mesh that is a soup of pieces is replaced by its alpha wrap
    // (mesh_wrap.hpp); "always", "never".
    WrapMode wrap = WrapMode::Automatic;
    SurfaceScaleBy scaleBy = SurfaceScaleBy::None;
    double scaleStrength = 1.0;
    // Anisotropic diffusion only (a "diffusion" of type anisotropic).
    SurfaceDirection direction;
    SurfaceView view;

    bool active() const { return !mesh.empty(); }
};

// The "sample:" prefix of SurfaceSpec::mesh.
constexpr std::string_view kSampleMeshPrefix = "sample:";

// "along" or "around" and an axis, as the JSON and --direction write them.
std::string toString(const SurfaceDirection& direction);

// The "surface" block; errors name `top`'s source and the field.
SurfaceSpec surfaceSpecFromJson(const FieldReader& top, const nlohmann::json& block);
nlohmann::json surfaceSpecToJson(const SurfaceSpec& spec);

} // namespace morphogen
