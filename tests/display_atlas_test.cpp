// The padded display atlas: gutter texels against independent one-step
// references across every kind of glued edge (cube, rotated and mirrored
// tiles), clamping at open edges, corner blocks, bilinear filtering at
// irregular tile corners, and the UVs.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/domain/atlas.hpp"
#include "core/surface/display_atlas.hpp"

using namespace morphogen;

namespace {

// Per-cell values all different (so an equality names the cell).
std::vector<float> cellIds(const Atlas& atlas) {
    std::vector<float> v(atlas.cellCount());
    for (std::size_t c = 0; c < v.size(); ++c)
        v[c] = float(c) + 1.0f;
    return v;
}

float at(const DisplayAtlas& d, const std::vector<float>& padded, int tile, int u, int v) {
    const std::array<int, 2> xy = d.texel(tile, u, v);
    return padded[std::size_t(xy[1]) * d.width() + xy[0]];
}

// Bilinear filtering of the padded image at uv, as GL samples (texel centres at +0.5).
float bilinear(const DisplayAtlas& d, const std::vector<float>& padded, Eigen::Vector2f uv) {
    const float x = uv.x() * d.width() - 0.5f, y = uv.y() * d.height() - 0.5f;
    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
    const float fx = x - x0, fy = y - y0;
    auto p = [&](int xx, int yy) { return padded[std::size_t(yy) * d.width() + xx]; };
    return (1 - fx) * (1 - fy) * p(x0, y0) + fx * (1 - fy) * p(x0 + 1, y0) +
           (1 - fx) * fy * p(x0, y0 + 1) + fx * fy * p(x0 + 1, y0 + 1);
}

constexpr Direction kOut[4] = {Direction::PlusX, Direction::PlusY, Direction::MinusX,
                               Direction::MinusY};

// Every gutter texel beside an edge (not in a corner block), ring by ring: ring 1 is the cell
// one step across the edge from the border texel (Atlas::step); ring r + 1 continues straight on
// from ring r in the frame it arrived in (opposite of `back`), which is the gluing's rule in
// atlas.hpp, independent of Atlas::walk.
void expectEdgeGutters(const Atlas& atlas, int gutter) {
    const DisplayAtlas d(atlas, gutter);
    const std::vector<float> ids = cellIds(atlas);
    const std::vector<float> padded = d.pad(ids, 1);
    const int n = atlas.tileSize();
    int checked = 0;
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int e = 0; e < 4; ++e)
            for (int i = 0; i < n; ++i) {
                // Border texel i along edge e (u, v in the tile frame) and the outward unit step.
                const int du = e == 0 ? 1 : e == 2 ? -1 : 0, dv = e == 1 ? 1 : e == 3 ? -1 : 0;
                const int u = e == 0 ? n - 1 : e == 2 ? 0 : i, v = e == 1 ? n - 1 : e == 3 ? 0 : i;
                std::uint32_t cell = atlas.tileCell(t, u, v);
                Direction d0 = kOut[e];
                for (int r = 1; r <= gutter; ++r) {
                    const AtlasStep s = atlas.step(cell, d0);
                    if (s.cell != cell) // glued: carry on straight in the new frame
                        d0 = opposite(s.back);
                    cell = s.cell;
                    EXPECT_EQ(at(d, padded, t, u + r * du, v + r * dv), ids[cell])
                        << "tile " << t << " edge " << e << " texel " << i << " ring " << r;
                    ++checked;
                }
            }
    EXPECT_EQ(checked, atlas.tileCount() * 4 * n * gutter);
}

// The tile interiors are copied unchanged, and texels of no tile are 0.
void expectInteriorsCopied(const Atlas& atlas, int gutter) {
    const DisplayAtlas d(atlas, gutter);
    const std::vector<float> ids = cellIds(atlas);
    const std::vector<float> padded = d.pad(ids, 1);
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int v = 0; v < atlas.tileSize(); ++v)
            for (int u = 0; u < atlas.tileSize(); ++u)
                ASSERT_EQ(at(d, padded, t, u, v), ids[atlas.tileCell(t, u, v)]);
}

