#include "core/surface/surface_setup.hpp"

#include "core/surface/mesh_surface.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/mesh/mesh_samples.hpp"
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
    return loadMesh(path.string());
}

std::string SurfaceSetup::describe() const {
    std::ostringstream os;
    const Atlas& atlas = *tiles.atlas;
    os << "mesh " << mesh.file.path << ": " << mesh.mesh.triangles.size() << " triangles, area "
       << tiles.surfaceArea << " (mesh units^2); simplified to "
       << tiles.simplified.triangles.size() << " triangles -> " << atlas.tileCount() << " tiles of "
       << atlas.tileSize() << "x" << atlas.tileSize() << " texels in a " << atlas.width() << "x"
       << atlas.height() << " atlas; " << unitsPerWorld << " model units per mesh unit, texels "
       << texelUnits << " units on average; built in " << seconds << " s";
    return os.str();
}

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
    session.atlasPositions = texelPositionsOf(setup.tiles);
    setup.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The run's handle on the surface for deformations (a copy: the caller
    // keeps its own setup).
    session.surfaceGeometry =
        std::make_shared<const MeshSurface>(std::make_shared<const SurfaceSetup>(setup), weights);
    return setup;
}

} // namespace morphogen
