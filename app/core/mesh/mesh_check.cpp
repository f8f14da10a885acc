#include "core/mesh/mesh_check.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <unordered_map>

#include "core/base/errors.hpp"
#include "core/mesh/edge_table.hpp"

namespace morphogen {

namespace {

void note(MeshDefect& d, const Eigen::Vector3f& at) {
    if (d.count++ == 0)
        d.first = at;
}

int cornerOf(const std::array<std::uint32_t, 3>& tri, std::uint32_t v) {
    return tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
}

// Fans: corners of a vertex joined across the manifold edges around it. A
// manifold vertex has one; so does a boundary vertex (its fan is open).
std::vector<std::uint32_t> fanCounts(const TriangleMesh& mesh, const EdgeTable& edges) {
    UnionFind corners(3 * mesh.triangles.size());
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        if (edges.useCount(e) != 2)
            continue;
        const EdgeTable::Use& a = *edges.begin(e);
        const EdgeTable::Use& b = *(edges.begin(e) + 1);
        const auto& ta = mesh.triangles[a.triangle];
        const auto& tb = mesh.triangles[b.triangle];
        for (std::uint32_t v : {edges.lowVertex(e), edges.highVertex(e)})
            corners.unite(3 * a.triangle + cornerOf(ta, v), 3 * b.triangle + cornerOf(tb, v));
    }
    // Each root is one fan of the vertex at that corner.
    std::vector<std::uint32_t> fans(mesh.positions.size(), 0);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t corner = std::uint32_t(3 * t + c);
            if (corners.find(corner) == corner)
                ++fans[mesh.triangles[t][c]];
        }
    return fans;
}

// Boundary vertices with another boundary vertex within `tolerance`, found
// through a hash grid of cells `tolerance` wide (neighbouring cells included).
void findNearSeams(const TriangleMesh& mesh, const std::vector<std::uint8_t>& onBoundary,
                   float tolerance, MeshDefect& out) {
    if (!(tolerance > 0))
        return;
    auto cellOf = [&](const Eigen::Vector3f& p) {
        return (p / tolerance).array().floor().cast<std::int64_t>().eval();
    };
    auto keyOf = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        return std::uint64_t(x) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(y) * 0xC2B2AE3D27D4EB4Full ^
               std::uint64_t(z) * 0x165667B19E3779F9ull;
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    for (std::uint32_t v = 0; v < onBoundary.size(); ++v)
        if (onBoundary[v]) {
            const auto c = cellOf(mesh.positions[v]);
            grid[keyOf(c.x(), c.y(), c.z())].push_back(v);
        }
    for (std::uint32_t v = 0; v < onBoundary.size(); ++v) {
        if (!onBoundary[v])
            continue;
        const Eigen::Vector3f& p = mesh.positions[v];
        const auto c = cellOf(p);
        bool near = false;
        for (int dz = -1; dz <= 1 && !near; ++dz)
            for (int dy = -1; dy <= 1 && !near; ++dy)
                for (int dx = -1; dx <= 1 && !near; ++dx) {
                    const auto it = grid.find(keyOf(c.x() + dx, c.y() + dy, c.z() + dz));
                    if (it == grid.end())
                        continue;
                    for (std::uint32_t w : it->second)
                        if (w != v && (mesh.positions[w] - p).norm() <= tolerance) {
                            near = true;
                            break;
                        }
                }
        if (near)
            note(out, p);
    }
}

std::string point(const Eigen::Vector3f& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
    return text;
}

} // namespace

