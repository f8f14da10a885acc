#pragma once

#include <cstddef>
#include <vector>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/surface/surface_tiles.hpp"

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

// How closely the tiled surface (the tiles' corner grids, what a renderer
// draws and the pattern lives on) follows the model: per vertex of the
// full-resolution mesh, the distance to the nearest point of the grids, as a
// fraction of the mesh's bounding-box diagonal. A thin part the simplified
// mesh lost (an ear tip, a spout) shows as a large gap.
struct SurfaceGap {
    std::size_t vertices = 0;
    double max = 0;
    double p99 = 0;
    std::size_t overOnePercent = 0;                  // vertices farther than 1% of the diagonal
    Eigen::Vector3f worst = Eigen::Vector3f::Zero(); // the vertex farthest away
};
// `distances`, when given, gets each vertex's distance (the same fraction).
SurfaceGap tiledSurfaceGap(const SurfaceTiles& tiles, const TriangleMesh& full,
                           std::vector<double>* distances = nullptr);
// The same to any mesh standing in for the model (the simplified mesh).
SurfaceGap surfaceGap(const TriangleMesh& stand, const TriangleMesh& full,
                      std::vector<double>* distances = nullptr);

} // namespace morphogen
