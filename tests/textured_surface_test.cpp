// The drawable surface (core/surface/textured_surface): mesh layout, winding,
// tangent frames, UVs, padded colours, and the baked relief against the
// analytic surface gradient of a known height, on both sides of tile edges.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "core/surface/display_atlas.hpp"
#include "core/surface/textured_surface.hpp"
#include "surface_fixtures.hpp"

using namespace morphogen;

namespace {

Eigen::Vector3f decode(const std::array<std::uint8_t, 4>& t) {
    return Eigen::Vector3f(t[0], t[1], t[2]) / 127.5f - Eigen::Vector3f::Ones();
}

} // namespace

TEST(TexturedSurface, MeshFramesAndUvs) {
    const int n = 6;
    const SurfaceTiles tiles = test::cubeSphereTiles(n, 2.0f);
    const TexturedMesh mesh =
        texturedSurface(tiles, {}, test::constantColours(tiles, {10, 20, 30, 255}));
    const std::size_t perTile = std::size_t(n + 1) * (n + 1);
    ASSERT_EQ(mesh.positions.size(), 6 * perTile);
    ASSERT_EQ(mesh.triangles.size(), std::size_t(6 * 2 * n * n));
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3f a = mesh.positions[t[0]], b = mesh.positions[t[1]],
                              c = mesh.positions[t[2]];
        // Wound counter-clockwise seen from outside the sphere.
        EXPECT_GT((b - a).cross(c - a).dot(a + b + c), 0.0f);
        // Both corners of a triangle in one tile.
        EXPECT_EQ(t[0] / perTile, t[1] / perTile);
        EXPECT_EQ(t[0] / perTile, t[2] / perTile);
    }
    const DisplayAtlas display(*tiles.atlas, 2, displayScale(*tiles.atlas, SurfaceLook{}));
    EXPECT_EQ(display.scale(), 3); // 6 x 6 tiles, drawn at least 16 texels wide
    for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
        const int tile = int(k / perTile), i = int(k % perTile) % (n + 1),
                  j = int(k % perTile) / (n + 1);
        EXPECT_TRUE(mesh.uvs[k].isApprox(display.cornerUv(tile, i, j)));
        const Eigen::Vector3f normal = mesh.normals[k], tangent = mesh.tangents[k].head<3>();
        EXPECT_NEAR(normal.norm(), 1.0f, 1e-5f);
        EXPECT_NEAR(tangent.norm(), 1.0f, 1e-5f);
        EXPECT_NEAR(tangent.dot(normal), 0.0f, 1e-5f);
        // The tangent follows +u, the bitangent -v (up the image: glTF's +Y up), along the grid.
        const Eigen::Vector3f bitangent = normal.cross(tangent) * mesh.tangents[k].w();
        const std::size_t right = i < n ? k + 1 : k, left = i < n ? k : k - 1;
        const std::size_t up = j < n ? k + n + 1 : k, down = j < n ? k : k - n - 1;
        EXPECT_GT(tangent.dot(mesh.positions[right] - mesh.positions[left]), 0.0f);
        EXPECT_LT(bitangent.dot(mesh.positions[up] - mesh.positions[down]), 0.0f);
    }
    // Colours padded, normals flat without a height.
    EXPECT_EQ(mesh.baseColour.width, display.width());
    EXPECT_EQ(mesh.baseColour.texels, display.pad(test::constantColours(tiles, {10, 20, 30, 255})));
    for (std::size_t p = 0; p < display.texelCount(); ++p)
        ASSERT_EQ(mesh.normalMap.texels[p], (std::array<std::uint8_t, 4>{128, 128, 255, 255}));
    EXPECT_THROW(texturedSurface(tiles, {1.0f}, test::constantColours(tiles, {0, 0, 0, 255})),
                 std::invalid_argument);
}

