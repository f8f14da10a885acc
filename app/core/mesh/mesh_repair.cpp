#include "core/mesh/mesh_repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <Eigen/Geometry>

#include "core/mesh/mesh_check.hpp"

namespace morphogen {

namespace {

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// Open-boundary vertices (on an edge of one triangle) within `distance` of an
// earlier one are moved onto it, in index order, through a grid of cells
// `distance` wide. Returns how many were merged; `mesh`'s triangles then
// refer to the vertices kept.
std::size_t mergeBoundaryVertices(TriangleMesh& mesh, double distance) {
    std::unordered_map<std::uint64_t, int> edgeUses;
    edgeUses.reserve(mesh.triangles.size() * 3);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            ++edgeUses[edgeKey(t[k], t[(k + 1) % 3])];
    std::vector<char> onBoundary(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (edgeUses[edgeKey(t[k], t[(k + 1) % 3])] == 1)
                onBoundary[t[k]] = onBoundary[t[(k + 1) % 3]] = 1;

    struct CellHash {
        std::size_t operator()(const std::array<long long, 3>& c) const {
            return std::size_t(std::uint64_t(c[0]) * 73856093u ^ std::uint64_t(c[1]) * 19349663u ^
                               std::uint64_t(c[2]) * 83492791u);
        }
    };
    std::unordered_map<std::array<long long, 3>, std::vector<std::uint32_t>, CellHash> cells;
    // Cells counted from the box's corner: at most diagonal / distance of them
    // per side, which the caller keeps far within a long long.
    const Eigen::Vector3d origin = boundsOf(mesh.positions).min.cast<double>();
    const auto cellOf = [&](const Eigen::Vector3f& p) {
        const Eigen::Vector3d c = (p.cast<double>() - origin) / distance;
        return std::array<long long, 3>{(long long)std::floor(c.x()), (long long)std::floor(c.y()),
                                        (long long)std::floor(c.z())};
    };
    std::vector<std::uint32_t> target(mesh.positions.size());
    std::iota(target.begin(), target.end(), 0u);
    std::size_t merged = 0;
    const double squared = distance * distance;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        if (!onBoundary[v])
            continue;
        const Eigen::Vector3f& p = mesh.positions[v];
        const std::array<long long, 3> c = cellOf(p);
        bool found = false;
        for (long long dx = -1; dx <= 1 && !found; ++dx)
            for (long long dy = -1; dy <= 1 && !found; ++dy)
                for (long long dz = -1; dz <= 1 && !found; ++dz) {
                    const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == cells.end())
                        continue;
                    for (std::uint32_t kept : it->second)
                        if ((mesh.positions[kept] - p).cast<double>().squaredNorm() <= squared) {
                            target[v] = kept;
                            found = true;
                            break;
                        }
                }
        if (found)
            ++merged;
        else
            cells[c].push_back(v);
    }
    for (auto& t : mesh.triangles)
        for (std::uint32_t& v : t)
            v = target[v];
    return merged;
}

// Removes triangles with a repeated corner; returns how many.
std::size_t removeCollapsed(TriangleMesh& mesh) {
    const std::size_t before = mesh.triangles.size();
    mesh.triangles.erase(std::remove_if(mesh.triangles.begin(), mesh.triangles.end(),
                                        [](const std::array<std::uint32_t, 3>& t) {
                                            return t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
                                        }),
                         mesh.triangles.end());
    return before - mesh.triangles.size();
}

// Removes triangles on the same three vertices as an earlier one (either
// winding), keeping the first; returns how many.
std::size_t removeDuplicates(TriangleMesh& mesh) {
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::size_t>> sorted;
    sorted.reserve(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        std::array<std::uint32_t, 3> key = mesh.triangles[i];
        std::sort(key.begin(), key.end());
        sorted.emplace_back(key, i);
    }
    std::sort(sorted.begin(), sorted.end());
    std::vector<char> drop(mesh.triangles.size(), 0);
    std::size_t removed = 0;
    for (std::size_t i = 1; i < sorted.size(); ++i)
        if (sorted[i].first == sorted[i - 1].first) {
            drop[sorted[i].second] = 1;
            ++removed;
        }
    std::size_t out = 0;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        if (!drop[i])
            mesh.triangles[out++] = mesh.triangles[i];
    mesh.triangles.resize(out);
    return removed;
}

// Cuts sheets apart where they only meet (fins, bowtie vertices) with CGAL's
// polygon soup orientation, which duplicates the vertices there; returns how
// many copies it added.
std::size_t splitNonManifold(TriangleMesh& mesh) {
    std::vector<Eigen::Vector3f> points = mesh.positions;
    std::vector<std::array<std::size_t, 3>> polygons;
    polygons.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        polygons.push_back({t[0], t[1], t[2]});
    const std::size_t before = points.size();
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, polygons);
    mesh.positions = std::move(points);
    for (std::size_t i = 0; i < polygons.size(); ++i)
        for (int k = 0; k < 3; ++k)
            mesh.triangles[i][k] = std::uint32_t(polygons[i][k]);
    return mesh.positions.size() - before;
}

