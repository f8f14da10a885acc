#pragma once

#include <cstddef>
#include <vector>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// Per atlas cell, the sum of its weights as the explicit step's stability
// bound sees it (maxCoefficientSum: the four axis coefficients plus the
// diagonals' magnitudes); 0 for unused cells.
std::vector<double> texelWeightSums(const Atlas& atlas, const AtlasWeights& weights);

// The distribution of the weight sums over the used texels. The substeps a
// step needs follow the largest; a uniform grid of the mean texel size has
// max / median near 1, so max / median says how much the worst texels cost.
struct WeightSumStats {
    std::size_t texels = 0;
    double max = 0;
    double p99 = 0; // 99th percentile
    double p90 = 0;
    double median = 0;
};
WeightSumStats weightSumStats(const Atlas& atlas, const AtlasWeights& weights);

// The angles of a mesh's triangles in degrees, sorted ascending (3 per triangle;
// degenerate corners count as 0).
std::vector<double> triangleAngles(const TriangleMesh& mesh);

} // namespace morphogen
