#pragma once

#include <array>
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
struct AtlasWeights {
    std::vector<std::array<float, 4>> coefficients; // per atlas cell; 0 for unused cells
    std::vector<float> area;                        // per atlas cell, units^2; 0 for unused cells
};

// Throws InputError unless `weights` fits `atlas`: one entry per atlas cell in
// both vectors, every coefficient and area finite and >= 0.
void checkAtlasWeights(const Atlas& atlas, const AtlasWeights& weights);
// Only the sizes (constant time, for every Domain made from a session).
void checkAtlasWeightSizes(const Atlas& atlas, const AtlasWeights& weights);

// Every used texel's four coefficients `coefficient` and area 1 (unused: 0):
// the unweighted atlas.
AtlasWeights uniformAtlasWeights(const Atlas& atlas, float coefficient = 1.0f);

// max over texels of the sum of its four coefficients (4 on a unit grid). The
// explicit step of pure diffusion is stable for dt * rate * maxCoefficientSum
// <= 1, the unit grid's dt * rate * 4 <= 1 with 4 replaced by this sum
// (Gershgorin: |lambda| <= 2 * rate * sum at the worst texel; the operator is
// similar to a symmetric one through the areas, so its spectrum is real).
float maxCoefficientSum(const AtlasWeights& weights);

// Explicit steps per session step on a weighted atlas: ceil(maxCoefficientSum
// / 4) when above 4 (as ceil(1 / h^2) on a grid finer than one unit), else 1.
int weightedSubsteps(const AtlasWeights& weights);

// The weights as four planes (structure of arrays, cell-major inside a plane):
// plane d holds coefficients[i][d] at i. What the CPU kernels stream.
std::vector<float> coefficientPlanes(const AtlasWeights& weights);

// The weights as RGBA per texel (+x, +y, -x, -y): the GPU's RGBA32F texture.
std::vector<float> coefficientTexels(const AtlasWeights& weights);

} // namespace morphogen
