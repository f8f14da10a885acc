#pragma once

#include <array>
#include <memory>
#include <vector>

namespace morphogen {

class Atlas;

// Per-texel diffusion weights on an atlas (Lo et al. section 3, Witkin & Kass
// eq. 8): the 5-point Laplacian of a texel i becomes
//
//     lap(u)_i = sum over d of coefficients[i][d] * (u[neighbour(i, d)] - u[i])
//
// in model units^-2, d in Direction order (+x, +y, -x, -y of i's tile frame).
// A plain unit grid has every coefficient 1. The weights come from the surface
// (core/surface): the flux between i and its neighbour j is the same seen from
// both sides, coefficients[i][d] * area[i] == coefficients[j][back] * area[j],
// so diffusion conserves sum_i area[i] * u[i] (the amount on the surface).
//
// Optionally a 9-point stencil: `diagonal` adds, per texel, four links to its
// diagonals (atlas_diagonals.hpp's slot order: (-x,-y), (+x,-y), (-x,+y),
// (+x,+y) of i's frame, reached x then y):
//
//     lap(u)_i += sum over s of diagonal[i][s] * (u[diagonal(i, s)] - u[i])
//
// with the same pair symmetry (diagonal[i][s] * area[i] == diagonal[j][s'] *
// area[j], s' j's slot that reaches i). A diagonal coefficient is non-zero only
// where both orders of the walk reach the same texel (everywhere but at a tile
// corner of valence != 4, see Atlas::walk), so one order's index map serves.
// What it is for: the cross term of the Laplace-Beltrami operator on sheared
// texels (core/surface/surface_weights.hpp).
//
// Optionally, for anisotropic diffusion on a surface, `tensor`: the operators
// div(Q grad u) of two traceless tangent tensor fields (AtlasTensorWeights).
struct AtlasTensorWeights;
struct AtlasDrift;
struct AtlasWeights {
    std::vector<std::array<float, 4>> coefficients; // per atlas cell; 0 for unused cells
    std::vector<float> area;                        // per atlas cell, units^2; 0 for unused cells
    // Empty (the 5-point stencil) or per atlas cell; 0 for unused cells.
    std::vector<std::array<float, 4>> diagonal;
    std::shared_ptr<const AtlasTensorWeights> tensor; // null: isotropic only
    std::shared_ptr<const AtlasDrift> drift;          // null: no gravity

