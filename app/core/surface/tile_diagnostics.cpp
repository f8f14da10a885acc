#include "core/surface/tile_diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/mesh/mesh_check.hpp"
#include "core/surface/mesh_projector.hpp"

namespace morphogen {

namespace {

// The value at fraction q of a sorted sequence (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty())
        return 0;
    const auto k = std::size_t(std::lround(q * double(sorted.size() - 1)));
    return sorted[std::min(k, sorted.size() - 1)];
}

} // namespace

std::vector<double> texelWeightSums(const Atlas& atlas, const AtlasWeights& weights) {
    std::vector<double> sums(atlas.cellCount(), 0.0);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        double s = 0;
        for (float c : weights.coefficients[i])
            s += double(c);
        if (weights.hasDiagonals())
            for (float k : weights.diagonal[i])
                s += std::abs(double(k));
        sums[i] = s;
    }
    return sums;
}

WeightSumStats weightSumStats(const Atlas& atlas, const AtlasWeights& weights) {
    const std::vector<double> all = texelWeightSums(atlas, weights);
    std::vector<double> used;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            used.push_back(all[i]);
    std::sort(used.begin(), used.end());
    WeightSumStats s;
    s.texels = used.size();
    if (used.empty())
        return s;
    s.max = used.back();
    s.p99 = quantile(used, 0.99);
    s.p90 = quantile(used, 0.90);
    s.median = quantile(used, 0.5);
    return s;
}

std::vector<double> triangleAngles(const TriangleMesh& mesh) {
    std::vector<double> angles;
    angles.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d p = mesh.positions[t[k]].cast<double>();
            const Eigen::Vector3d u = mesh.positions[t[(k + 1) % 3]].cast<double>() - p;
            const Eigen::Vector3d v = mesh.positions[t[(k + 2) % 3]].cast<double>() - p;
            const double nu = u.norm(), nv = v.norm();
            angles.push_back(nu > 0 && nv > 0
                                 ? std::acos(std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0)) * 180.0 /
                                       M_PI
                                 : 0.0);
        }
    std::sort(angles.begin(), angles.end());
    return angles;
}

SurfaceGap tiledSurfaceGap(const SurfaceTiles& tiles, const TriangleMesh& full,
                           std::vector<double>* distances) {
    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize(), side = n + 1;
    // Every k-th grid line, at most 4 x 4 quads a tile: the chords of a
    // tile's quarter lie far closer to the grid than the gaps looked for, and
    // 16 x 16 tiles would give an AABB tree of a million triangles.
    std::vector<int> lines;
    const int k = std::max(1, n / 4);
    for (int i = 0; i < n; i += k)
        lines.push_back(i);
    lines.push_back(n);
    TriangleMesh grids;
    grids.positions = tiles.gridPositions;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const auto at = [&](int i, int j) { return std::uint32_t((t * side + j) * side + i); };
        for (std::size_t b = 0; b + 1 < lines.size(); ++b)
            for (std::size_t a = 0; a + 1 < lines.size(); ++a) {
                const int i0 = lines[a], i1 = lines[a + 1], j0 = lines[b], j1 = lines[b + 1];
                grids.triangles.push_back({at(i0, j0), at(i1, j0), at(i1, j1)});
                grids.triangles.push_back({at(i0, j0), at(i1, j1), at(i0, j1)});
            }
    }
    return surfaceGap(grids, full, distances);
}

SurfaceGap surfaceGap(const TriangleMesh& stand, const TriangleMesh& full,
                      std::vector<double>* distances) {
    SurfaceGap gap;
    if (stand.triangles.empty() || full.positions.empty())
        return gap;
    const MeshProjector projector(stand);
    const double diagonal = std::max(double(boundsOf(full.positions).diagonal()), 1e-30);
    std::vector<double> d(full.positions.size());
#pragma omp parallel for schedule(static)
    for (long long v = 0; v < (long long)d.size(); ++v) {
        const Eigen::Vector3f& p = full.positions[std::size_t(v)];
        d[std::size_t(v)] = double((projector.closest(p).position - p).norm()) / diagonal;
    }
    gap.vertices = d.size();
    if (distances)
        *distances = d;
    const auto worst = std::max_element(d.begin(), d.end());
    gap.max = *worst;
    gap.worst = full.positions[std::size_t(worst - d.begin())];
    gap.overOnePercent =
        std::size_t(std::count_if(d.begin(), d.end(), [](double x) { return x > 0.01; }));
    std::sort(d.begin(), d.end());
    gap.p99 = quantile(d, 0.99);
    return gap;
}

} // namespace morphogen
