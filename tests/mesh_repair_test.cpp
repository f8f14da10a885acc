// Mesh repair (core/mesh/mesh_repair.hpp) on the broken shapes real models
// carry, generated here: duplicate triangles, a fin, a bowtie vertex, a seam
// off by a hair (sin and cos of 2 pi), specks, far-apart parts, a concave
// polygon. Each comes out a manifold that surface tiles are built on.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_repair.hpp"
#include "core/mesh/polygon_triangulation.hpp"
#include "core/surface/tile_builder.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

constexpr double kPi = 3.14159265358979323846;

TriangleMesh tetrahedron(const Eigen::Vector3f& at = Eigen::Vector3f::Zero(), float size = 1) {
    TriangleMesh m;
    m.positions = {at, at + Eigen::Vector3f(size, 0, 0), at + Eigen::Vector3f(0, size, 0),
                   at + Eigen::Vector3f(0, 0, size)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

// The tetrahedron mirrored through its corner at the origin (wound outward).
TriangleMesh mirroredTetrahedron() {
    TriangleMesh m = tetrahedron();
    for (Eigen::Vector3f& p : m.positions)
        p = -p;
    for (auto& t : m.triangles)
        std::swap(t[1], t[2]);
    return m;
}

TriangleMesh joined(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh m = a;
    const std::uint32_t offset = std::uint32_t(a.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles)
        m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return m;
}

// A torus whose seam vertices are computed again at angle 2 pi, as a
// procedural generator writes them: sin(2 pi) is -2.4e-16, not 0, so the
// copies differ from the first column by a hair and exact welding leaves the
// seam open.
TriangleMesh torusWithHairlineSeams(int around, int tube) {
    TriangleMesh m;
    for (int j = 0; j <= tube; ++j)
        for (int i = 0; i <= around; ++i) {
            const double u = 2 * kPi * i / around, v = 2 * kPi * j / tube;
            m.positions.emplace_back(float((1 + 0.4 * std::cos(v)) * std::cos(u)),
                                     float((1 + 0.4 * std::cos(v)) * std::sin(u)),
                                     float(0.4 * std::sin(v)));
        }
    const auto id = [&](int i, int j) { return std::uint32_t(j * (around + 1) + i); };
    for (int j = 0; j < tube; ++j)
        for (int i = 0; i < around; ++i) {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return m;
}

// Repairs as loadMesh does (weld, repair, orient) and checks the result is
// a manifold with area that tiles can be built on.
MeshReport repairedAndTiled(TriangleMesh& m, RepairStats& stats, const RepairOptions& o = {}) {
    weldVertices(m);
    stats = repairMesh(m, o);
    orientConsistently(m);
    const MeshReport r = checkMesh(m);
    EXPECT_TRUE(r.usableForTiles()) << whyNotUsableForTiles(r);
    TileOptions tiles;
    tiles.tileSize = 4;
    tiles.tiles = 60;
    EXPECT_NO_THROW(buildSurfaceTiles(m, tiles, {}, "repaired"));
    return r;
}

} // namespace

TEST(MeshRepair, DuplicateTrianglesAreRemovedAndTheSurfaceClosed) {
    TriangleMesh m = tetrahedron();
    m.triangles.push_back(m.triangles[1]);
    m.triangles.push_back({m.triangles[2][0], m.triangles[2][2], m.triangles[2][1]}); // flipped
    ASSERT_FALSE(checkMesh(m).manifold());
    RepairStats stats;
    const MeshReport r = repairedAndTiled(m, stats);
    EXPECT_EQ(stats.duplicateTriangles, 2u);
    EXPECT_EQ(stats.nonManifoldEdges, 5u);
    EXPECT_EQ(r.triangles, 4u);
    EXPECT_EQ(r.boundaryEdges, 0u); // closed, as before the duplicates
    EXPECT_EQ(stats.splitVertices, 0u);
}

TEST(MeshRepair, AFinIsCutAwayFromTheSurface) {
    // A closed tetrahedron with a third triangle on one of its edges.
    TriangleMesh m = tetrahedron();
    m.positions.emplace_back(0.5f, -1.0f, 0.0f);
    m.triangles.push_back({0, 1, 4});
    ASSERT_EQ(checkMesh(m).nonManifoldEdges.count, 1u);
    RepairStats stats;
    const MeshReport r = repairedAndTiled(m, stats);
    EXPECT_EQ(stats.nonManifoldEdges, 1u);
    EXPECT_GE(stats.splitVertices, 2u); // the edge's two ends, copied for one of the sheets
    EXPECT_EQ(r.triangles, 5u);         // nothing removed
}

TEST(MeshRepair, ABowtieVertexIsSplitIntoOnePerFan) {
    // Two tetrahedra touching at one corner (the teapot's spout on its body).
    TriangleMesh m = joined(tetrahedron(), mirroredTetrahedron());
    weldVertices(m); // (0,0,0) is a corner of both
    ASSERT_EQ(checkMesh(m).nonManifoldVertices.count, 1u);
    RepairStats stats;
    const MeshReport r = repairedAndTiled(m, stats);
    EXPECT_EQ(stats.nonManifoldVertices, 1u);
    EXPECT_EQ(stats.splitVertices, 1u);
    EXPECT_EQ(r.components.size(), 2u);
    EXPECT_EQ(r.boundaryEdges, 0u);
}

TEST(MeshRepair, ASeamOffByAHairIsMerged) {
    TriangleMesh m = torusWithHairlineSeams(24, 12);
    {
        TriangleMesh welded = m;
        weldVertices(welded);
        ASSERT_GT(checkMesh(welded).boundaryEdges, 0u) << "the seam should not weld exactly";
    }
    RepairStats stats;
    const MeshReport r = repairedAndTiled(m, stats);
    EXPECT_GT(stats.mergedVertices, 0u);
    EXPECT_EQ(r.boundaryEdges, 0u);
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_EQ(r.components[0].genus, 1);
    // Off: the seam stays open, as the file has it.
    TriangleMesh off = torusWithHairlineSeams(24, 12);
    weldVertices(off);
    RepairOptions noMerge;
    noMerge.mergeDistance = 0;
    repairMesh(off, noMerge);
    EXPECT_GT(checkMesh(off).boundaryEdges, 0u);
}

TEST(MeshRepair, AGapWiderThanTheMergeDistanceStaysOpen) {
    // One seam's copies moved about 1e-3 of the diagonal away: a real gap, kept.
    TriangleMesh m = torusWithHairlineSeams(24, 12);
    for (std::size_t k = 24; k < m.positions.size(); k += 25)
        m.positions[k].z() += 0.003f;
    weldVertices(m);
    repairMesh(m, {});
    // The other seam (the tube's, at v = 2 pi) merges; this one keeps both
    // its sides open, 12 edges each.
    EXPECT_EQ(checkMesh(m).boundaryEdges, 24u);
}

TEST(MeshRepair, SpecksAreRemovedAndFarApartPartsKept) {
    // A scan's stray triangle and a zero-area sliver far off, beside two
    // real parts 10,000 units apart.
    TriangleMesh m = joined(tetrahedron(), tetrahedron(Eigen::Vector3f(10000, 0, 0)));
    m = joined(m, tetrahedron(Eigen::Vector3f(5, 5, 5), 1e-4f));
    const std::uint32_t n = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), {{3, 3, 3}, {3.5f, 3, 3}, {4, 3, 3}});
    m.triangles.push_back({n, n + 1, n + 2});
    weldVertices(m);
    const RepairStats stats = repairMesh(m, {});
    EXPECT_EQ(stats.specks, 2u);
    EXPECT_EQ(stats.speckTriangles, 5u);
    const MeshReport r = checkMesh(m);
    EXPECT_EQ(r.components.size(), 2u);
    EXPECT_TRUE(r.usableForTiles());
}

