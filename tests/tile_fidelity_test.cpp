// The tiles follow the whole model (core/surface/tile_fidelity.hpp): what a
// tight budget's simplification cuts off (the blob's tail, a scan's ears) is
// put back, so the tiled surface stays within 1% of the bounding-box diagonal
// of every vertex of the model, while a smooth model, whose chords the
// projection already closes, is left as it was.

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/surface/tile_builder.hpp"
#include "core/surface/tile_diagnostics.hpp"
#include "core/surface/tile_fidelity.hpp"

using namespace morphogen;

namespace {

long eulerSum(const TriangleMesh& mesh) {
    long sum = 0;
    for (const MeshComponent& c : checkMesh(mesh).components)
        sum += c.eulerCharacteristic;
    return sum;
}

} // namespace

TEST(TileFidelity, TheBlobsTailIsPutBack) {
    const TriangleMesh model = blob(4);
    TileOptions options;
    options.tileSize = 4;
    const SurfaceTiles tiles = buildSurfaceTiles(model, options, {}, "blob");
    // Without the insertions the tail's tip lay 4.1% of the diagonal from the
    // tiles (measured with tile-stats).
    EXPECT_GT(tiles.follow.gapBefore, 0.02);
    EXPECT_GT(tiles.follow.insertions, 0u);
    const SurfaceGap gap = tiledSurfaceGap(tiles, model);
    EXPECT_LT(gap.max, 0.01);
    EXPECT_DOUBLE_EQ(tiles.follow.gapAfter, gap.max);
    // A third more triangles at most, the topology unchanged.
    EXPECT_LE(tiles.atlas->tileCount(), 4 * automaticTileBudget(4) / 3 + 3);
    EXPECT_TRUE(checkMesh(tiles.simplified).manifold());
    EXPECT_EQ(eulerSum(tiles.simplified), eulerSum(model));
}

TEST(TileFidelity, ASmoothModelIsLeftAsItWas) {
    const TriangleMesh model = torus(64);
    TileOptions options;
    options.tileSize = 4;
    const SurfaceTiles tiles = buildSurfaceTiles(model, options, {}, "torus");
    EXPECT_TRUE(tiles.simplifyStats.simplified);
    EXPECT_EQ(tiles.follow.insertions, 0u);
    EXPECT_LT(tiledSurfaceGap(tiles, model).max, 0.002);
}

// followModel alone: a square cut from a pyramid's base gets its apex back,
// as one vertex over the triangle below it; the four sides face up.
TEST(TileFidelity, AMissedApexBecomesAVertexOfTheTriangleBelowIt) {
    TriangleMesh pyramid;
    pyramid.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.4f, 0.45f, 0.8f}};
    pyramid.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    TriangleMesh base;
    base.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    base.triangles = {{0, 1, 2}, {0, 2, 3}};
    std::vector<char> inserted;
    const FollowStats s = followModel(base, pyramid, 0.01, 100, 6, &inserted);
    EXPECT_EQ(s.insertions, 1u);
    EXPECT_NEAR(s.gapBefore, 0.8 / boundsOf(pyramid.positions).diagonal(), 1e-6);
    EXPECT_LT(s.gapAfter, 1e-6);
    ASSERT_EQ(base.positions.size(), 5u);
    EXPECT_EQ(base.positions[4], pyramid.positions[4]);
    EXPECT_EQ(inserted, (std::vector<char>{0, 0, 0, 0, 1}));
    EXPECT_EQ(base.triangles.size(), 4u);
    for (const auto& t : base.triangles) {
        const Eigen::Vector3f n = (base.positions[t[1]] - base.positions[t[0]])
                                      .cross(base.positions[t[2]] - base.positions[t[0]]);
        EXPECT_GT(n.z(), 0.0f);
    }
    // No budget left: nothing inserted.
    TriangleMesh again;
    again.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    again.triangles = {{0, 1, 2}, {0, 2, 3}};
    EXPECT_EQ(followModel(again, pyramid, 0.01, 3).insertions, 0u);
}
