// The atlas domain's connectivity: stepping across every kind of tile edge (all rotations, both
// orientations) against independent references (index arithmetic of periodic and Moebius
// grids, 3D positions on a cube, a plane of tiles stored rotated), corner valences, the diagonal
// walk at regular and irregular corners, the CPU index array and GPU map, and broken input.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/domain/atlas.hpp"

using namespace morphogen;

namespace {

constexpr Direction kDirections[4] = {Direction::PlusX, Direction::PlusY, Direction::MinusX,
                                      Direction::MinusY};
constexpr TileEdge kEdges[4] = {TileEdge::PlusX, TileEdge::PlusY, TileEdge::MinusX,
                                TileEdge::MinusY};

Direction dir(int i) {
    return kDirections[((i % 4) + 4) % 4];
}

// The message of the std::invalid_argument that f throws ("" and a failure if none).
std::string invalidArgument(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    ADD_FAILURE() << "no std::invalid_argument thrown";
    return "";
}

// A fan of k tiles around one vertex (corner 0 of every tile), its rim edges open.
Atlas fan(int n, int k) {
    std::vector<std::array<int, 4>> quads;
    for (int t = 0; t < k; ++t)
        quads.push_back({0, 1 + 2 * t, 2 + 2 * t, 1 + (2 * t + 2) % (2 * k)});
    return Atlas::fromQuads(n, quads);
}

// A strip of `tiles` tiles in a row, the last glued to the first (reversed: a Moebius strip).
Atlas strip(int n, int tiles, bool moebius) {
    Atlas atlas(n, tiles, tiles);
    for (int t = 0; t < tiles; ++t)
        atlas.glue(t, TileEdge::PlusX, (t + 1) % tiles, TileEdge::MinusX,
                   moebius && t == tiles - 1);
    return atlas;
}

void expectStepsReturn(const Atlas& atlas, const std::string& name) {
    for (std::uint32_t c = 0; c < atlas.cellCount(); ++c) {
        if (!atlas.used(c))
            continue;
        for (Direction d : kDirections) {
            const AtlasStep s = atlas.step(c, d);
            ASSERT_TRUE(atlas.used(s.cell)) << name << " cell " << c;
            EXPECT_EQ(atlas.neighbours()[c][int(d)], s.cell) << name << " cell " << c;
            if (s.cell == c) {
                // Only an unglued edge stays put (zero flux), and says so.
                EXPECT_EQ(s.back, opposite(d));
                EXPECT_FALSE(s.mirrored);
                continue;
            }
            const AtlasStep r = atlas.step(s.cell, s.back);
            ASSERT_EQ(r.cell, c) << name << " cell " << c << " " << toString(d);
            EXPECT_EQ(r.back, d) << name << " cell " << c << " " << toString(d);
            EXPECT_EQ(r.mirrored, s.mirrored) << name << " cell " << c;
        }
    }
}

// Going straight on from `start` in direction d: the number of steps until it is back at the
// start in the same direction (0 if not within maxSteps).
int straightLoopLength(const Atlas& atlas, std::uint32_t start, Direction d, int maxSteps) {
    std::uint32_t c = start;
    Direction heading = d;
    for (int k = 1; k <= maxSteps; ++k) {
        const AtlasStep s = atlas.step(c, heading);
        c = s.cell;
        heading = opposite(s.back);
        if (c == start && heading == d)
            return k;
    }
    return 0;
}

// The D4 element of an edge gluing: the rotation (proper) or reflection (mirrored) index that
// maps the first tile's directions to the second's.
std::pair<bool, int> gluingKind(TileEdge ea, const AtlasLink& l) {
    const int a = int(ea), b = int(l.edge);
    return {l.reversed, l.reversed ? (a + b + 2) % 4 : (b + 2 - a + 4) % 4};
}

// The two directions that point from a tile's corner texel towards the corner vertex.
std::pair<Direction, Direction> towardsCorner(int corner) {
    switch (corner) {
    case 0:
        return {Direction::MinusX, Direction::MinusY};
    case 1:
        return {Direction::PlusX, Direction::MinusY};
    case 2:
        return {Direction::PlusX, Direction::PlusY};
    default:
        return {Direction::MinusX, Direction::PlusY};
    }
}

bool isCornerStep(const Atlas& atlas, std::uint32_t c, Direction d1, Direction d2) {
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int corner = 0; corner < 4; ++corner) {
            const auto [a, b] = towardsCorner(corner);
            if (atlas.cornerCell(t, corner) == c && ((a == d1 && b == d2) || (a == d2 && b == d1)))
                return true;
        }
    return false;
}

} // namespace

