#include "core/surface/tile_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/mesh/edge_table.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/surface/mesh_simplify.hpp"
#include "core/surface/surface_geometry.hpp"
#include "core/surface/tile_diagnostics.hpp"
#include "core/surface/tile_fidelity.hpp"
#include "core/surface/tile_mesh_quality.hpp"
#include "core/surface/tile_split.hpp"

namespace morphogen {

namespace {

constexpr int kAutomaticTiles = 2000;
constexpr int kMaxAtlasSide = 65535;
// Edges longer than this many times the equilateral edge of the budget's mean
// triangle are split (Botsch and Kobbelt's isotropic remeshing uses 4/3).
constexpr double kSplitLength = 4.0 / 3.0;
// The farthest a model's vertex may lie from the simplified mesh before it is
// put back (followModel), a fraction of the bounding-box diagonal.
constexpr double kFollowTolerance = 0.006;
// How far a vertex put back may move while the shapes are evened out, a
// fraction of the diagonal.
constexpr double kPinReach = 0.008;
// Passes of putting back, evening out and laying the tiles again.
constexpr int kFollowPasses = 3;

// The most tiles of this size the limits and the atlas side allow.
long long maxTiles(int tileSize) {
    const long long perRow = kMaxAtlasSide / tileSize;
    return std::min({perRow * perRow, static_cast<long long>(kMaxSurfaceTiles),
                     kMaxSurfaceTexels / (static_cast<long long>(tileSize) * tileSize)});
}

} // namespace

int automaticTileBudget(int tileSize) {
    return int(std::min<long long>(kAutomaticTiles, maxTiles(tileSize)));
}

void checkTileOptions(const TileOptions& options) {
    if (options.tileSize < kMinSurfaceTileSize || options.tileSize > kMaxSurfaceTileSize)
        throw InputError("--tile-size " + std::to_string(options.tileSize) +
                         " is out of range: a tile is " + std::to_string(kMinSurfaceTileSize) +
                         " to " + std::to_string(kMaxSurfaceTileSize) + " texels on a side");
    if (options.tiles == 0)
        return;
    if (options.tiles < kMinSurfaceTiles || options.tiles > kMaxSurfaceTiles)
        throw InputError("--tiles " + std::to_string(options.tiles) +
                         " is out of range: 0 (automatic) or " + std::to_string(kMinSurfaceTiles) +
                         " to " + std::to_string(kMaxSurfaceTiles) +
                         " tiles (3 per triangle of the simplified mesh)");
    const long long texels =
        static_cast<long long>(options.tiles) * options.tileSize * options.tileSize;
    if (texels > kMaxSurfaceTexels || options.tiles > maxTiles(options.tileSize))
        throw InputError("--tiles " + std::to_string(options.tiles) + " of --tile-size " +
                         std::to_string(options.tileSize) + " is too many: at most " +
                         std::to_string(maxTiles(options.tileSize)) + " tiles of " +
                         std::to_string(options.tileSize) + "x" + std::to_string(options.tileSize) +
                         " texels (" + std::to_string(kMaxSurfaceTexels) +
                         " texels in all, an atlas under 65536 texels per side)");
}

SurfaceTiles splitIntoTiles(const TriangleMesh& mesh, int tileSize) {
    SurfaceTiles out;
    out.simplified = mesh;
    const EdgeTable edges(mesh);
    const int nv = int(mesh.positions.size());
    const int ne = int(edges.edgeCount());
    out.quadVertices = mesh.positions;
    out.quadVertices.reserve(std::size_t(nv + ne) + mesh.triangles.size());
    for (int e = 0; e < ne; ++e)
        out.quadVertices.push_back(
            0.5f * (mesh.positions[edges.lowVertex(e)] + mesh.positions[edges.highVertex(e)]));
    out.splitBarycentric.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3f &a = mesh.positions[t[0]], &b = mesh.positions[t[1]],
                              &c = mesh.positions[t[2]];
        const Eigen::Vector3f w = quadSplitPoint(a, b, c);
        out.splitBarycentric.push_back(w);
        out.quadVertices.push_back(w[0] * a + w[1] * b + w[2] * c);
    }

    out.quads.reserve(3 * mesh.triangles.size());
    out.tileTriangle.reserve(3 * mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        const int split = nv + ne + int(t);
        for (int k = 0; k < 3; ++k) {
            // Corner k's quad: its vertex, the midpoint of the edge leaving it
            // (k -> k+1, used by corner k), the split point, the midpoint of the
            // edge arriving (k+2 -> k, used by corner k+2): the triangle's sense.
            const int leaving = nv + int(edges.edgeOf(t, k));
            const int arriving = nv + int(edges.edgeOf(t, (k + 2) % 3));
            out.quads.push_back({int(tri[k]), leaving, split, arriving});
            out.tileTriangle.push_back(std::uint32_t(t));
        }
    }
    out.atlas = std::make_shared<const Atlas>(Atlas::fromQuads(tileSize, out.quads));
    return out;
}