MeshReport checkMesh(const TriangleMesh& mesh) {
    MeshReport r;
    const std::size_t nv = mesh.positions.size();
    const std::size_t nt = mesh.triangles.size();
    r.vertices = nv;
    r.triangles = nt;
    r.bounds = boundsOf(mesh.positions);

    const EdgeTable edges(mesh);
    r.edges = edges.edgeCount();

    // Components through shared vertices, numbered in vertex order.
    UnionFind joined(nv);
    for (const auto& tri : mesh.triangles) {
        joined.unite(tri[0], tri[1]);
        joined.unite(tri[1], tri[2]);
    }
    std::vector<std::uint32_t> componentOf(nv, ~0u);
    {
        std::vector<std::uint32_t> idOfRoot(nv, ~0u);
        std::vector<std::uint8_t> used(nv, 0);
        for (const auto& tri : mesh.triangles)
            for (std::uint32_t v : tri)
                used[v] = 1;
        for (std::uint32_t v = 0; v < nv; ++v) {
            if (!used[v])
                continue;
            const std::uint32_t root = joined.find(v);
            if (idOfRoot[root] == ~0u) {
                idOfRoot[root] = std::uint32_t(r.components.size());
                r.components.emplace_back();
                r.components.back().bounds.min = r.components.back().bounds.max = mesh.positions[v];
            }
            componentOf[v] = idOfRoot[root];
            MeshComponent& c = r.components[componentOf[v]];
            ++c.vertices;
            c.bounds.min = c.bounds.min.cwiseMin(mesh.positions[v]);
            c.bounds.max = c.bounds.max.cwiseMax(mesh.positions[v]);
        }
    }

    // Edges: boundary, non-manifold; boundary loops through the boundary edges.
    UnionFind loops(nv);
    std::vector<std::uint8_t> onBoundary(nv, 0), onNonManifoldEdge(nv, 0);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        const std::uint32_t a = edges.lowVertex(e), b = edges.highVertex(e);
        MeshComponent& c = r.components[componentOf[a]];
        ++c.edges;
        const Eigen::Vector3f mid = 0.5f * (mesh.positions[a] + mesh.positions[b]);
        if (edges.useCount(e) == 1) {
            ++r.boundaryEdges;
            onBoundary[a] = onBoundary[b] = 1;
            loops.unite(a, b);
        } else if (edges.useCount(e) > 2) {
            note(r.nonManifoldEdges, mid);
            onNonManifoldEdge[a] = onNonManifoldEdge[b] = 1;
            c.manifold = false;
        }
    }
    for (std::uint32_t v = 0; v < nv; ++v)
        if (onBoundary[v] && loops.find(v) == v) {
            ++r.boundaryLoops;
            ++r.components[componentOf[v]].boundaryLoops;
        }

    const std::vector<std::uint32_t> fans = fanCounts(mesh, edges);
    for (std::uint32_t v = 0; v < nv; ++v)
        if (fans[v] > 1 && !onNonManifoldEdge[v]) {
            note(r.nonManifoldVertices, mesh.positions[v]);
            r.components[componentOf[v]].manifold = false;
        }

    // Triangles: area, zero area, duplicates, winding.
    const PieceOrientation orientation = orientPieces(mesh, edges);
    for (std::size_t t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        MeshComponent& c = r.components[componentOf[tri[0]]];
        ++c.triangles;
        const Eigen::Vector3f centroid =
            (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0f;
        const double twiceArea = doubleAreaVector(mesh, t).norm();
        c.area += 0.5 * twiceArea;
        double longest = 0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, (mesh.positions[tri[(k + 1) % 3]].cast<double>() -
                                         mesh.positions[tri[k]].cast<double>())
                                            .squaredNorm());
        // height = twiceArea / longestEdge <= 1e-6 longestEdge
        if (twiceArea <= 1e-6 * longest)
            note(r.zeroAreaTriangles, centroid);
        if (orientation.flip[t])
            note(r.inconsistentWinding, centroid);
        if (!orientation.orientable[orientation.piece[t]])
            c.orientable = false;
    }
    {
        std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> sorted(nt);
        for (std::size_t t = 0; t < nt; ++t) {
            sorted[t] = {mesh.triangles[t], std::uint32_t(t)};
            std::sort(sorted[t].first.begin(), sorted[t].first.end());
        }
        std::sort(sorted.begin(), sorted.end());
        for (std::size_t i = 1; i < nt; ++i)
            if (sorted[i].first == sorted[i - 1].first) {
                const auto& tri = mesh.triangles[sorted[i].second];
                note(r.duplicateTriangles,
                     (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) /
                         3.0f);
            }
    }
    findNearSeams(mesh, onBoundary, 1e-5f * r.bounds.diagonal(), r.nearSeamVertices);

    for (MeshComponent& c : r.components) {
        c.eulerCharacteristic = long(c.vertices) - long(c.edges) + long(c.triangles);
        const long twiceGenus = 2 - long(c.boundaryLoops) - c.eulerCharacteristic;
        if (c.manifold && c.orientable && twiceGenus >= 0 && twiceGenus % 2 == 0)
            c.genus = int(twiceGenus / 2);
        r.area += c.area;
    }
    return r;
}

void requireManifold(const MeshReport& report, const std::string& source) {
    if (report.manifold())
        return;
    std::string what;
    if (report.nonManifoldEdges.count > 0)
        what += std::to_string(report.nonManifoldEdges.count) +
                " edge(s) shared by more than two triangles (the first at " +
                point(report.nonManifoldEdges.first) + ")";
    if (report.nonManifoldVertices.count > 0) {
        if (!what.empty())
            what += " and ";
        what += std::to_string(report.nonManifoldVertices.count) +
                " vertex(es) where separate fans of triangles meet (the first at " +
                point(report.nonManifoldVertices.first) + ")";
    }
    throw InputError(source + ": not a manifold surface: " + what +
                     "; surface tiles need every edge on at most two triangles and every "
                     "vertex on one fan (a mesh editor's \"select non-manifold\" finds them)");
}

std::string whyNotUsableForTiles(const MeshReport& report) {
    if (!report.manifold())
        return "not a manifold surface";
    if (!report.hasArea())
        return "the surface has no area: " +
               std::string(report.triangles == 0 ? "it has no triangles"
                                                 : "every triangle is zero-area (its corners on "
                                                   "a line or a point)");
    return "";
}

void requireUsableForTiles(const MeshReport& report, const std::string& source) {
    requireManifold(report, source);
    if (!report.hasArea())
        throw InputError(source + ": " + whyNotUsableForTiles(report) +
                         "; nothing to grow a pattern on");
}

} // namespace morphogen