// A height that rises along x: every texel's relief (tangent-space normal, gutters included)
// is the tilt -relief * grad_surface(h) in its tile's frame. The surface gradient of
// h = (x + r) / 2r on a sphere of radius r is (e_x - N N_x) / 2r.
TEST(TexturedSurface, ReliefIsTheSurfaceGradientOnBothSidesOfEveryEdge) {
    const int n = 12;
    const float r = 1.0f;
    const SurfaceTiles tiles = test::cubeSphereTiles(n, r);
    const std::vector<float> height =
        test::fieldOnTexels(tiles, [](const Eigen::Vector3f& p) { return p.x(); });
    SurfaceLook look;
    look.bump = 3.0f;
    look.scale = 1; // the atlas's texels, each checked against its own gradient
    const TexturedMesh mesh =
        texturedSurface(tiles, height, test::constantColours(tiles, {9, 9, 9, 255}), look);
    const TexelFrames frames = texelFrames(tiles);
    // min-max normalisation over the texel centres: nearly [-r, r].
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t c = 0; c < height.size(); ++c) {
        lo = std::min(lo, height[c]);
        hi = std::max(hi, height[c]);
    }
    const float relief = look.bump * frames.meanTexelLength;
    const DisplayAtlas display(*tiles.atlas, look.gutter);
    double worst = 0;
    int checked = 0;
    for (int t = 0; t < 6; ++t)
        for (int v = -1; v <= n; ++v) // the tile and its first gutter ring
            for (int u = -1; u <= n; ++u) {
                if ((u < 0 || u >= n) && (v < 0 || v >= n))
                    continue; // corner blocks: an average at irregular corners
                const std::uint32_t own =
                    tiles.atlas->tileCell(t, std::clamp(u, 0, n - 1), std::clamp(v, 0, n - 1));
                // The texel the padded one stands for (across the edge for the gutter).
                const std::array<int, 2> xy = display.texel(t, u, v);
                const std::vector<DisplayAtlas::Source> src =
                    display.sources(std::size_t(xy[1]) * display.width() + xy[0]);
                ASSERT_EQ(src.size(), 1u);
                const Eigen::Vector3f N = tiles.texelNormals[src[0].cell];
                const Eigen::Vector3f gradient = (Eigen::Vector3f::UnitX() - N * N.x()) / (hi - lo);
                const Eigen::Vector3f tilt = -relief * gradient;
                const Eigen::Vector3f expected =
                    Eigen::Vector3f(tilt.dot(frames.tangent[own]), tilt.dot(frames.bitangent[own]),
                                    1.0f)
                        .normalized();
                const Eigen::Vector3f got =
                    decode(mesh.normalMap.texels[std::size_t(xy[1]) * display.width() + xy[0]]);
                worst = std::max(worst, double((got - expected).norm()));
                ++checked;
            }
    EXPECT_EQ(checked, 6 * (n * n + 4 * n));
    // 8-bit encoding (up to 0.0068 per vector) and the normals' curvature; a tilt from central
    // differences on the texel grid errs by 0.039 next to the cube's corners, one that used a
    // gutter in the wrong frame by more.
    EXPECT_LT(worst, 0.012) << "relief " << relief;
    std::cout << "worst tangent-space normal error " << worst << "\n";
}

// The textures of 4 x 4 tiles: 16 x 16 texture texels a tile, so the 2-texel
// gutter is 36% of the texture (75% when the atlas's texels were padded as
// they are), and the tiled mesh's UVs reach the finer texels' corners.
TEST(TexturedSurface, SmallTilesAreDrawnFinerSoTheGutterIsAboutAThird) {
    for (const int n : {4, 6, 8, 16}) {
        SCOPED_TRACE("tiles of " + std::to_string(n));
        const SurfaceTiles tiles = test::cubeSphereTiles(n, 1.0f);
        const TexturedMesh mesh =
            texturedSurface(tiles, {}, test::constantColours(tiles, {10, 20, 30, 255}));
        const int s = displayScale(*tiles.atlas, SurfaceLook{});
        EXPECT_GE(n * s, kDisplayTileTexels);
        const double inTiles = 6.0 * double(n * s) * double(n * s);
        const double share = inTiles / (double(mesh.baseColour.width) * mesh.baseColour.height);
        EXPECT_GE(share, 0.63) << mesh.baseColour.width << " x " << mesh.baseColour.height;
        EXPECT_EQ(mesh.normalMap.width, mesh.baseColour.width);
        // Constant colours stay constant wherever a tile is (weights sum to 1).
        int covered = 0;
        for (const auto& t : mesh.baseColour.texels)
            if (t[3] != 0) {
                ++covered;
                ASSERT_EQ(t, (std::array<std::uint8_t, 4>{10, 20, 30, 255}));
            }
        EXPECT_EQ(covered, 6 * (n * s + 4) * (n * s + 4));
    }
}
