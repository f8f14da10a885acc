#include "core/surface/tile_diagnostics.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

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

} // namespace morphogen