TEST(Atlas, LayoutOfTilesInTheTexture) {
    const Atlas atlas(4, 5); // 3 tiles per row, 2 rows, one slot unused
    EXPECT_EQ(atlas.tilesPerRow(), 3);
    EXPECT_EQ(atlas.width(), 12);
    EXPECT_EQ(atlas.height(), 8);
    EXPECT_EQ(atlas.cellCount(), 96u);
    EXPECT_EQ(atlas.tileOf(atlas.cellAt(5, 2)), 1);
    EXPECT_EQ(atlas.tileOf(atlas.cellAt(3, 7)), 3);
    EXPECT_EQ(atlas.tileOf(atlas.cellAt(8, 4)), -1);
    EXPECT_FALSE(atlas.used(atlas.cellAt(11, 7)));
    EXPECT_EQ(atlas.tileCell(4, 1, 2), atlas.cellAt(5, 6));
    EXPECT_EQ(atlas.cornerCell(1, 0), atlas.cellAt(4, 0));
    EXPECT_EQ(atlas.cornerCell(1, 1), atlas.cellAt(7, 0));
    EXPECT_EQ(atlas.cornerCell(1, 2), atlas.cellAt(7, 3));
    EXPECT_EQ(atlas.cornerCell(1, 3), atlas.cellAt(4, 3));
    EXPECT_EQ(Atlas(3, 4).tilesPerRow(), 2);
    EXPECT_EQ(Atlas(3, 10, 7).width(), 21);
    EXPECT_EQ(Atlas(3, 10, 7).height(), 6);
}

TEST(Atlas, EveryStepLeadsBack) {
    expectStepsReturn(Atlas::cube(2), "cube(2)");
    expectStepsReturn(Atlas::cube(5), "cube(5)");
    expectStepsReturn(Atlas::rotatedTiles(2), "rotatedTiles(2)");
    expectStepsReturn(Atlas::rotatedTiles(4), "rotatedTiles(4)");
    expectStepsReturn(Atlas::periodicPlane(3, 2, 3), "periodicPlane(3, 2, 3)");
    expectStepsReturn(Atlas::periodicPlane(2, 1, 1), "periodicPlane(2, 1, 1)");
    expectStepsReturn(strip(3, 3, true), "Moebius strip");
    expectStepsReturn(fan(3, 5), "fan of 5");
}

TEST(Atlas, ArrivalDirectionPointsBackAcrossTheEdgeCrossed) {
    // Crossing edge ea into tile b through eb: `back` is eb, the arrival texel lies on eb, and
    // `mirrored` is the gluing's orientation.
    for (const Atlas& atlas : {Atlas::cube(3), Atlas::rotatedTiles(3)}) {
        const int n = atlas.tileSize();
        for (int t = 0; t < atlas.tileCount(); ++t)
            for (TileEdge e : kEdges) {
                const AtlasLink& l = atlas.link(t, e);
                ASSERT_TRUE(l.glued);
                for (int i = 0; i < n; ++i) {
                    const AtlasStep s = atlas.step(atlas.edgeCell(t, e, i), dir(int(e)));
                    EXPECT_EQ(int(s.back), int(l.edge));
                    EXPECT_EQ(s.mirrored, l.reversed);
                    EXPECT_EQ(s.cell, atlas.edgeCell(l.tile, l.edge, l.reversed ? i : n - 1 - i));
                    EXPECT_EQ(atlas.tileOf(s.cell), l.tile);
                }
            }
    }
}

