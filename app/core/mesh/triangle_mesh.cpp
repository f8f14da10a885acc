#include "core/mesh/triangle_mesh.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

#include <Eigen/Geometry>
#include <meshoptimizer.h>

#include "core/mesh/edge_table.hpp"

namespace morphogen {

Bounds boundsOf(const std::vector<Eigen::Vector3f>& positions) {
    Bounds b;
    if (positions.empty())
        return b;
    b.min = b.max = positions.front();
    for (const Eigen::Vector3f& p : positions) {
        b.min = b.min.cwiseMin(p);
        b.max = b.max.cwiseMax(p);
    }
    return b;
}

Eigen::Vector3d doubleAreaVector(const TriangleMesh& mesh, std::size_t t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d a = mesh.positions[tri[0]].cast<double>();
    const Eigen::Vector3d b = mesh.positions[tri[1]].cast<double>();
    const Eigen::Vector3d c = mesh.positions[tri[2]].cast<double>();
    return (b - a).cross(c - a);
}

double triangleArea(const TriangleMesh& mesh, std::size_t t) {
    return 0.5 * doubleAreaVector(mesh, t).norm();
}

double surfaceArea(const TriangleMesh& mesh) {
    double sum = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        sum += triangleArea(mesh, t);
    return sum;
}

WeldStats weldVertices(TriangleMesh& mesh) {
    WeldStats stats;
    stats.verticesBefore = mesh.positions.size();
    // -0 and +0 differ in their bits but not as positions.
    for (Eigen::Vector3f& p : mesh.positions)
        for (int k = 0; k < 3; ++k)
            if (p[k] == 0.0f)
                p[k] = 0.0f;

    static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "positions must be packed");
    static_assert(sizeof(mesh.triangles[0]) == 3 * sizeof(unsigned int), "indices must be packed");
    const std::size_t indexCount = 3 * mesh.triangles.size();
    std::vector<unsigned int> remap(mesh.positions.size());
    const std::size_t unique = meshopt_generateVertexRemap(
        remap.data(), reinterpret_cast<const unsigned int*>(mesh.triangles.data()), indexCount,
        mesh.positions.data(), mesh.positions.size(), sizeof(Eigen::Vector3f));

    // meshopt numbers the distinct positions by first use in the triangles;
    // renumber them by their first copy in the file instead, so a mesh without
    // duplicates keeps its vertex order.
    std::vector<std::uint32_t> order(unique, ~0u);
    std::vector<Eigen::Vector3f> positions;
    positions.reserve(unique);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (remap[i] == ~0u)
            continue;
        if (order[remap[i]] == ~0u) {
            order[remap[i]] = std::uint32_t(positions.size());
            positions.push_back(mesh.positions[i]);
        }
        remap[i] = order[remap[i]];
    }
    stats.unreferencedDropped =
        mesh.positions.size() -
        std::count_if(remap.begin(), remap.end(), [](unsigned r) { return r != ~0u; });
    mesh.positions = std::move(positions);

    std::size_t kept = 0;
    for (auto& tri : mesh.triangles) {
        for (std::uint32_t& v : tri)
            v = remap[v];
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])
            continue;
        mesh.triangles[kept++] = tri;
    }
    stats.collapsedRemoved = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    // Collapsed triangles may have been a vertex's only users: drop those too,
    // keeping the order.
    std::vector<std::uint32_t> index(mesh.positions.size(), ~0u);
    for (const auto& tri : mesh.triangles)
        for (std::uint32_t v : tri)
            index[v] = 0;
    std::size_t next = 0;
    for (std::size_t v = 0; v < index.size(); ++v)
        if (index[v] == 0) {
            index[v] = std::uint32_t(next);
            mesh.positions[next++] = mesh.positions[v];
        }
    stats.unreferencedDropped += mesh.positions.size() - next;
    mesh.positions.resize(next);
    for (auto& tri : mesh.triangles)
        for (std::uint32_t& v : tri)
            v = index[v];
    stats.verticesAfter = next;
    return stats;
}

std::size_t orientConsistently(TriangleMesh& mesh) {
    const PieceOrientation o = orientPieces(mesh, EdgeTable(mesh));
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        if (o.flip[t])
            std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);
    return o.flipped;
}

std::vector<std::vector<std::uint32_t>> componentTriangles(const TriangleMesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& t : mesh.triangles)
        for (int k = 1; k < 3; ++k) {
            const std::uint32_t a = find(t[0]), b = find(t[k]);
            if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<std::uint32_t> slot(mesh.positions.size(), UINT32_MAX);
    std::vector<std::vector<std::uint32_t>> out;
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::uint32_t root = find(mesh.triangles[t][0]);
        if (slot[root] == UINT32_MAX) {
            slot[root] = std::uint32_t(out.size());
            out.emplace_back();
        }
        out[slot[root]].push_back(t);
    }
    return out;
}

} // namespace morphogen
