#include "core/surface/tile_fidelity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <Eigen/Geometry>

#include "core/mesh/edge_table.hpp"
#include "core/surface/mesh_projector.hpp"

namespace morphogen {

namespace {

using Tri = std::array<std::uint32_t, 3>;

Eigen::Vector3d normalOf(const TriangleMesh& mesh, const Tri& t) {
    const Eigen::Vector3d a = mesh.positions[t[0]].cast<double>();
    return (mesh.positions[t[1]].cast<double>() - a).cross(mesh.positions[t[2]].cast<double>() - a);
}

// Below this barycentric weight the nearest point counts as on the opposite
// edge: splitting the triangle there would leave a sliver.
constexpr float kOnEdge = 0.05f;

struct Miss {
    double distance;
    std::uint32_t vertex;
    SurfacePoint nearest;
};

// One round: the misses, farthest first, each inserted unless a triangle it
// would change was already changed this round.
std::size_t insertionRound(TriangleMesh& mesh, const TriangleMesh& full, double reach,
                           std::size_t maxTriangles, std::vector<char>& inserted,
                           const std::vector<char>* candidates, double& farthest) {
    const MeshProjector projector(mesh);
    std::vector<Miss> misses(full.positions.size());
#pragma omp parallel for schedule(static)
    for (long long v = 0; v < (long long)full.positions.size(); ++v) {
        const Eigen::Vector3f& p = full.positions[std::size_t(v)];
        const SurfacePoint s = projector.closest(p);
        misses[std::size_t(v)] = {double((s.position - p).norm()), std::uint32_t(v), s};
    }
    farthest = 0;
    for (const Miss& m : misses)
        farthest = std::max(farthest, m.distance);
    misses.erase(std::remove_if(misses.begin(), misses.end(),
                                [&](const Miss& m) {
                                    return m.distance <= reach ||
                                           (candidates && !(*candidates)[m.vertex]);
                                }),
                 misses.end());
    std::sort(misses.begin(), misses.end(),
              [](const Miss& a, const Miss& b) { return a.distance > b.distance; });

    const EdgeTable edges(mesh);
    std::vector<char> touched(mesh.triangles.size(), 0);
    std::size_t count = 0;
    for (const Miss& miss : misses) {
        if (mesh.triangles.size() + 2 > maxTriangles)
            break;
        const std::uint32_t t = miss.nearest.triangle;
        if (touched[t])
            continue;
        const Eigen::Vector3f& at = full.positions[miss.vertex];
        const auto w = std::uint32_t(mesh.positions.size());
        const Eigen::Vector3f& b = miss.nearest.barycentric;
        int low = 0;
        for (int k = 1; k < 3; ++k)
            if (b[k] < b[low])
                low = k;
        std::vector<std::pair<std::uint32_t, Tri>> changed; // triangle, its new corners
        std::vector<Tri> added;
        if (b[low] < kOnEdge) {
            // On the edge opposite corner `low`: split it in every triangle using it.
            const std::uint32_t e = edges.edgeOf(t, (low + 1) % 3);
            bool free = true;
            for (auto u = edges.begin(e); u != edges.end(e); ++u)
                free = free && !touched[u->triangle];
            if (!free)
                continue;
            for (auto u = edges.begin(e); u != edges.end(e); ++u) {
                const Tri& old = mesh.triangles[u->triangle];
                const int k = u->corner;
                changed.push_back({u->triangle, {old[k], w, old[(k + 2) % 3]}});
                added.push_back({w, old[(k + 1) % 3], old[(k + 2) % 3]});
            }
        } else {
            const Tri& old = mesh.triangles[t];
            changed.push_back({t, {old[0], old[1], w}});
            added.push_back({old[1], old[2], w});
            added.push_back({old[2], old[0], w});
        }
        // Each new triangle faces as its parent did (it would not if the
        // nearest point were off the triangle, which a closest point is not,
        // but rounding is checked rather than trusted).
        mesh.positions.push_back(at);
        bool facing = true;
        const auto faces = [&](const Tri& now, const Tri& parent) {
            facing = facing && normalOf(mesh, now).dot(normalOf(mesh, parent)) > 0;
        };
        if (b[low] < kOnEdge) {
            const std::uint32_t e = edges.edgeOf(t, (low + 1) % 3);
            std::size_t k = 0;
            for (auto u = edges.begin(e); u != edges.end(e); ++u, ++k) {
                faces(changed[k].second, mesh.triangles[u->triangle]);
                faces(added[k], mesh.triangles[u->triangle]);
            }
        } else {
            for (const Tri& n : {changed[0].second, added[0], added[1]})
                faces(n, mesh.triangles[t]);
        }
        if (!facing) {
            mesh.positions.pop_back();
            continue;
        }
        for (const auto& [triangle, corners] : changed) {
            mesh.triangles[triangle] = corners;
            touched[triangle] = 1;
        }
        for (const Tri& n : added) {
            mesh.triangles.push_back(n);
            touched.push_back(1);
        }
        inserted.resize(mesh.positions.size(), 0);
        inserted[w] = 1;
        ++count;
    }
    return count;
}

} // namespace

FollowStats followModel(TriangleMesh& mesh, const TriangleMesh& full, double tolerance,
                        std::size_t maxTriangles, int rounds, std::vector<char>* inserted,
                        const std::vector<char>* candidates) {
    FollowStats s;
    std::vector<char> marks(mesh.positions.size(), 0);
    if (mesh.triangles.empty() || full.positions.empty()) {
        if (inserted)
            *inserted = marks;
        return s;
    }
    const double diagonal = std::max(double(boundsOf(full.positions).diagonal()), 1e-30);
    const double reach = tolerance * diagonal;
    double farthest = 0;
    for (int r = 0; r < rounds; ++r) {
        const std::size_t n =
            insertionRound(mesh, full, reach, maxTriangles, marks, candidates, farthest);
        if (r == 0)
            s.gapBefore = farthest / diagonal;
        s.gapAfter = farthest / diagonal;
        if (n == 0)
            break;
        s.insertions += n;
    }
    if (s.insertions > 0) {
        // The gap the last insertions left.
        const MeshProjector projector(mesh);
        farthest = 0;
        for (const Eigen::Vector3f& p : full.positions)
            farthest = std::max(farthest, double((projector.closest(p).position - p).norm()));
        s.gapAfter = farthest / diagonal;
    }
    marks.resize(mesh.positions.size(), 0);
    if (inserted)
        *inserted = std::move(marks);
    return s;
}

} // namespace morphogen