TEST(Atlas, StraightLinesCloseAroundTheCubeAndThePlane) {
    for (int n : {2, 3, 5}) {
        const Atlas cube = Atlas::cube(n);
        for (std::uint32_t c = 0; c < cube.cellCount(); ++c)
            for (Direction d : kDirections) {
                // Every straight line on a cube is a belt of four faces.
                EXPECT_EQ(straightLoopLength(cube, c, d, 8 * n), 4 * n) << "n " << n << " " << c;
                EXPECT_EQ(cube.walk(c, std::vector<Direction>(std::size_t(4 * n), d)), c);
                EXPECT_NE(cube.walk(c, std::vector<Direction>(std::size_t(2 * n), d)), c);
            }
    }
    const Atlas plane = Atlas::periodicPlane(3, 4, 2);
    for (std::uint32_t c = 0; c < plane.cellCount(); ++c) {
        EXPECT_EQ(straightLoopLength(plane, c, Direction::PlusX, 100), 12);
        EXPECT_EQ(straightLoopLength(plane, c, Direction::MinusY, 100), 6);
    }
    const Atlas torus = Atlas::rotatedTiles(3);
    for (std::uint32_t c = 0; c < torus.cellCount(); ++c)
        for (Direction d : kDirections)
            EXPECT_EQ(straightLoopLength(torus, c, d, 100), 9);
}

TEST(Atlas, PeriodicPlaneHasTheNeighboursOfAPeriodicGrid) {
    for (auto [n, tx, ty] : {std::array<int, 3>{3, 2, 3}, {4, 1, 1}, {2, 3, 1}, {5, 2, 2}}) {
        const Atlas atlas = Atlas::periodicPlane(n, tx, ty);
        const int w = n * tx, h = n * ty;
        ASSERT_EQ(atlas.width(), w);
        ASSERT_EQ(atlas.height(), h);
        atlas.validate(true);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const auto& nb = atlas.neighbours()[std::size_t(y * w + x)];
                EXPECT_EQ(nb[0], std::uint32_t(y * w + (x + 1) % w));
                EXPECT_EQ(nb[1], std::uint32_t(((y + 1) % h) * w + x));
                EXPECT_EQ(nb[2], std::uint32_t(y * w + (x + w - 1) % w));
                EXPECT_EQ(nb[3], std::uint32_t(((y + h - 1) % h) * w + x));
            }
        for (int t = 0; t < atlas.tileCount(); ++t)
            for (int corner = 0; corner < 4; ++corner)
                EXPECT_EQ(atlas.cornerValence(t, corner), 4);
    }
}

TEST(Atlas, MoebiusStripAndCylinderMatchIndexArithmetic) {
    const int n = 3, tiles = 3, w = n * tiles;
    for (bool moebius : {false, true}) {
        const Atlas atlas = strip(n, tiles, moebius);
        atlas.validate(false);
        EXPECT_THROW(atlas.validate(true), std::invalid_argument);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < w; ++x) {
                const auto& nb = atlas.neighbours()[std::size_t(y * w + x)];
                // Across the seam x = w-1 | 0 the strip flips y when it is a Moebius strip.
                const int ys = moebius ? n - 1 - y : y;
                EXPECT_EQ(nb[0], std::uint32_t(x == w - 1 ? ys * w : y * w + x + 1));
                EXPECT_EQ(nb[2], std::uint32_t(x == 0 ? ys * w + w - 1 : y * w + x - 1));
                // The long edges are open: zero flux.
                EXPECT_EQ(nb[1], std::uint32_t(y == n - 1 ? y * w + x : (y + 1) * w + x));
                EXPECT_EQ(nb[3], std::uint32_t(y == 0 ? y * w + x : (y - 1) * w + x));
            }
        // Going round once comes back mirrored on a Moebius strip: twice to close the loop.
        const std::uint32_t start = atlas.cellAt(1, 0);
        EXPECT_EQ(straightLoopLength(atlas, start, Direction::PlusX, 100), moebius ? 2 * w : w);
        const AtlasStep seam = atlas.step(atlas.cellAt(w - 1, 0), Direction::PlusX);
        EXPECT_EQ(seam.mirrored, moebius);
        // The walk carries the flipped frame on across later (plain) edges: once round, the
        // start's +y points down the stored tiles; twice round, up again.
        std::vector<Direction> once(std::size_t(w + 1), Direction::PlusX);
        once.back() = Direction::PlusY;
        EXPECT_EQ(atlas.walk(start, once), atlas.cellAt(1, moebius ? n - 2 : 1));
        std::vector<Direction> twice(std::size_t(2 * w + 1), Direction::PlusX);
        twice.back() = Direction::PlusY;
        EXPECT_EQ(atlas.walk(start, twice), atlas.cellAt(1, 1));
    }
}