// Bilinear filtering at every tile-corner vertex gives the mean of the corner texels round it,
// the same from each tile there (valence 3, 4 and 5).
void expectCornerVerticesAgree(const Atlas& atlas, int gutter) {
    const DisplayAtlas d(atlas, gutter);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> values(atlas.cellCount());
    for (float& x : values)
        x = uniform(rng);
    const std::vector<float> padded = d.pad(values, 1);
    const int n = atlas.tileSize();
    const int cornerI[4] = {0, n, n, 0}, cornerJ[4] = {0, 0, n, n};
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int c = 0; c < 4; ++c) {
            const int k = atlas.cornerValence(t, c);
            if (k < 3 || k > 5)
                continue;
            // The corner texels round the vertex: walk round the fan from this tile's corner
            // texel, crossing one edge at a time (each corner texel's two neighbours across its
            // tile's edges at the vertex are the next ones round).
            std::vector<std::uint32_t> ring;
            std::uint32_t cell = atlas.cornerCell(t, c);
            Direction out = kOut[(c + 2) % 4]; // corner 0: -x first
            for (int step = 0; step < k; ++step) {
                ring.push_back(cell);
                const AtlasStep s = atlas.step(cell, out);
                // s.cell is the next tile's corner texel at the vertex; of its corner's two
                // outward directions, leave by the one that is not the way back.
                const int next = atlas.tileOf(s.cell);
                int corner = -1;
                for (int cc = 0; cc < 4; ++cc)
                    if (atlas.cornerCell(next, cc) == s.cell)
                        corner = cc;
                ASSERT_GE(corner, 0);
                const int a = (corner + 2) % 4, b = (corner + 3) % 4;
                out = kOut[int(s.back) == a ? b : a];
                cell = s.cell;
            }
            ASSERT_EQ(cell, atlas.cornerCell(t, c)) << "the fan closes";
            float mean = 0;
            for (const std::uint32_t r : ring)
                mean += values[r];
            mean /= float(k);
            EXPECT_NEAR(bilinear(d, padded, d.cornerUv(t, cornerI[c], cornerJ[c])), mean, 1e-5f)
                << "tile " << t << " corner " << c << " valence " << k;
        }
}

} // namespace

TEST(DisplayAtlas, SizesAndUvs) {
    const Atlas cube = Atlas::cube(8);
    const DisplayAtlas d(cube, 2);
    EXPECT_EQ(d.paddedTileSize(), 12);
    EXPECT_EQ(d.width(), cube.tilesPerRow() * 12);
    EXPECT_EQ(d.height(), 2 * 12); // 6 tiles, 3 per row
    for (int t = 0; t < 6; ++t) {
        const std::array<float, 4> rect = d.paddedRect(t);
        for (int j = 0; j <= 8; ++j)
            for (int i = 0; i <= 8; ++i) {
                const Eigen::Vector2f uv = d.cornerUv(t, i, j);
                // Inside the padded rectangle by the gutter, in [0, 1].
                EXPECT_GE(uv.x(), rect[0] + 2.0f / d.width() - 1e-6f);
                EXPECT_LE(uv.x(), rect[2] - 2.0f / d.width() + 1e-6f);
                EXPECT_GE(uv.y(), rect[1] + 2.0f / d.height() - 1e-6f);
                EXPECT_LE(uv.y(), rect[3] - 2.0f / d.height() + 1e-6f);
            }
        // Corner (0, 0) is the lower-left corner of texel (0, 0).
        const std::array<int, 2> xy = d.texel(t, 0, 0);
        EXPECT_FLOAT_EQ(d.cornerUv(t, 0, 0).x(), float(xy[0]) / d.width());
        EXPECT_FLOAT_EQ(d.cornerUv(t, 0, 0).y(), float(xy[1]) / d.height());
    }
    EXPECT_THROW(DisplayAtlas(cube, 0), std::invalid_argument);
}

TEST(DisplayAtlas, GuttersMatchTheirNeighboursAcrossGluedEdges) {
    expectEdgeGutters(Atlas::cube(5), 1);
    expectEdgeGutters(Atlas::cube(5), 3);
    // Every relative rotation, plain and mirrored.
    expectEdgeGutters(Atlas::rotatedTiles(4), 2);
    // A gutter wider than a tile walks through the next tile into the one after.
    expectEdgeGutters(Atlas::periodicPlane(2, 3, 2), 3);
    expectInteriorsCopied(Atlas::rotatedTiles(4), 2);
}

TEST(DisplayAtlas, OpenEdgesClampToTheBorder) {
    const Atlas lone(4, 1);
    const DisplayAtlas d(lone, 2);
    const std::vector<float> ids = cellIds(lone);
    const std::vector<float> padded = d.pad(ids, 1);
    for (int v = -2; v < 6; ++v)
        for (int u = -2; u < 6; ++u)
            EXPECT_EQ(at(d, padded, 0, u, v),
                      ids[lone.tileCell(0, std::clamp(u, 0, 3), std::clamp(v, 0, 3))])
                << u << ", " << v;
}

TEST(DisplayAtlas, PeriodicPlaneCornerBlocksAreThePlane) {
    // Valence 4 everywhere: the padded tile is a window of the periodic plane.
    const int n = 4, g = 2;
    const Atlas plane = Atlas::periodicPlane(n, 3, 3);
    const DisplayAtlas d(plane, g);
    std::vector<float> xy(plane.cellCount());
    for (std::size_t c = 0; c < xy.size(); ++c)
        xy[c] = float(c);
    const std::vector<float> padded = d.pad(xy, 1);
    const int side = 3 * n;
    for (int t = 0; t < 9; ++t)
        for (int v = -g; v < n + g; ++v)
            for (int u = -g; u < n + g; ++u) {
                const int x = ((t % 3) * n + u + side) % side, y = ((t / 3) * n + v + side) % side;
                EXPECT_EQ(at(d, padded, t, u, v), float(plane.cellAt(x, y)));
            }
}