TEST(MeshRepair, OffLeavesTheMeshAsItIs) {
    TriangleMesh m = tetrahedron();
    m.triangles.push_back(m.triangles[0]);
    RepairOptions off;
    off.enabled = false;
    const RepairStats stats = repairMesh(m, off);
    EXPECT_FALSE(stats.changed());
    EXPECT_EQ(m.triangles.size(), 5u);
    EXPECT_FALSE(checkMesh(m).manifold());
}

TEST(PolygonTriangulation, AConcavePolygonIsCoveredExactly) {
    // An L of area 3 (a 2 x 2 square less a corner), starting at the reflex
    // corner's neighbour so that a fan from corner 0 would stick out.
    const std::vector<Eigen::Vector3f> l = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0},
                                            {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
    const auto triangles = triangulatePolygon(l);
    ASSERT_EQ(triangles.size(), 4u);
    double area = 0;
    for (const auto& t : triangles) {
        const Eigen::Vector3f n = (l[std::size_t(t[1])] - l[std::size_t(t[0])])
                                      .cross(l[std::size_t(t[2])] - l[std::size_t(t[0])]);
        EXPECT_GT(n.z(), 0) << "a triangle wound against the polygon";
        area += 0.5 * n.norm();
    }
    EXPECT_NEAR(area, 3.0, 1e-6);
    // The fan from corner 0 would cover 1 + 1 + ... more than the L: the
    // check above is one a fan fails.
    double fanArea = 0;
    for (std::size_t k = 1; k + 1 < l.size(); ++k)
        fanArea += 0.5 * (l[k] - l[0]).cross(l[k + 1] - l[0]).norm();
    EXPECT_GT(fanArea, 3.0 + 1e-3);
}

TEST(PolygonTriangulation, AnObjWithAConcaveFaceLoadsAsThatFace) {
    const std::string path = (test::scratchDir("morphogen_mesh_repair_test") / "l.obj").string();
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path) << "v 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nv 0 0 0\nv 2 0 0\nf 1 2 3 4 5 6\n";
    const LoadedMesh loaded = loadMesh(path);
    EXPECT_EQ(loaded.mesh.triangles.size(), 4u);
    EXPECT_NEAR(checkMesh(loaded.mesh).area, 3.0, 1e-5);
}