SurfaceTiles buildSurfaceTiles(const TriangleMesh& full, const TileOptions& options,
                               const TileProgress& progress, const std::string& source) {
    checkTileOptions(options);
    const auto report = [&](const char* phase, double fraction) {
        if (progress)
            progress(phase, fraction);
    };
    if (full.triangles.empty())
        throw InputError(source + ": the mesh has no triangles to lay tiles on");
    requireUsableForTiles(checkMesh(full), source);

    const int budget = options.tiles > 0 ? options.tiles : automaticTileBudget(options.tileSize);
    report("simplify", 0);
    SimplifyStats stats;
    TriangleMesh simplified = simplifyForTiles(full, std::size_t(budget / 3), &stats);
    const long long tiles = 3 * static_cast<long long>(simplified.triangles.size());
    if (tiles > maxTiles(options.tileSize))
        throw InputError(source + ": " + std::to_string(full.triangles.size()) +
                         " triangles could only be simplified to " +
                         std::to_string(simplified.triangles.size()) + " (" +
                         std::to_string(tiles) + " tiles) keeping their topology and borders; " +
                         "at most " + std::to_string(maxTiles(options.tileSize)) + " tiles of " +
                         std::to_string(options.tileSize) + "x" + std::to_string(options.tileSize) +
                         " texels fit the limits: lower --tile-size or simplify the mesh first");

    report("tiles", 0);
    const MeshProjector projector(full);
    if (stats.simplified) {
        // Room for splitting the long edges within the budget: simplify further by
        // as many triangles as the splits would add (a dry run says how many).
        const std::size_t target = std::max(std::size_t(budget / 3), simplified.triangles.size());
        const double maxLength = kSplitLength * tileEdgeLength(simplified, target);
        TriangleMesh trial = simplified;
        splitLongEdges(trial, projector, maxLength, SIZE_MAX);
        if (trial.triangles.size() > target) {
            SimplifyStats again;
            TriangleMesh fewer =
                simplifyForTiles(full, target * target / trial.triangles.size(), &again);
            if (again.simplified && fewer.triangles.size() < simplified.triangles.size())
                simplified = std::move(fewer);
        }
        splitLongEdges(simplified, projector, maxLength, target);
        improveForTiles(simplified, projector);
    }
    const auto lay = [&](const TriangleMesh& on) {
        SurfaceTiles tiles = splitIntoTiles(on, options.tileSize);
        tiles.simplifyStats = stats;
        report("projection", 0);
        computeSurfaceGeometry(tiles, full, projector, [&](double f) { report("projection", f); });
        report("projection", 1);
        return tiles;
    };
    SurfaceTiles out = lay(simplified);
    if (!stats.simplified)
        return out;
    // What the simplifier cut off and the projection could not reach (an
    // ear's tip) goes back, held near where it is while the shapes are evened
    // out, and the tiles are laid again; up to a third more triangles. Evening
    // out moves the other vertices too, so a pass can open a gap elsewhere:
    // a few passes.
    const std::size_t cap = simplified.triangles.size() * 4 / 3;
    VertexPins pins;
    pins.reach = float(kPinReach * boundsOf(full.positions).diagonal());
    std::vector<double> gaps;
    SurfaceGap gap = tiledSurfaceGap(out, full, &gaps);
    FollowStats follow;
    follow.gapBefore = follow.gapAfter = gap.max;
    for (int pass = 0; pass < kFollowPasses && gap.max > kFollowTolerance; ++pass) {
        std::vector<char> missed(gaps.size());
        for (std::size_t v = 0; v < gaps.size(); ++v)
            missed[v] = gaps[v] > kFollowTolerance ? 1 : 0;
        std::vector<char> inserted;
        const FollowStats f =
            followModel(simplified, full, kFollowTolerance, cap, 6, &inserted, &missed);
        if (f.insertions == 0)
            break;
        pins.pinned.resize(simplified.positions.size(), 0);
        pins.at.resize(simplified.positions.size(), Eigen::Vector3f::Zero());
        for (std::size_t v = 0; v < inserted.size(); ++v)
            if (inserted[v]) {
                pins.pinned[v] = 1;
                pins.at[v] = simplified.positions[v];
            }
        improveForTiles(simplified, projector, 8, &pins);
        SurfaceTiles again = lay(simplified);
        std::vector<double> gapsAgain;
        const SurfaceGap gapAgain = tiledSurfaceGap(again, full, &gapsAgain);
        if (gapAgain.max >= gap.max)
            break; // no closer (a budget far too small for the shape): keep the tiles before
        follow.insertions += f.insertions;
        follow.gapAfter = gapAgain.max;
        out = std::move(again);
        gap = gapAgain;
        gaps = std::move(gapsAgain);
    }
    out.follow = follow;
    return out;
}

} // namespace morphogen