TEST(Atlas, CubeNeighboursAreNearestOnTheCubeIn3D) {
    // Independent of the gluing rules: place every texel on the cube's surface from the face
    // corners documented in atlas.hpp; a neighbour on the same face is 1 texel away, one across
    // a cube edge sqrt(1/2) (texel centres half a texel from the edge on both faces).
    const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                             {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    for (int n : {2, 3, 6}) {
        const Atlas cube = Atlas::cube(n);
        const auto vertex = [n](int v, int axis) { return double(n * ((v >> axis) & 1)); };
        const auto position = [&](std::uint32_t cell) {
            const int t = cube.tileOf(cell);
            const int x = int(cell % std::uint32_t(cube.width())) % n;
            const int y = int(cell / std::uint32_t(cube.width())) % n;
            std::array<double, 3> p{};
            for (int a = 0; a < 3; ++a) {
                const double c0 = vertex(faces[t][0], a), c1 = vertex(faces[t][1], a);
                const double c3 = vertex(faces[t][3], a);
                p[a] = c0 + (x + 0.5) / n * (c1 - c0) + (y + 0.5) / n * (c3 - c0);
            }
            return p;
        };
        for (std::uint32_t c = 0; c < cube.cellCount(); ++c)
            for (Direction d : kDirections) {
                const std::uint32_t nb = cube.neighbours()[c][int(d)];
                const auto p = position(c), q = position(nb);
                const double dist =
                    std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                              (p[2] - q[2]) * (p[2] - q[2]));
                const double expected = cube.tileOf(c) == cube.tileOf(nb) ? 1.0 : std::sqrt(0.5);
                EXPECT_NEAR(dist, expected, 1e-12) << "n " << n << " cell " << c;
                // And the step leaves the face in direction d: the neighbour is ahead, along
                // the face's own axis for d.
                const int t = cube.tileOf(c);
                const int axisCorner = int(d) % 2 == 0 ? 1 : 3;
                const double sign = int(d) < 2 ? 1.0 : -1.0;
                double along = 0;
                for (int a = 0; a < 3; ++a)
                    along += (q[a] - p[a]) *
                             (vertex(faces[t][axisCorner], a) - vertex(faces[t][0], a)) / n;
                EXPECT_GT(along * sign, 0.49) << "n " << n << " cell " << c;
            }
    }
}

TEST(Atlas, CubeIsClosedOrientableWithEightCornersOfValenceThree) {
    const Atlas cube = Atlas::cube(4);
    EXPECT_EQ(cube.tileCount(), 6);
    cube.validate(true);
    std::set<std::pair<std::pair<int, int>, std::pair<int, int>>> gluings;
    double vertices = 0;
    for (int t = 0; t < 6; ++t) {
        for (TileEdge e : kEdges) {
            const AtlasLink& l = cube.link(t, e);
            ASSERT_TRUE(l.glued) << "tile " << t << " edge " << toString(e);
            EXPECT_FALSE(l.reversed);
            EXPECT_NE(l.tile, t);
            const AtlasLink& back = cube.link(l.tile, l.edge);
            EXPECT_TRUE(back.glued && back.tile == t && back.edge == e);
            const std::pair<int, int> here{t, int(e)}, there{l.tile, int(l.edge)};
            gluings.insert({std::min(here, there), std::max(here, there)});
        }
        for (int corner = 0; corner < 4; ++corner) {
            EXPECT_EQ(cube.cornerValence(t, corner), 3);
            vertices += 1.0 / cube.cornerValence(t, corner);
        }
    }
    EXPECT_EQ(gluings.size(), 12u); // every cube edge glued exactly once
    EXPECT_NEAR(vertices, 8.0, 1e-12);
}

