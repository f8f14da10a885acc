#include "core/surface/tile_mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include <Eigen/Geometry>

#include "core/mesh/edge_table.hpp"
#include "core/surface/mesh_curvature.hpp"

namespace morphogen {

namespace {

constexpr double kRadToDeg = 57.29577951308232;

using Tri = std::array<std::uint32_t, 3>;

double minAngle(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c) {
    const Eigen::Vector3f p[3] = {a, b, c};
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d u = (p[(k + 1) % 3] - p[k]).cast<double>();
        const Eigen::Vector3d v = (p[(k + 2) % 3] - p[k]).cast<double>();
        const double nu = u.norm(), nv = v.norm();
        if (!(nu > 0 && nv > 0))
            return 0;
        smallest =
            std::min(smallest, std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0)) * kRadToDeg);
    }
    return smallest;
}

Eigen::Vector3d normalOf(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                         const Eigen::Vector3f& c) {
    return (b - a).cast<double>().cross((c - a).cast<double>());
}

// 4 sqrt(3) area / sum of squared edges, signed by `up`: 1 for equilateral.
double shape(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
             const Eigen::Vector3d& up) {
    const Eigen::Vector3d n = normalOf(a, b, c);
    const double edges = (b - a).cast<double>().squaredNorm() +
                         (c - b).cast<double>().squaredNorm() +
                         (a - c).cast<double>().squaredNorm();
    if (!(edges > 0))
        return 0;
    const double area = 0.5 * n.norm();
    const double sign = n.dot(up) >= 0 ? 1.0 : -1.0;
    return sign * 4 * std::sqrt(3.0) * area / edges;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32 | b) : (std::uint64_t(b) << 32 | a);
}

std::size_t flipPass(TriangleMesh& mesh) {
    const EdgeTable edges(mesh);
    std::unordered_set<std::uint64_t> existing;
    existing.reserve(edges.edgeCount() * 2);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e)
        existing.insert(key(edges.lowVertex(e), edges.highVertex(e)));
    std::vector<int> degree(mesh.positions.size(), 0);
    for (const Tri& t : mesh.triangles)
        for (std::uint32_t v : t)
            ++degree[v];
    std::vector<char> touched(mesh.triangles.size(), 0);
    const double minCoplanar = std::cos(30.0 / kRadToDeg);
    std::size_t flips = 0;
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        if (edges.useCount(e) != 2)
            continue;
        const EdgeTable::Use& u1 = *edges.begin(e);
        const EdgeTable::Use& u2 = *(edges.begin(e) + 1);
        if (u1.forward == u2.forward || touched[u1.triangle] || touched[u2.triangle])
            continue; // not consistently wound here, or already changed this pass
        Tri& t1 = mesh.triangles[u1.triangle];
        Tri& t2 = mesh.triangles[u2.triangle];
        const std::uint32_t a = t1[u1.corner], b = t1[(u1.corner + 1) % 3],
                            c = t1[(u1.corner + 2) % 3], d = t2[(u2.corner + 2) % 3];
        if (c == d || degree[a] < 4 || degree[b] < 4 || existing.count(key(c, d)))
            continue;
        const auto& p = mesh.positions;
        const Eigen::Vector3d n1 = normalOf(p[a], p[b], p[c]), n2 = normalOf(p[b], p[a], p[d]);
        const double l1 = n1.norm(), l2 = n2.norm();
        if (l1 > 0 && l2 > 0 && n1.dot(n2) < minCoplanar * l1 * l2)
            continue;
        const double before = std::min(minAngle(p[a], p[b], p[c]), minAngle(p[b], p[a], p[d]));
        const double after = std::min(minAngle(p[a], p[d], p[c]), minAngle(p[d], p[b], p[c]));
        if (after <= before + 1e-3)
            continue;
        const Eigen::Vector3d up = n1 + n2;
        if (normalOf(p[a], p[d], p[c]).dot(up) <= 0 || normalOf(p[d], p[b], p[c]).dot(up) <= 0)
            continue;
        t1 = {a, d, c};
        t2 = {d, b, c};
        existing.erase(key(a, b));
        existing.insert(key(c, d));
        --degree[a];
        --degree[b];
        ++degree[c];
        ++degree[d];
        touched[u1.triangle] = touched[u2.triangle] = 1;
        ++flips;
    }
    return flips;
}