    bool hasDiagonals() const { return !diagonal.empty(); }
};

// The anisotropic part of diffusion on a surface (core/surface/surface_tensor.hpp):
// for a direction field e with f = n x e, the traceless tangent tensors
// Q1 = e e^T - f f^T and Q2 = e f^T + f e^T (their eigenvalues +-|e|^2, |e| <= 1).
// A Witkin-Kass tensor A = a1^2 v v^T + a2^2 w w^T with v at angle theta from e is
//     A = (a1^2 + a2^2) / 2 P + (a1^2 - a2^2) / 2 (cos 2theta Q1 + sin 2theta Q2),
// P the tangent plane's identity (the isotropic weights above), so every chemical
// runs p lap + q1 L1 + q2 L2 with its own three numbers over these shared weights.
// field[k] is L_{k+1}: its links (Direction order) and its four diagonals (slot
// order), with the flux of each pair the same from both sides (area-weighted, as
// AtlasWeights), so diffusion conserves sum(area u). Unlike the isotropic weights
// they are signed: a traceless tensor has a negative direction. Every diagonal is
// set (the centred cross derivative), 0 where a diagonal is not one texel.
struct AtlasTensorWeights {
    struct Field {
        std::vector<std::array<float, 4>> links;     // per atlas cell
        std::vector<std::array<float, 4>> diagonals; // per atlas cell
    };
    std::array<Field, 2> field;
};

// Water drops running downhill on a surface (Lo et al. section 5.6; built by
// core/surface/surface_drift.hpp): a first-order upwind drift along the four
// links, the same for every chemical that diffuses, added to its diffusion:
//
//     drift(u)_i = sum over d of inflow[i][d] * u[neighbour(i, d)] - outflow[i] * u[i]
//
// per unit time, d in Direction order. Texel j passes the fraction a_jd per unit
// time of its amount across its link d (outflow[j] = sum_d a_jd); what reaches
// i arrives per i's area: inflow[i][d] = area[j] a_j,back / area[i]. So drift
// conserves sum(area u), like the weights, and keeps every value >= 0 (upwind)
// while dt * outflow <= 1. Unlike the weights, inflow is not outflow's mirror:
// where the flow converges (the bottom of a sphere) a texel gains more than it
// loses.
struct AtlasDrift {
    std::vector<std::array<float, 4>> inflow; // per atlas cell
    std::vector<float> outflow;               // per atlas cell
};

// The drift's part of the bound on the step's spectral radius (0 without
// drift), the smaller of two Gershgorin bounds of the same matrix:
// - rows: a texel's disc has its outflow plus its inflow coefficients, which
//   overstate it where the flow converges on a small texel (its inflow is the
//   neighbours' outflow times their area over its own: up to 20x on
//   simplified meshes): the largest outflow + inflow sum;
// - area-weighted columns (D M D^-1, D = diag(area)): each column of the
//   drift has -outflow[j] on its diagonal and +outflow[j] off it (what leaves
//   j arrives elsewhere), as the diffusion's columns have their weight sums:
//   twice the largest outflow. Explicit Euler is also positive while dt times
//   a texel's diffusion sum plus its outflow stays at most 1.
double driftSpectralBound(const AtlasWeights& weights);

// Throws InputError unless `weights` fits `atlas`: one entry per atlas cell in
// both vectors (and in `diagonal` unless it is empty), every coefficient and
// area finite and >= 0, and a diagonal coefficient non-zero only where the two
// orders of its diagonal reach the same texel (see AtlasWeights). Non-negative
// diagonals keep the stencil monotone (an M-matrix: no new extrema, so the
// clamps stay inactive for pure diffusion) and maxCoefficientSum a plain sum.
void checkAtlasWeights(const Atlas& atlas, const AtlasWeights& weights);
// Only the sizes (constant time, for every Domain made from a session).
void checkAtlasWeightSizes(const Atlas& atlas, const AtlasWeights& weights);

// Every used texel's four coefficients `coefficient` and area 1 (unused: 0):
// the unweighted atlas.
AtlasWeights uniformAtlasWeights(const Atlas& atlas, float coefficient = 1.0f);

// max over texels of the sum of its four coefficients plus its four diagonal
// ones, if any (4 on a unit grid; absolute values, for safety). The
// explicit step of pure diffusion is stable for dt * rate * maxCoefficientSum
// <= 1, the unit grid's dt * rate * 4 <= 1 with 4 replaced by this sum
// (Gershgorin: |lambda| <= 2 * rate * sum at the worst texel; the operator is
// similar to a symmetric one through the areas, so its spectrum is real).
float maxCoefficientSum(const AtlasWeights& weights);

// `weights` with every texel's coefficient sum (as maxCoefficientSum counts
// it) at most `limit`: a texel above it has its links and diagonals scaled
// by limit / sum and its area by sum / limit, so every pair's flux, and the
// amount sum(area u), stay as they were (the texel's neighbours' coefficients
// towards it are untouched) -- the floors of surface_weights.hpp for a texel
// squeezed after the weights were made (a deformation in a running session,
// whose substeps are fixed). The pattern in such a texel diffuses by up to
// that factor more slowly than its metric says. `capped`: how many changed;
// `smallest`: the smallest scale applied (1 when none).
AtlasWeights capCoefficientSums(const AtlasWeights& weights, float limit, int* capped = nullptr,
                                float* smallest = nullptr);

// Explicit steps per session step on a weighted atlas: ceil(maxCoefficientSum
// / 4) when above 4 (as ceil(1 / h^2) on a grid finer than one unit), else 1.
int weightedSubsteps(const AtlasWeights& weights);

// A Witkin-Kass tensor (theta in degrees from the field's direction, a1 along,
// a2 across) at diffusion rate `rate` as the three numbers AtlasTensorWeights
// mixes: rate (a1^2 + a2^2) / 2, rate (a1^2 - a2^2) / 2 cos 2theta, ... sin 2theta.
std::array<float, 3> tensorMix(double theta, double a1, double a2, double rate);

// With anisotropy (weights.tensor): the largest sum over a texel of the
// absolute values of its links and diagonals combined by `mix` (p lap + q1 L1 +
// q2 L2): that operator's Gershgorin bound is twice this.
double maxTensorSum(const AtlasWeights& weights, const std::array<float, 3>& mix);
// With anisotropy (weights.tensor): for each (p, q1, q2) of `mixes` (a
// chemical's operator p lap + q1 L1 + q2 L2, p > 0), the largest sum over a
// texel of the absolute values of its combined links and diagonals, over 4p:
// the step's limit relative to a unit grid diffusing at rate p (4 p the grid's
// sum; the session's dt is chosen for its grid). The largest over `mixes`.
double maxTensorSumRatio(const AtlasWeights& weights,
                         const std::vector<std::array<float, 3>>& mixes);
// The substeps for it: ceil of that ratio when above 1, else 1.
int tensorSubsteps(const AtlasWeights& weights, const std::vector<std::array<float, 3>>& mixes);

// The weights as four planes (structure of arrays, cell-major inside a plane):
// plane d holds coefficients[i][d] at i. What the CPU kernels stream.
std::vector<float> coefficientPlanes(const AtlasWeights& weights);

// The weights as RGBA per texel (+x, +y, -x, -y): the GPU's RGBA32F texture.
std::vector<float> coefficientTexels(const AtlasWeights& weights);

// The diagonal coefficients as four planes (slot order, as coefficientPlanes)
// and as RGBA per texel (the GPU's second RGBA32F texture). Empty when the
// weights have no diagonals.
std::vector<float> diagonalPlanes(const AtlasWeights& weights);
std::vector<float> diagonalTexels(const AtlasWeights& weights);

// The drift as five planes (inflow +x, +y, -x, -y, then outflow; as
// coefficientPlanes), and as the GPU's textures: inflow RGBA per texel, outflow
// one float per texel. Empty without drift.
std::vector<float> driftPlanes(const AtlasWeights& weights);
std::vector<float> driftInflowTexels(const AtlasWeights& weights);
std::vector<float> driftOutflowTexels(const AtlasWeights& weights);

// The tensor weights as 16 planes: L1's four links, L1's four diagonals, then
// L2's (as coefficientPlanes); and as four RGBA textures' texels in that order.
std::vector<float> tensorPlanes(const AtlasTensorWeights& tensor);
std::array<std::vector<float>, 4> tensorTexels(const AtlasTensorWeights& tensor);

} // namespace morphogen
