#include "core/surface/surface_features.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include <Eigen/Eigenvalues>

#include "core/domain/atlas.hpp"

namespace morphogen {

std::vector<SurfaceFeature> findSurfaceFeatures(const Atlas& atlas, const float* plane,
                                                const std::vector<float>& area,
                                                const std::vector<Eigen::Vector3f>& position,
                                                const std::vector<float>& scalar,
                                                std::size_t minTexels) {
    const std::size_t cells = atlas.cellCount();
    assert(area.size() == cells && position.size() == cells);
    assert(scalar.empty() || scalar.size() == cells);
    // The threshold and the minority phase by area, so large texels count for more.
    double total = 0, weighted = 0;
    for (std::uint32_t i = 0; i < cells; ++i)
        if (atlas.used(i)) {
            total += area[i];
            weighted += double(area[i]) * plane[i];
        }
    if (total <= 0)
        return {};
    const double mean = weighted / total;
    double above = 0;
    for (std::uint32_t i = 0; i < cells; ++i)
        if (atlas.used(i) && plane[i] > mean)
            above += area[i];
    const bool countAbove = 2 * above <= total;
    auto inFeature = [&](std::uint32_t i) {
        return atlas.used(i) && (countAbove ? plane[i] > mean : plane[i] < mean);
    };

    const auto& neighbours = atlas.neighbours();
    std::vector<std::uint8_t> seen(cells, 0);
    std::vector<std::uint32_t> stack;
    std::vector<SurfaceFeature> features;
    for (std::uint32_t start = 0; start < cells; ++start) {
        if (seen[start] || !inFeature(start))
            continue;
        SurfaceFeature f;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
        double scalarSum = 0;
        seen[start] = 1;
        stack.assign(1, start);
        while (!stack.empty()) {
            const std::uint32_t i = stack.back();
            stack.pop_back();
            ++f.texels;
            f.area += area[i];
            const Eigen::Vector3d p = position[i].cast<double>();
            sum += double(area[i]) * p;
            second += double(area[i]) * p * p.transpose();
            if (!scalar.empty())
                scalarSum += double(area[i]) * scalar[i];
            for (const std::uint32_t j : neighbours[i])
                if (!seen[j] && inFeature(j)) {
                    seen[j] = 1;
                    stack.push_back(j);
                }
        }
        if (f.texels < minTexels || f.area <= 0)
            continue;
        f.centroid = sum / f.area;
        f.meanValue = scalarSum / f.area;
        // The smallest eigenvalue is the spread along the normal (the
        // surface's bend under the feature); the two others span its extent.
        const Eigen::Matrix3d covariance = second / f.area - f.centroid * f.centroid.transpose();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
        const double major = eigen.eigenvalues()[2], minor = eigen.eigenvalues()[1];
        if (minor > 0)
            f.elongation = std::sqrt(major / minor);
        f.majorAxis = eigen.eigenvectors().col(2);
        features.push_back(f);
    }
    return features;
}

FeatureAreaStats featureAreaStats(const std::vector<SurfaceFeature>& features) {
    FeatureAreaStats s;
    s.count = features.size();
    if (features.empty())
        return s;
    for (const SurfaceFeature& f : features)
        s.meanArea += f.area;
    s.meanArea /= double(features.size());
    if (features.size() < 2 || s.meanArea <= 0)
        return s;
    double variance = 0;
    for (const SurfaceFeature& f : features)
        variance += (f.area - s.meanArea) * (f.area - s.meanArea);
    variance /= double(features.size() - 1);
    s.coefficientOfVariation = std::sqrt(variance) / s.meanArea;
    return s;
}

double medianElongation(const std::vector<SurfaceFeature>& features, std::size_t minTexels) {
    std::vector<double> e;
    for (const SurfaceFeature& f : features)
        if (f.texels >= minTexels)
            e.push_back(f.elongation);
    if (e.empty())
        return 0;
    const auto middle = e.begin() + std::ptrdiff_t(e.size() / 2);
    std::nth_element(e.begin(), middle, e.end());
    return *middle;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
    assert(a.size() == b.size());
    const std::size_t n = a.size();
    if (n < 3)
        return 0;
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        ma += a[i];
        mb += b[i];
    }
    ma /= double(n);
    mb /= double(n);
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < n; ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    if (saa <= 0 || sbb <= 0)
        return 0;
    return sab / std::sqrt(saa * sbb);
}

} // namespace morphogen