std::size_t relaxPass(TriangleMesh& mesh, const MeshProjector& full, const VertexPins* pins) {
    const std::size_t nv = mesh.positions.size();
    const EdgeTable edges(mesh);
    std::vector<char> boundary(nv, 0);
    std::vector<std::vector<std::uint32_t>> neighbours(nv);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        const std::uint32_t a = edges.lowVertex(e), b = edges.highVertex(e);
        if (edges.useCount(e) != 2)
            boundary[a] = boundary[b] = 1;
        neighbours[a].push_back(b);
        neighbours[b].push_back(a);
    }
    std::vector<std::vector<std::uint32_t>> around(nv);
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t])
            around[v].push_back(t);
    const std::vector<Eigen::Vector3f> normals = areaWeightedVertexNormals(mesh);

    std::size_t moves = 0;
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (boundary[v] || neighbours[v].empty())
            continue;
        const bool pinned = pins && v < pins->pinned.size() && pins->pinned[v];
        // The area-weighted mean of the centroids of its triangles: a vertex moves
        // towards its larger triangles, which evens out the triangles' areas (and so
        // the texels', whose smallest set the time step), not only the edge lengths.
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        double weight = 0;
        for (std::uint32_t t : around[v]) {
            const auto& tri = mesh.triangles[t];
            const Eigen::Vector3f &p0 = mesh.positions[tri[0]], &p1 = mesh.positions[tri[1]],
                                  &p2 = mesh.positions[tri[2]];
            const double area = 0.5 * normalOf(p0, p1, p2).norm();
            sum += area * ((p0 + p1 + p2) / 3.0f).cast<double>();
            weight += area;
        }
        if (!(weight > 0))
            continue;
        const Eigen::Vector3f centre = (sum / weight).cast<float>();
        const Eigen::Vector3f n = normals[v];
        Eigen::Vector3f delta = centre - mesh.positions[v];
        delta -= n * n.dot(delta);
        const Eigen::Vector3f moved = full.closest(mesh.positions[v] + delta).position;
        if (pinned && (moved - pins->at[v]).norm() > pins->reach)
            continue;

        const Eigen::Vector3d up = n.cast<double>();
        const auto worst = [&](const Eigen::Vector3f& at) {
            double w = 1e9;
            for (std::uint32_t t : around[v]) {
                Eigen::Vector3f q[3];
                for (int k = 0; k < 3; ++k)
                    q[k] = mesh.triangles[t][k] == v ? at : mesh.positions[mesh.triangles[t][k]];
                w = std::min(w, shape(q[0], q[1], q[2], up));
            }
            return w;
        };
        // Accept a move that keeps the worst triangle at least as good, or good
        // enough (0.5: angles of some 30 degrees or more), so that sizes even out too.
        const double now = worst(mesh.positions[v]);
        if (worst(moved) >= std::min(now, 0.5) && moved != mesh.positions[v]) {
            mesh.positions[v] = moved;
            ++moves;
        }
    }
    return moves;
}

// Splits each edge longer than maxLength at its midpoint (moved onto `full`
// when that keeps its triangles facing as before), longest first, at most one
// edge per triangle; stops before the mesh passes maxTriangles.
std::size_t splitPass(TriangleMesh& mesh, const MeshProjector& full, double maxLength,
                      std::size_t maxTriangles) {
    const EdgeTable edges(mesh);
    std::vector<std::pair<double, std::size_t>> candidates;
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        const double length = double(
            (mesh.positions[edges.highVertex(e)] - mesh.positions[edges.lowVertex(e)]).norm());
        if (length > maxLength)
            candidates.emplace_back(length, e);
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const auto& x, const auto& y) { return x.first > y.first; });
    std::vector<char> touched(mesh.triangles.size(), 0);
    std::size_t splits = 0;
    for (const auto& [length, e] : candidates) {
        const std::size_t uses = edges.useCount(e);
        if (mesh.triangles.size() + uses > maxTriangles)
            break;
        bool free = true;
        for (auto u = edges.begin(e); u != edges.begin(e) + std::ptrdiff_t(uses); ++u)
            free = free && !touched[u->triangle];
        if (!free)
            continue;
        const Eigen::Vector3f mid =
            0.5f * (mesh.positions[edges.lowVertex(e)] + mesh.positions[edges.highVertex(e)]);
        Eigen::Vector3f at = full.closest(mid).position;
        // On the surface unless that turns a new triangle over (an edge that cuts
        // far through a concave region): the tiles are projected onto it anyway.
        for (auto u = edges.begin(e); u != edges.begin(e) + std::ptrdiff_t(uses); ++u) {
            const Tri& t = mesh.triangles[u->triangle];
            const auto& p = mesh.positions;
            const int k = u->corner;
            const Eigen::Vector3d n = normalOf(p[t[0]], p[t[1]], p[t[2]]);
            if (normalOf(p[t[k]], at, p[t[(k + 2) % 3]]).dot(n) <= 0 ||
                normalOf(at, p[t[(k + 1) % 3]], p[t[(k + 2) % 3]]).dot(n) <= 0)
                at = mid;
        }
        const auto m = std::uint32_t(mesh.positions.size());
        mesh.positions.push_back(at);
        for (auto u = edges.begin(e); u != edges.begin(e) + std::ptrdiff_t(uses); ++u) {
            Tri& t = mesh.triangles[u->triangle];
            const int k = u->corner;
            const Tri second = {m, t[(k + 1) % 3], t[(k + 2) % 3]};
            t = {t[k], m, t[(k + 2) % 3]};
            mesh.triangles.push_back(second);
            touched[u->triangle] = 1;
            touched.push_back(1);
        }
        ++splits;
    }
    return splits;
}

} // namespace

std::size_t splitLongEdges(TriangleMesh& mesh, const MeshProjector& full, double maxLength,
                           std::size_t maxTriangles) {
    std::size_t splits = 0;
    for (int pass = 0; pass < 16; ++pass) {
        const std::size_t n = splitPass(mesh, full, maxLength, maxTriangles);
        if (n == 0)
            break;
        splits += n;
    }
    return splits;
}

double tileEdgeLength(const TriangleMesh& mesh, std::size_t triangles) {
    double area = 0;
    for (const Tri& t : mesh.triangles)
        area +=
            0.5 * normalOf(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]).norm();
    return triangles > 0 ? std::sqrt(4 * area / (std::sqrt(3.0) * double(triangles))) : 0.0;
}

double minimumAngle(const TriangleMesh& mesh) {
    double smallest = 180;
    for (const Tri& t : mesh.triangles)
        smallest = std::min(
            smallest, minAngle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
    return smallest;
}

MeshQualityStats improveForTiles(TriangleMesh& mesh, const MeshProjector& full, int rounds,
                                 const VertexPins* pins) {
    MeshQualityStats s;
    s.minAngleBefore = minimumAngle(mesh);
    for (int r = 0; r < rounds; ++r) {
        s.flips += flipPass(mesh);
        s.moves += relaxPass(mesh, full, pins);
    }
    s.flips += flipPass(mesh);
    s.minAngleAfter = minimumAngle(mesh);
    return s;
}

} // namespace morphogen