TEST(Atlas, RotatedTilesCoverEveryRotationInBothOrientations) {
    const Atlas atlas = Atlas::rotatedTiles(3);
    atlas.validate(true);
    std::set<std::pair<bool, int>> kinds;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        for (TileEdge e : kEdges) {
            const AtlasLink& l = atlas.link(t, e);
            ASSERT_TRUE(l.glued);
            kinds.insert(gluingKind(e, l));
        }
        for (int corner = 0; corner < 4; ++corner)
            EXPECT_EQ(atlas.cornerValence(t, corner), 4);
    }
    EXPECT_EQ(kinds.size(), 8u);
    for (bool mirrored : {false, true})
        for (int k = 0; k < 4; ++k)
            EXPECT_EQ(kinds.count({mirrored, k}), 1u) << "mirrored " << mirrored << " k " << k;
}

TEST(Atlas, RotatedTilesAreAPeriodicPlaneStoredTurned) {
    // Reference, written here from the rule documented in atlas.hpp: tile t = (tx, ty) of a
    // 3 x 3 plane stored mirrored (u -> n-1-u) when e >= 4, then turned (e mod 4) quarter
    // turns counter-clockwise, e = t for tiles 0..7 and 2 for tile 8.
    const auto element = [](int t) { return t == 8 ? 2 : t; };
    for (int n : {2, 3, 4}) {
        const Atlas atlas = Atlas::rotatedTiles(n);
        const int side = 3 * n;
        const auto toPlane = [&](std::uint32_t cell) {
            const int t = atlas.tileOf(cell), e = element(t);
            int u = int(cell % std::uint32_t(atlas.width())) % n;
            int v = int(cell / std::uint32_t(atlas.width())) % n;
            if (e >= 4)
                u = n - 1 - u;
            for (int k = 0; k < e % 4; ++k) {
                const int nu = n - 1 - v;
                v = u;
                u = nu;
            }
            return std::pair<int, int>{(t % 3) * n + u, (t / 3) * n + v};
        };
        // Each stored direction, seen on the plane.
        const auto planeDirection = [&element](int t, int d) {
            const int e = element(t);
            const int mirrored = e >= 4 ? (6 - d) % 4 : d;
            return (mirrored + e % 4) % 4;
        };
        const auto planeStep = [side](std::pair<int, int> p, int d) {
            const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
            return std::pair<int, int>{(p.first + dx[d] + side) % side,
                                       (p.second + dy[d] + side) % side};
        };
        const std::vector<std::uint32_t> planeCells = Atlas::rotatedTilesPlaneCells(n);
        ASSERT_EQ(planeCells.size(), atlas.cellCount());
        std::set<std::uint32_t> covered;
        for (std::uint32_t c = 0; c < atlas.cellCount(); ++c) {
            const auto p = toPlane(c);
            EXPECT_EQ(planeCells[c], std::uint32_t(p.second * side + p.first));
            covered.insert(planeCells[c]);
            const int t = atlas.tileOf(c);
            for (int d = 0; d < 4; ++d)
                EXPECT_EQ(toPlane(atlas.neighbours()[c][std::size_t(d)]),
                          planeStep(p, planeDirection(t, d)))
                    << "n " << n << " tile " << t << " cell " << c << " " << toString(dir(d));
            // Diagonals through the carried frame are the plane's diagonals, in both orders.
            for (int d = 0; d < 4; ++d) {
                const auto diagonal =
                    planeStep(planeStep(p, planeDirection(t, d)), planeDirection(t, d + 1));
                EXPECT_EQ(toPlane(atlas.walk(c, {dir(d), dir(d + 1)})), diagonal);
                EXPECT_EQ(toPlane(atlas.walk(c, {dir(d + 1), dir(d)})), diagonal);
            }
        }
        EXPECT_EQ(covered.size(), std::size_t(side * side));

        // Long walks across many edges of every kind carry the frame like the plane does.
        std::uint32_t seed = 12345;
        for (std::uint32_t c = 0; c < atlas.cellCount(); c += 5) {
            std::vector<Direction> path;
            auto p = toPlane(c);
            for (int k = 0; k < 8 * n; ++k) {
                seed = seed * 1664525u + 1013904223u;
                const int d = int(seed >> 30);
                path.push_back(dir(d));
                p = planeStep(p, planeDirection(atlas.tileOf(c), d));
            }
            EXPECT_EQ(toPlane(atlas.walk(c, path)), p) << "n " << n << " cell " << c;
        }
    }
}