// Triangle area (double precision).
double areaOf(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
    const Eigen::Vector3d a = mesh.positions[t[0]].cast<double>();
    const Eigen::Vector3d b = mesh.positions[t[1]].cast<double>();
    const Eigen::Vector3d c = mesh.positions[t[2]].cast<double>();
    return 0.5 * (b - a).cross(c - a).norm();
}

// Removes components (triangles joined through vertices) whose area is below
// kSpeckAreaFraction of the whole; counts them and their triangles.
void removeSpecks(TriangleMesh& mesh, RepairStats& stats) {
    const std::vector<std::vector<std::uint32_t>> pieces = componentTriangles(mesh);
    if (pieces.size() < 2)
        return;
    std::vector<double> area(pieces.size(), 0.0);
    double total = 0;
    for (std::size_t p = 0; p < pieces.size(); ++p)
        for (std::uint32_t t : pieces[p]) {
            const double a = areaOf(mesh, mesh.triangles[t]);
            area[p] += a;
            total += a;
        }
    if (!(total > 0))
        return;
    std::vector<char> drop(mesh.triangles.size(), 0);
    bool any = false;
    for (std::size_t p = 0; p < pieces.size(); ++p)
        if (area[p] < kSpeckAreaFraction * total) {
            ++stats.specks;
            any = true;
            for (std::uint32_t t : pieces[p])
                drop[t] = 1;
        }
    if (!any)
        return;
    std::size_t out = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (drop[t]) {
            ++stats.speckTriangles;
            continue;
        }
        mesh.triangles[out++] = mesh.triangles[t];
    }
    mesh.triangles.resize(out);
}

// Drops vertices no triangle uses, keeping the others' order.
void dropUnused(TriangleMesh& mesh) {
    std::vector<char> used(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles)
        for (std::uint32_t v : t)
            used[v] = 1;
    std::vector<std::uint32_t> renumber(mesh.positions.size(), UINT32_MAX);
    std::vector<Eigen::Vector3f> positions;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
        if (used[v]) {
            renumber[v] = std::uint32_t(positions.size());
            positions.push_back(mesh.positions[v]);
        }
    for (auto& t : mesh.triangles)
        for (std::uint32_t& v : t)
            v = renumber[v];
    mesh.positions = std::move(positions);
}

} // namespace

RepairStats repairMesh(TriangleMesh& mesh, const RepairOptions& options) {
    RepairStats stats;
    if (!options.enabled || mesh.triangles.empty())
        return stats;
    const MeshReport before = checkMesh(mesh);
    stats.nonManifoldEdges = before.nonManifoldEdges.count;
    stats.nonManifoldVertices = before.nonManifoldVertices.count;

    const double diagonal = before.bounds.diagonal();
    if (options.mergeDistance > 0 && diagonal > 0 && std::isfinite(diagonal) &&
        before.boundaryEdges > 0) {
        // At least 1e-9 of the diagonal: a grid of at most 1e9 cells a side.
        const double distance = std::max(options.mergeDistance, 1e-9) * diagonal;
        stats.mergedVertices = mergeBoundaryVertices(mesh, distance);
        stats.collapsedTriangles = removeCollapsed(mesh);
    }
    stats.duplicateTriangles = removeDuplicates(mesh);
    removeSpecks(mesh, stats);
    dropUnused(mesh);
    if (!mesh.triangles.empty())
        stats.splitVertices = splitNonManifold(mesh);
    return stats;
}

} // namespace morphogen
