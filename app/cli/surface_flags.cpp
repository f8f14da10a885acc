#include "cli/surface_flags.hpp"

#include <filesystem>
#include <sstream>
#include <vector>

#include "cli/flag_values.hpp"
#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/mesh/mesh_repair.hpp"

namespace morphogen::cli {

namespace {

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    std::string part;
    while (std::getline(in, part, ','))
        parts.push_back(part);
    if (!text.empty() && text.back() == ',')
        parts.emplace_back();
    return parts;
}

// "auto" or 0 is automatic (0); otherwise a number in [min, max].
int autoOrInteger(const std::string& flag, const std::string& text, int min, int max) {
    if (text == "auto" || text == "0")
        return 0;
    return int(integerFlag(flag, text, min, max, " (or auto)"));
}

// X,Y,Z: three numbers within kMaxSurfacePoint.
std::array<double, 3> pointFlag(const std::string& what, const std::string& text) {
    const std::vector<std::string> parts = splitCommas(text);
    if (parts.size() != 3)
        throw InputError(what + " '" + text + "': expected X,Y,Z (three numbers, e.g. 0,1,0)");
    std::array<double, 3> v{};
    for (std::size_t i = 0; i < 3; ++i)
        v[i] = numberFlag(what, parts[i], -kMaxSurfacePoint, kMaxSurfacePoint);
    return v;
}

SurfaceDirection parseDirection(const std::string& text) {
    const std::string usage = "--direction '" + text +
                              "': expected along:X,Y,Z or around:X,Y,Z[@PX,PY,PZ] (e.g. "
                              "along:0,1,0 or around:0,1,0@0,0,0)";
    const std::size_t colon = text.find(':');
    if (colon == std::string::npos)
        throw InputError(usage);
    const std::string kind = text.substr(0, colon), rest = text.substr(colon + 1);
    SurfaceDirection d;
    if (kind == "along") {
        d.type = SurfaceDirection::Type::Along;
        d.axis = pointFlag("--direction axis", rest);
    } else if (kind == "around") {
        d.type = SurfaceDirection::Type::Around;
        const std::size_t at = rest.find('@');
        d.axis = pointFlag("--direction axis", rest.substr(0, at));
        if (at != std::string::npos)
            d.through = pointFlag("--direction point", rest.substr(at + 1));
    } else {
        throw InputError(usage);
    }
    if (d.axis[0] == 0 && d.axis[1] == 0 && d.axis[2] == 0)
        throw InputError("--direction '" + text + "': the axis is 0,0,0; it needs a length");
    return d;
}

} // namespace

void addSurfaceFlags(CLI::App& cmd, SurfaceFlags& f) {
    const std::string group = "Surface (grow the pattern on a 3D model)";
    cmd.add_option("--mesh", f.mesh,
                   "grow the pattern on this mesh (OBJ, glTF, GLB, or sample:sphere|torus|holes|"
                   "blob); --out then takes a screenshot (.png, ...) or a textured model (.glb)")
        ->group(group);
    cmd.add_option("--tile-size", f.tileSize,
                   "texels per tile side, " + std::to_string(kMinSurfaceTileSize) + ".." +
                       std::to_string(kMaxSurfaceTileSize) +
                       " (default auto: from the pattern's scale)")
        ->group(group);
    cmd.add_option("--tiles", f.tiles,
                   "tile budget: the mesh is simplified to about a third as many triangles, "
                   "each split into 3 tiles (default auto)")
        ->group(group);
    cmd.add_flag("--no-metric-correction", f.noMetricCorrection,
                 "diffuse as if every texel were the same square (features then grow where the "
                 "tiles are stretched)")
        ->group(group);
    cmd.add_flag("--no-cross-term", f.noCrossTerm,
                 "the metric-corrected diffusion without its 9-point cross term: the 5-point "
                 "stencil, anisotropic on sheared tiles")
        ->group(group);
    cmd.add_flag("--no-repair", f.noRepair,
                 "tile the mesh as it is: no merging of seams, no removal of duplicate triangles "
                 "and specks, fins and bowtie vertices refused instead of cut apart")
        ->group(group);
    cmd.add_option("--merge-distance", f.mergeDistance,
                   "merge open-boundary vertices closer than this fraction of the bounding box's "
                   "diagonal (0..0.01, default 1e-5; 0: off), as Merge by Distance does")
        ->group(group);
    cmd.add_option("--wrap", f.wrap, kWrapHelp)
        ->check(CLI::IsMember({"auto", "always", "never"}))
        ->group(group);
    cmd.add_option("--curvature-scale", f.curvatureScale,
                   "shrink features where the mean curvature is high (strength, 0 = off; "
                   "size factor 1 / (1 + S |H| / median |H|))")
        ->group(group);
    cmd.add_option("--direction", f.direction,
                   "anisotropic presets' 0-degree direction on the model: along:X,Y,Z (a world "
                   "axis projected onto the surface; default along:0,1,0) or "
                   "around:X,Y,Z[@PX,PY,PZ] (circles about the axis through point P, default the "
                   "origin)")
        ->group(group);
    cmd.add_option("--view", f.view,
                   "camera: AZIMUTH,ELEVATION[,DISTANCE] in degrees and bounding-sphere radii "
                   "(default 30,20,0: 0 frames the model)")
        ->group(group);
    cmd.add_option("--resolution", f.resolution, "screenshot size WxH (default 1024x1024)")
        ->group(group);
    cmd.add_option("--turntable", f.turntable,
                   "N screenshots around the model, OUT_000.png ... (0: one)")
        ->group(group);
}