TEST(Atlas, DiagonalWalksCommuteExceptTowardsAnIrregularCorner) {
    for (const Atlas& atlas : {Atlas::cube(2), Atlas::cube(4), Atlas::periodicPlane(3, 2, 2)}) {
        const bool cube = atlas.tileCount() == 6;
        for (std::uint32_t c = 0; c < atlas.cellCount(); ++c)
            for (int d = 0; d < 4; ++d) {
                const Direction a = dir(d), b = dir(d + 1);
                const std::uint32_t ab = atlas.walk(c, {a, b}), ba = atlas.walk(c, {b, a});
                if (cube && isCornerStep(atlas, c, a, b))
                    EXPECT_NE(ab, ba) << "cell " << c;
                else
                    EXPECT_EQ(ab, ba) << "cell " << c << " " << toString(a) << toString(b);
            }
    }
}

TEST(Atlas, DiagonalAtAValenceThreeCornerReachesTheDirectNeighbours) {
    const Atlas cube = Atlas::cube(3);
    for (int t = 0; t < 6; ++t)
        for (int corner = 0; corner < 4; ++corner) {
            const std::uint32_t c = cube.cornerCell(t, corner);
            const auto [x, y] = towardsCorner(corner);
            const std::uint32_t nx = cube.step(c, x).cell, ny = cube.step(c, y).cell;
            // x-then-y reaches the third tile's corner texel: the direct y neighbour; and the
            // other way round.
            EXPECT_EQ(cube.walk(c, {x, y}), ny);
            EXPECT_EQ(cube.walk(c, {y, x}), nx);
            EXPECT_NE(nx, ny);
            EXPECT_NE(cube.tileOf(nx), cube.tileOf(ny));
        }
}

TEST(Atlas, DiagonalAtAValenceFiveCornerReachesTheTwoFarCornerTexels) {
    const int n = 3;
    const Atlas atlas = fan(n, 5);
    atlas.validate(false);
    std::set<std::uint32_t> centre;
    for (int t = 0; t < 5; ++t) {
        EXPECT_EQ(atlas.cornerValence(t, 0), 5);
        EXPECT_EQ(atlas.cornerValence(t, 1), 2);
        EXPECT_EQ(atlas.cornerValence(t, 2), 1);
        EXPECT_EQ(atlas.cornerValence(t, 3), 2);
        centre.insert(atlas.cornerCell(t, 0));
    }
    for (int t = 0; t < 5; ++t) {
        const std::uint32_t c = atlas.cornerCell(t, 0);
        const auto [x, y] = towardsCorner(0);
        const std::uint32_t nx = atlas.step(c, x).cell, ny = atlas.step(c, y).cell;
        const std::uint32_t xy = atlas.walk(c, {x, y}), yx = atlas.walk(c, {y, x});
        // Both are corner texels at the centre vertex, distinct, and not c or its neighbours.
        EXPECT_TRUE(centre.count(xy) && centre.count(yx));
        EXPECT_EQ((std::set<std::uint32_t>{c, nx, ny, xy, yx}).size(), 5u);
        // x-then-y goes on from the x neighbour's tile (p is next to b), y-then-x from y's.
        EXPECT_TRUE(atlas.step(nx, Direction::MinusX).cell == xy ||
                    atlas.step(nx, Direction::MinusY).cell == xy);
        EXPECT_TRUE(atlas.step(ny, Direction::MinusX).cell == yx ||
                    atlas.step(ny, Direction::MinusY).cell == yx);
    }
    // Away from the centre the fan is an ordinary surface with a boundary.
    EXPECT_EQ(Atlas(3, 1).cornerValence(0, 2), 1);
}

