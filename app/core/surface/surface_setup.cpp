#include "core/surface/surface_setup.hpp"

#include "core/surface/mesh_surface.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/mesh/mesh_report.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/session/cascade.hpp"
#include "core/sim/stroke_brush.hpp"
#include "core/surface/mesh_projector.hpp"
#include "core/surface/surface_weights.hpp"
#include "core/surface/tile_builder.hpp"

namespace morphogen {

LoadedMesh loadSurfaceMesh(const SurfaceSpec& spec, const std::string& baseDir) {
    const std::string& mesh = spec.mesh;
    if (mesh.rfind(kSampleMeshPrefix, 0) == 0) {
        const std::string name = mesh.substr(kSampleMeshPrefix.size());
        LoadedMesh loaded;
        loaded.mesh = sampleMesh(name, 0);
        loaded.file.path = mesh;
        loaded.file.format = "sample";
        loaded.file.vertices = loaded.mesh.positions.size();
        loaded.file.triangles = loaded.mesh.triangles.size();
        loaded.file.parts = 1;
        return loaded;
    }
    std::filesystem::path path(mesh);
    if (!baseDir.empty() && path.is_relative())
        path = std::filesystem::path(baseDir) / path;
    RepairOptions repair;
    repair.enabled = spec.repair;
    repair.mergeDistance = spec.mergeDistance;
    repair.wrap = spec.wrap;
    return loadMesh(path.string(), repair);
}

namespace {

// Says honestly what the tiles were laid on: a mesh too tangled to simplify
// is tiled whole (slowly), and a reader of the log should see that.
std::string simplificationSummary(const SurfaceTiles& tiles) {
    const SimplifyStats& s = tiles.simplifyStats;
    std::ostringstream os;
    if (!s.simplified) {
        os << "tiles laid on all of it"
           << (s.componentsKept > 0 ? " (no simplification kept its topology)" : "");
        return os.str();
    }
    os << "simplified to " << tiles.simplified.triangles.size() << " triangles";
    if (s.components > 1)
        os << " (" << s.components << " parts, each by its share of the area)";
    if (s.componentsKept > 0)
        os << ", " << s.componentsKept << (s.componentsKept == 1 ? " part" : " parts")
           << " kept whole (no simplification kept its topology)";
    const FollowStats& f = tiles.follow;
    if (f.insertions > 0) {
        os.precision(2);
        os << ", " << f.insertions << " of its vertices put back where the simplification cut off "
           << "parts (the tiles then " << 100 * f.gapAfter << "% of the diagonal from the model "
           << "at most, " << 100 * f.gapBefore << "% before)";
    }
    return os.str();
}

} // namespace

std::string SurfaceSetup::describe() const {
    std::ostringstream os;
    const Atlas& atlas = *tiles.atlas;
    os << "mesh " << mesh.file.path << ": ";
    if (mesh.repair.changed())
        os << "repaired (" << repairSummary(mesh.repair) << "), ";
    os << mesh.mesh.triangles.size() << " triangles, area " << tiles.surfaceArea
       << " (mesh units^2); " << simplificationSummary(tiles) << " -> " << atlas.tileCount()
       << " tiles of " << atlas.tileSize() << "x" << atlas.tileSize() << " texels in a "
       << atlas.width() << "x" << atlas.height() << " atlas; " << unitsPerWorld
       << " model units per mesh unit, texels " << texelUnits << " units on average; built in "
       << seconds << " s";
    if (switchedToSemiImplicit)
        os << "; semi-implicit steps, since explicit ones would run " << explicitSubsteps
           << " substeps each (set \"integrator\" or --integrator to choose)";
    return os.str();
}

int chooseSurfaceIntegrator(Session& session, const AtlasWeights& weights, bool* switched) {
    if (switched)
        *switched = false;
    const int substeps = weightedSubsteps(weights);
    if (session.integratorGiven || session.integrator != Integrator::ExplicitEuler ||
        weights.tensor || weights.drift || substeps <= session.relaxationPasses + 1)
        return substeps;
    // A mapped diffusion rate in any model the run uses (the semi-implicit
    // step needs constant rates).
    const auto mapsARate = [&](const ReactionModel& model) {
        for (const auto& chemical : model.chemicals())
            if (!chemical.diffusionParam.empty() &&
                session.paramMaps.count(chemical.diffusionParam))
                return true;
        return false;
    };
    if (mapsARate(session.reactionModel()))
        return substeps;
    for (std::size_t i = 0; i < session.stages.size(); ++i)
        if (mapsARate(stageModel(session.stages, i, session.reactionModel())))
            return substeps;
    session.integrator = Integrator::SemiImplicit;
    if (switched)
        *switched = true;
    return substeps;
}

namespace {

// Strokes placed by the model's bounding box land on the mesh's points
// nearest to them, their radius a fraction of its diagonal.
void placeModelStrokes(Session& session, const TriangleMesh& mesh) {
    const auto byBox = [](const LiveEdit& e) { return e.stroke && e.stroke->modelBox; };
    if (std::none_of(session.edits.begin(), session.edits.end(), byBox))
        return;
    const Bounds box = boundsOf(mesh.positions);
    const MeshProjector projector(mesh);
    for (LiveEdit& e : session.edits) {
        if (!byBox(e))
            continue;
        StrokeSpec& stroke = *e.stroke;
        stroke.surfacePoints.clear();
        for (const auto& f : stroke.boxPoints) {
            const Eigen::Vector3f inBox =
                box.min +
                (box.max - box.min).cwiseProduct(Eigen::Vector3d(f[0], f[1], f[2]).cast<float>());
            const Eigen::Vector3f p = projector.closest(inBox).position;
            stroke.surfacePoints.push_back({p.x(), p.y(), p.z()});
        }
        stroke.radius = stroke.boxRadius * box.diagonal();
    }
}

// A stroke or drop placed for another model (a preset's on its own mesh, run
// on the artist's) would paint nothing and say nothing: refused, naming it.
void requireStrokesOnSurface(const Session& session, const Atlas& atlas, const TriangleMesh& mesh,
                             const std::string& source) {
    const Bounds box = boundsOf(mesh.positions);
    // A stroke within a texel or two of the surface was placed on it (the
    // designer's picks land between texel centres): only clear misses count.
    const double slack = 0.02 * box.diagonal();
    for (std::size_t i = 0; i < session.edits.size(); ++i) {
        const LiveEdit& e = session.edits[i];
        if (!e.stroke || !e.stroke->surface || e.stroke->surfacePoints.empty())
            continue;
        const StrokeSpec& stroke = *e.stroke;
        const double nearest = nearestTexelDistance(stroke, *session.atlasPositions, &atlas);
        if (nearest <= std::max(stroke.radius, slack))
            continue;
        const auto& p = stroke.surfacePoints.front();
        std::ostringstream os;
        os << source << ": edit " << i + 1 << " (step " << e.step << "), a stroke at (" << p[0]
           << ", " << p[1] << ", " << p[2] << ") of radius " << stroke.radius
           << ", misses the surface: its nearest point is " << nearest << " away (the model spans ("
           << box.min.x() << ", " << box.min.y() << ", " << box.min.z() << ") to (" << box.max.x()
           << ", " << box.max.y() << ", " << box.max.z()
           << ")); strokes and drops in \"space\": \"surface\" are in the coordinates of the "
              "model they were made on: place them on this one, give them in \"space\": "
              "\"model\" (fractions of the model's bounding box, which fit any model), or "
              "leave them out";
        throw InputError(os.str());
    }
}

} // namespace

SurfaceSetup setUpSurface(Session& session,
                          const std::function<void(const std::string&, double)>& progress) {
    const auto start = std::chrono::steady_clock::now();
    const SurfaceSpec& spec = session.surface;
    SurfaceSetup setup;
    if (progress)
        progress("load", 0);
    setup.mesh = loadSurfaceMesh(spec, session.baseDir);
    const double area = surfaceArea(setup.mesh.mesh);
    if (!(area > 0) || !std::isfinite(area))
        throw InputError(spec.mesh + ": the surface has no area; nothing to grow a pattern on");
    if (session.length <= 0)
        session.length = session.width;
    // The surface holds as much pattern as the flat canvas: area length^2 units^2.
    setup.unitsPerWorld = session.length / std::sqrt(area);

    TileOptions options;
    options.tiles = spec.tiles;
    options.tileSize = spec.tileSize;
    if (options.tileSize == 0) {
        // Texels wanted over the budget's tiles, each tile n x n.
        const int budget = spec.tiles > 0 ? spec.tiles : automaticTileBudget(16);
        const double texels =
            session.length * session.length / (kSurfaceTexelUnits * kSurfaceTexelUnits);
        options.tileSize = std::clamp(int(std::lround(std::sqrt(texels / budget))),
                                      kMinSurfaceTileSize, kMaxSurfaceTileSize);
    }
    setup.tiles = buildSurfaceTiles(setup.mesh.mesh, options, progress, spec.mesh);

    SurfaceWeightOptions weights;
    weights.unitsPerWorld = setup.unitsPerWorld;
    weights.metricCorrection = spec.metricCorrection;
    weights.crossTerm = spec.crossTerm;
    if (session.diffusion.type == DiffusionType::Anisotropic)
        weights.direction = spec.direction;
    weights.gravity = session.gravity;
    if (spec.scaleBy == SurfaceScaleBy::MeanCurvature) {
        setup.featureScale = curvatureScale(setup.tiles, spec.scaleStrength);
        weights.featureScale = &setup.featureScale;
    }
    setup.weights = std::make_shared<const AtlasWeights>(surfaceWeights(setup.tiles, weights));

    double texelArea = 0;
    std::size_t used = 0;
    for (std::uint32_t i = 0; i < setup.tiles.atlas->cellCount(); ++i)
        if (setup.tiles.atlas->used(i)) {
            texelArea += setup.tiles.texelArea[i];
            ++used;
        }
    setup.texelUnits = used ? std::sqrt(texelArea / double(used)) * setup.unitsPerWorld : 0;
    useAtlas(session, setup.tiles.atlas, setup.weights);
    setup.explicitSubsteps =
        chooseSurfaceIntegrator(session, *setup.weights, &setup.switchedToSemiImplicit);
    session.atlasPositions = texelPositionsOf(setup.tiles);
    placeModelStrokes(session, setup.mesh.mesh);
    requireStrokesOnSurface(session, *setup.tiles.atlas, setup.mesh.mesh, spec.mesh);
    setup.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The run's handle on the surface for deformations (a copy: the caller
    // keeps its own setup).
    session.surfaceGeometry =
        std::make_shared<const MeshSurface>(std::make_shared<const SurfaceSetup>(setup), weights);
    return setup;
}

} // namespace morphogen
