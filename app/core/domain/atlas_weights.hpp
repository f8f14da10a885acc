#pragma once

#include <array>
#include <vector>

namespace morphogen {

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

} // namespace morphogen