TEST(Atlas, IndexArrayConnectivityMapAndBorderCellsAgree) {
    for (const Atlas& atlas : {fan(4, 5), Atlas::cube(3), Atlas::rotatedTiles(2), Atlas(5, 3)}) {
        const std::vector<std::uint32_t> map = atlas.connectivityMap();
        ASSERT_EQ(map.size(), atlas.cellCount() * 4);
        const auto w = std::uint32_t(atlas.width());
        std::vector<std::uint32_t> complement;
        for (std::uint32_t c = 0; c < atlas.cellCount(); ++c) {
            const auto& nb = atlas.neighbours()[c];
            for (int d = 0; d < 4; ++d) {
                const std::uint32_t packed = map[std::size_t(c) * 4 + std::size_t(d)];
                EXPECT_EQ((packed >> 16) * w + (packed & 0xFFFFu), nb[std::size_t(d)]);
            }
            if (!atlas.used(c)) {
                EXPECT_EQ(atlas.tileOf(c), -1);
                for (std::uint32_t x : nb)
                    EXPECT_EQ(x, c); // unused cells point at themselves
                EXPECT_FALSE(atlas.interior(c));
                continue;
            }
            if (atlas.interior(c)) {
                EXPECT_EQ(nb[0], c + 1);
                EXPECT_EQ(nb[1], c + w);
                EXPECT_EQ(nb[2], c - 1);
                EXPECT_EQ(nb[3], c - w);
            } else {
                complement.push_back(c);
            }
        }
        EXPECT_EQ(atlas.borderCells(), complement);
        const int n = atlas.tileSize();
        EXPECT_EQ(complement.size(), std::size_t(atlas.tileCount() * (4 * n - 4)));
    }
}

TEST(Atlas, UngluedEdgesAreZeroFlux) {
    const Atlas lone(3, 1);
    lone.validate(false);
    for (TileEdge e : kEdges)
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t c = lone.edgeCell(0, e, i);
            const AtlasStep s = lone.step(c, dir(int(e)));
            EXPECT_EQ(s.cell, c);
            EXPECT_EQ(s.back, opposite(dir(int(e))));
            EXPECT_FALSE(s.mirrored);
        }
    const std::string message = invalidArgument([&] { lone.validate(true); });
    EXPECT_NE(message.find("tile 0 edge +x"), std::string::npos) << message;
}

