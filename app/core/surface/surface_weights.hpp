#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/domain/atlas_weights.hpp"
#include "core/session/gravity.hpp"
#include "core/session/surface_spec.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

struct SurfaceWeightOptions {
    // Model units per world unit: a session's length scale on the surface.
    double unitsPerWorld = 1.0;
    // On: the diffusion follows the surface's metric (Lo section 3, Witkin &
    // Kass eq. 8), so features have the same size in world units wherever
    // tiles are stretched. Off: the paper's uncorrected baseline, every texel
    // a square of the mean texel size.
    bool metricCorrection = true;
    // Per atlas cell (cellCount() entries) or null: a factor on the feature
    // size; the diffusion rate scales with its square (curvatureScale).
    const std::vector<float>* featureScale = nullptr;
    // With metric correction: the 9-point stencil's cross term (AtlasWeights::
    // diagonal), isotropic on sheared texels. Off: the 5-point weights only.
    bool crossTerm = true;
    // Set: the weights also carry the anisotropic part (AtlasWeights::tensor,
    // surfaceTensorWeights) for this direction field. Needs metricCorrection.
    std::optional<SurfaceDirection> direction;
    // Active: the weights also carry the drift of water drops running down the
    // surface (AtlasWeights::drift, surfaceDrift) for its direction and strength.
    Gravity gravity;
};

// The guards against degenerate texels (see surfaceWeights): areas below
// minArea and centre distances below minDistance count as those floors (model
// units), set from the median texel area.
// 15% and 0.35: on the scan samples (docs/mesh_repair.md) the texels a rough
// surface squeezes set the step at 5% and 0.2 (91 substeps on a 30k-triangle
// scan, 217 on a 108k one); at these floors 30 and 44, while the samples'
// texels stay above them (their substeps unchanged but one on the holes model).
constexpr double kFloorArea = 0.15;     // of the median texel area
constexpr double kFloorDistance = 0.35; // of the median texel width
struct TexelFloors {
    double minArea = 0;
    double minDistance = 0;
    double meanArea = 1; // over used texels: the uncorrected weights' texel area
};
TexelFloors texelFloors(const SurfaceTiles& tiles, double unitsPerWorld);

// Texel `cell`'s Jacobian [J_u J_v] in model units per texel step (the tiles'
// world-unit columns times unitsPerWorld): what the tensor and drift weights
// map tangent vectors through.
Eigen::Matrix<double, 3, 2> texelJacobian(const SurfaceTiles& tiles, std::uint32_t cell,
                                          double unitsPerWorld);

// Per-texel weights of the Laplacian on the tiled surface (the AtlasWeights
// contract: coefficients[i][d] * area[i], and diagonal[i][s] * area[i], is the
// same from both sides of every texel pair, up to float rounding: one flux per
// pair). With metric correction and crossTerm, a 9-point stencil (diagonal
// filled): the 5-point's links below become the axial part of the texel's
// metric tensor and the diagonals carry its cross term, isotropic on sheared
// texels; the derivation, its cap and its limits are in surface_weights.cpp.
// Without crossTerm, the 5-point weights below.
//
// With correction, a finite-volume Laplacian on the surface: texel i is a cell
// of area |Ju x Jv| (world) * unitsPerWorld^2, and between i and its neighbour
// j the flux coefficient is c_ij = l_ij / d_ij, with d_ij the distance between
// the two texel centres on the surface (the chord; texels are small) and l_ij
// the length of the face they share: the mean of the two texels' widths
// across the step, each in its own frame (area / |Ju| for a step along u,
// area / |Jv| along v: |Jv| and |Ju| on a rectangular texel; on a sheared
// one the perpendicular width, which makes the stencil's effective diffusion
// tensor have trace 2 as on a square grid, spreading a blob at the right
// rate on average; a 5-point stencil cannot be isotropic on a sheared texel,
// its tensor has eigenvalues 1 +- cos(angle between Ju and Jv)). c_ij is
// dimensionless, so only the area carries the units:
// coefficients[i][d] = c_ij / area_i. c_ij is computed once per pair, so the
// flux is exactly symmetric and diffusion conserves sum(area * u).
// Without correction: c_ij = 1 and area = h^2 for every texel, h^2 the mean
// texel area (model units), as if the surface were a flat grid of squares.
// featureScale f multiplies c_ij by f_i * f_j (the geometric mean of the two
// texels' rates f^2).
// A step into an unglued tile edge (an open boundary) has coefficient 0: zero
// flux. Degenerate texels are guarded: an area below kFloorArea of the
// surface's median texel area, and a centre distance below kFloorDistance of
// the median texel width, count as that floor. The few texels folded or squeezed where a
// simplified triangle spans a smaller feature would otherwise force a time
// step hundreds of times smaller; with the floors the largest coefficient sum
// stayed within some 20x the median on the sample meshes, and since the tiles'
// triangles are evened out (docs/tile_quality.md) within 4-8x (without a
// curvature scale; the floors are then rarely reached). The floored values
// serve both sides of a pair, so conservation holds. Unused cells get zeros.
// Throws InputError if unitsPerWorld is not positive and finite, or if
// featureScale has the wrong size or a value that is not positive and finite.
AtlasWeights surfaceWeights(const SurfaceTiles& tiles, const SurfaceWeightOptions& options);

// The feature size factor for curvature-scaled patterns (Lo section 5.2):
//     f = 1 / (1 + strength * |H| / median |H|)
// per used texel (H the mean curvature, the median over used texels), 1 for
// unused cells and everywhere when the median is 0 (a flat surface). Features
// shrink where the surface bends more than it typically does: at strength 1
// a texel of median curvature gets half the size of a flat one. strength 0
// gives all ones. Throws InputError for a strength outside 0 to
// kMaxSurfaceScaleStrength (core/base/limits.hpp).
std::vector<float> curvatureScale(const SurfaceTiles& tiles, double strength);

} // namespace morphogen