TEST(DisplayAtlas, BilinearAtIrregularCornersIsTheSameFromEveryTile) {
    expectCornerVerticesAgree(Atlas::cube(4), 2); // valence 3
    expectCornerVerticesAgree(Atlas::periodicPlane(4, 3, 3), 1);
    std::vector<std::array<int, 4>> quads; // a closed-off fan of 5: valence 5 at vertex 0
    for (int t = 0; t < 5; ++t)
        quads.push_back({0, 1 + 2 * t, 2 + 2 * t, 1 + (2 * t + 2) % 10});
    expectCornerVerticesAgree(Atlas::fromQuads(4, quads), 2);
}

TEST(DisplayAtlas, PadsRgbaBytes) {
    const Atlas cube = Atlas::cube(3);
    const DisplayAtlas d(cube, 1);
    std::vector<std::array<std::uint8_t, 4>> colours(cube.cellCount(), {0, 0, 0, 0});
    std::vector<float> red(cube.cellCount(), 0.0f);
    for (std::size_t c = 0; c < colours.size(); ++c)
        if (cube.used(std::uint32_t(c))) {
            colours[c] = {std::uint8_t(c * 7 % 256), 10, 20, 255};
            red[c] = float(colours[c][0]);
        }
    const auto paddedBytes = d.pad(colours);
    const auto paddedRed = d.pad(red, 1);
    ASSERT_EQ(paddedBytes.size(), d.texelCount());
    for (std::size_t p = 0; p < d.texelCount(); ++p)
        EXPECT_EQ(int(paddedBytes[p][0]), int(std::lround(std::clamp(paddedRed[p], 0.0f, 255.0f))));
}

// At scale s every display texel, gutter included, is the bilinear
// interpolation of the atlas at its centre; on a periodic plane that is the
// plane's field, computed here from the plane's own coordinates. A field
// linear in x and y (periodic jumps kept away from the tiles checked)
// comes out exactly.
TEST(DisplayAtlas, ScaledTexelsInterpolateTheAtlas) {
    const int n = 4, tiles = 5;
    const Atlas plane = Atlas::periodicPlane(n, tiles, tiles);
    const int side = tiles * n;
    std::vector<float> field(plane.cellCount());
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
            field[plane.cellAt(x, y)] = 3.0f * float(x) + 0.5f * float(y) * float(y);
    for (const int s : {2, 3, 4})
        for (const int g : {1, 2, 5}) {
            SCOPED_TRACE("scale " + std::to_string(s) + ", gutter " + std::to_string(g));
            const DisplayAtlas d(plane, g, s);
            EXPECT_EQ(d.paddedTileSize(), n * s + 2 * g);
            EXPECT_EQ(d.width(), plane.tilesPerRow() * (n * s + 2 * g));
            const std::vector<float> padded = d.pad(field, 1);
            const auto value = [&](int x, int y) { return 3.0 * x + 0.5 * double(y) * double(y); };
            // The middle tile: its gutter's footprint stays off the periodic wrap.
            const int t = (tiles / 2) * tiles + tiles / 2, ox = (tiles / 2) * n, oy = ox;
            double worst = 0;
            for (int v = -g; v < n * s + g; ++v)
                for (int u = -g; u < n * s + g; ++u) {
                    const double x = (u + 0.5) / s - 0.5, y = (v + 0.5) / s - 0.5;
                    const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
                    const double fx = x - x0, fy = y - y0;
                    const double want = (1 - fx) * (1 - fy) * value(ox + x0, oy + y0) +
                                        fx * (1 - fy) * value(ox + x0 + 1, oy + y0) +
                                        (1 - fx) * fy * value(ox + x0, oy + y0 + 1) +
                                        fx * fy * value(ox + x0 + 1, oy + y0 + 1);
                    worst = std::max(worst, std::abs(double(at(d, padded, t, u, v)) - want));
                }
            EXPECT_LT(worst, 1e-3); // float sums of values up to ~50
            // Atlas corners land on display texel corners: the UVs of the
            // tiled mesh sample the same place at any scale.
            const std::array<int, 2> xy = d.texel(t, 0, 0);
            EXPECT_FLOAT_EQ(d.cornerUv(t, 1, 2).x(), float(xy[0] + s) / d.width());
            EXPECT_FLOAT_EQ(d.cornerUv(t, 1, 2).y(), float(xy[1] + 2 * s) / d.height());
            EXPECT_EQ(d.atlasTexel(-1, n * s), (std::array<int, 2>{0, n - 1}));
            EXPECT_EQ(d.atlasTexel(s, 2 * s - 1), (std::array<int, 2>{1, 1}));
        }
    EXPECT_THROW(DisplayAtlas(plane, 2, 0), std::invalid_argument);
}