TEST(Atlas, BrokenInputIsRefusedByName) {
    Atlas atlas(4, 3);
    atlas.glue(0, TileEdge::PlusX, 1, TileEdge::MinusY);
    std::string m = invalidArgument([&] { atlas.glue(2, TileEdge::MinusX, 1, TileEdge::MinusY); });
    EXPECT_NE(m.find("tile 1 edge -y is already glued"), std::string::npos) << m;
    EXPECT_NE(m.find("tile 0 edge +x"), std::string::npos) << m;
    m = invalidArgument([&] { atlas.glue(0, TileEdge::PlusX, 2, TileEdge::PlusY); });
    EXPECT_NE(m.find("tile 0 edge +x is already glued"), std::string::npos) << m;
    m = invalidArgument([&] { atlas.glue(2, TileEdge::PlusY, 2, TileEdge::PlusY); });
    EXPECT_NE(m.find("tile 2 edge +y"), std::string::npos) << m;
    m = invalidArgument([&] { atlas.glue(1, TileEdge::PlusY, 3, TileEdge::PlusY); });
    EXPECT_NE(m.find("tile 3 is out of range (0..2)"), std::string::npos) << m;
    m = invalidArgument([&] { atlas.glue(-1, TileEdge::PlusY, 2, TileEdge::PlusY); });
    EXPECT_NE(m.find("tile -1"), std::string::npos) << m;
    m = invalidArgument([&] { (void)atlas.link(7, TileEdge::PlusX); });
    EXPECT_NE(m.find("tile 7"), std::string::npos) << m;
    m = invalidArgument([&] { (void)atlas.cornerValence(0, 4); });
    EXPECT_NE(m.find("corner 4"), std::string::npos) << m;
    // A failed glue leaves the atlas as it was.
    EXPECT_FALSE(atlas.link(2, TileEdge::MinusX).glued);
    EXPECT_FALSE(atlas.link(2, TileEdge::PlusY).glued);
    atlas.validate(false);
    m = invalidArgument([&] { atlas.validate(true); });
    EXPECT_NE(m.find("tile 0 edge +y is not glued"), std::string::npos) << m;

    m = invalidArgument([] { Atlas(1, 4); });
    EXPECT_NE(m.find("tile size 1"), std::string::npos) << m;
    m = invalidArgument([] { Atlas(4, 0); });
    EXPECT_NE(m.find("tile count 0"), std::string::npos) << m;
    m = invalidArgument([] { Atlas(4, 4, -2); });
    EXPECT_NE(m.find("tiles per row -2"), std::string::npos) << m;
    // 16-bit addresses: 65536 texels on a side is one too many, 65535 still fits.
    m = invalidArgument([] { Atlas(4096, 17 * 17); });
    EXPECT_NE(m.find("69632 x 69632"), std::string::npos) << m;
    m = invalidArgument([] { Atlas(2, 32768, 32768); });
    EXPECT_NE(m.find("65536 x 2"), std::string::npos) << m;
    m = invalidArgument([] { Atlas(65536, 1); });
    EXPECT_NE(m.find("16-bit"), std::string::npos) << m;
    EXPECT_EQ(Atlas(5, 13107, 13107).width(), 65535);
    m = invalidArgument([] { Atlas::periodicPlane(4, 0, 2); });
    EXPECT_NE(m.find("0 x 2"), std::string::npos) << m;

    // Quads: an edge in three quads is not a surface; a quad edge from a vertex to itself.
    m = invalidArgument([] {
        Atlas::fromQuads(3, {{{0, 1, 2, 3}}, {{1, 0, 4, 5}}, {{0, 1, 6, 7}}});
    });
    EXPECT_NE(m.find("more than two quads"), std::string::npos) << m;
    m = invalidArgument([] { Atlas::fromQuads(3, {{{0, 1, 1, 3}}}); });
    EXPECT_NE(m.find("tile 0 edge +x"), std::string::npos) << m;
}

TEST(Atlas, FromQuadsGluesSharedEdgesByTheirSense) {
    // Two quads sharing the edge 1-2: listed in opposite senses (proper), then in the same
    // sense (the second quad stored mirrored: a reversed gluing).
    const Atlas proper = Atlas::fromQuads(3, {{{0, 1, 2, 3}}, {{1, 4, 5, 2}}});
    const AtlasLink& l = proper.link(0, TileEdge::PlusX);
    EXPECT_TRUE(l.glued);
    EXPECT_EQ(l.tile, 1);
    EXPECT_EQ(l.edge, TileEdge::MinusX);
    EXPECT_FALSE(l.reversed);
    EXPECT_EQ(proper.step(proper.tileCell(0, 2, 0), Direction::PlusX).cell,
              proper.tileCell(1, 0, 0));
    const Atlas mirrored = Atlas::fromQuads(3, {{{0, 1, 2, 3}}, {{1, 2, 5, 4}}});
    const AtlasLink& r = mirrored.link(0, TileEdge::PlusX);
    EXPECT_TRUE(r.glued);
    EXPECT_EQ(r.edge, TileEdge::MinusY);
    EXPECT_TRUE(r.reversed);
    // Texel (2, 0) of tile 0 touches vertex 1, which is tile 1's corner 0: texel (0, 0).
    const AtlasStep s = mirrored.step(mirrored.tileCell(0, 2, 0), Direction::PlusX);
    EXPECT_EQ(s.cell, mirrored.tileCell(1, 0, 0));
    EXPECT_TRUE(s.mirrored);
    EXPECT_EQ(s.back, Direction::MinusY);
}