bool anySurfaceFlag(const SurfaceFlags& f) {
    return !f.mesh.empty() || !f.tileSize.empty() || !f.tiles.empty() || f.noMetricCorrection ||
           f.noCrossTerm || f.noRepair || !f.mergeDistance.empty() || !f.wrap.empty() ||
           !f.curvatureScale.empty() || !f.direction.empty() || !f.view.empty() ||
           !f.resolution.empty() || !f.turntable.empty();
}

void applySurfaceFlags(const SurfaceFlags& f, Session& s) {
    if (!f.mesh.empty()) {
        SurfaceSpec spec = s.surface; // keep a session's view and options
        spec.mesh = f.mesh;
        if (f.mesh.rfind(kSampleMeshPrefix, 0) != 0)
            spec.mesh = std::filesystem::absolute(f.mesh).lexically_normal().string();
        s.surface = spec;
    }
    if (!anySurfaceFlag(f))
        return;
    if (!s.surface.active())
        throw InputError(
            "the surface flags (--tile-size, --tiles, --no-metric-correction, "
            "--no-cross-term, --no-repair, --merge-distance, --wrap, --curvature-scale, "
            "--direction, --view, --resolution, --turntable) "
            "need a mesh: "
            "give --mesh FILE");
    SurfaceSpec& spec = s.surface;
    if (!f.tileSize.empty())
        spec.tileSize =
            autoOrInteger("--tile-size", f.tileSize, kMinSurfaceTileSize, kMaxSurfaceTileSize);
    if (!f.tiles.empty())
        spec.tiles = autoOrInteger("--tiles", f.tiles, kMinSurfaceTiles, kMaxSurfaceTiles);
    if (f.noMetricCorrection)
        spec.metricCorrection = false;
    if (f.noCrossTerm)
        spec.crossTerm = false;
    if (f.noRepair)
        spec.repair = false;
    if (!f.mergeDistance.empty())
        spec.mergeDistance = numberFlag("--merge-distance", f.mergeDistance, 0, kMaxMergeDistance);
    if (!f.wrap.empty())
        spec.wrap = *parseWrapMode(f.wrap); // checked by the option
    if (!f.curvatureScale.empty()) {
        spec.scaleStrength =
            numberFlag("--curvature-scale", f.curvatureScale, 0, kMaxSurfaceScaleStrength);
        spec.scaleBy =
            spec.scaleStrength > 0 ? SurfaceScaleBy::MeanCurvature : SurfaceScaleBy::None;
    }
    if (!f.direction.empty())
        spec.direction = parseDirection(f.direction);
    if (!f.view.empty()) {
        const std::vector<std::string> parts = splitCommas(f.view);
        if (parts.size() < 2 || parts.size() > 3)
            throw InputError("--view '" + f.view +
                             "': expected AZIMUTH,ELEVATION[,DISTANCE] (e.g. 30,20 or 45,10,3)");
        spec.view.azimuth = numberFlag("--view azimuth", parts[0], -360, 360);
        spec.view.elevation = numberFlag("--view elevation", parts[1], -90, 90);
        if (parts.size() == 3) {
            spec.view.distance = numberFlag("--view distance", parts[2], 0, kMaxViewDistance,
                                            " (bounding-sphere radii from the model's centre; 0 "
                                            "frames the model)");
            if (spec.view.distance != 0 && spec.view.distance < kMinViewDistance)
                throw InputError("--view distance '" + parts[2] + "': accepted are 0 (framed) or " +
                                 std::to_string(kMinViewDistance) + ".." +
                                 std::to_string(kMaxViewDistance) + " bounding-sphere radii");
        }
    }
    if (!f.resolution.empty()) {
        const std::size_t x = f.resolution.find('x');
        const std::string range =
            std::to_string(kMinViewSide) + ".." + std::to_string(kMaxViewSide);
        if (x == std::string::npos)
            throw InputError("--resolution '" + f.resolution + "': expected WxH with sides in " +
                             range + " (e.g. 1024x768)");
        spec.view.width = int(integerFlag("--resolution width", f.resolution.substr(0, x),
                                          kMinViewSide, kMaxViewSide));
        spec.view.height = int(integerFlag("--resolution height", f.resolution.substr(x + 1),
                                           kMinViewSide, kMaxViewSide));
    }
    if (!f.turntable.empty())
        spec.view.turntable = int(integerFlag("--turntable", f.turntable, 0, kMaxTurntableFrames));
}

} // namespace morphogen::cli
