#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace morphogen {

class Atlas;

// A connected region of the minority phase on an atlas (the atlas version of
// pattern_stats.hpp's PatternFeature): the texels above the area-weighted mean
// where those cover less than half the surface, else those below it, joined
// through the connectivity map, so a spot that straddles tile edges is one
// feature.
struct SurfaceFeature {
    std::size_t texels = 0;
    double area = 0;            // sum of the texels' areas (world units^2)
    Eigen::Vector3d centroid{}; // area-weighted mean texel position
    double meanValue = 0;       // area-weighted mean of a per-texel scalar (e.g. curvature)
    // The shape: the square root of the ratio of the two largest eigenvalues of
    // the texel positions' area-weighted covariance (1 for a round spot, about
    // 2 for one twice as long as wide), and the unit direction it is longest in.
    double elongation = 1;
    Eigen::Vector3d majorAxis{1, 0, 0};
};

// Features of `plane` (one value per atlas cell) on `atlas`. `area` and
// `position` are per cell (unused cells ignored); `scalar`, when not empty, is
// averaged per feature into meanValue. Regions of fewer than minTexels texels
// are left out (noise).
std::vector<SurfaceFeature> findSurfaceFeatures(const Atlas& atlas, const float* plane,
                                                const std::vector<float>& area,
                                                const std::vector<Eigen::Vector3f>& position,
                                                const std::vector<float>& scalar = {},
                                                std::size_t minTexels = 3);

// Summary of feature areas: count, mean and coefficient of variation (standard
// deviation / mean; 0 for fewer than two features).
struct FeatureAreaStats {
    std::size_t count = 0;
    double meanArea = 0;
    double coefficientOfVariation = 0;
};
FeatureAreaStats featureAreaStats(const std::vector<SurfaceFeature>& features);

// The median elongation of the features with at least `minTexels` texels (a
// spot of a handful of texels has the shape of its texels, not its own); 0
// when there are none.
double medianElongation(const std::vector<SurfaceFeature>& features, std::size_t minTexels);

// Pearson correlation of two equally long series (0 when either is constant
// or they have fewer than three entries).
double correlation(const std::vector<double>& a, const std::vector<double>& b);

} // namespace morphogen
