#pragma once
// Sessions and states on atlas domains, shared by the CPU and GPU atlas tests.

#include <memory>
#include <vector>

#include "core/base/state.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/session/session.hpp"

namespace morphogen::test {

// gs_coral on an atlas: Gray-Scott at the preset's F and k, isotropic diffusion.
Session atlasSession(std::shared_ptr<const Atlas> atlas, Stencil stencil = Stencil::FivePoint);

// Pure diffusion of u: Gray-Scott with F = k = 0 and v = 0 everywhere has no
// reaction at all (du = -u v^2 + F (1 - u), dv = u v^2 - (F + k) v).
Session pureDiffusionSession(std::shared_ptr<const Atlas> atlas,
                             Stencil stencil = Stencil::FivePoint);

// u random in [0, 1] on used texels (v = 0), and a marker value on unused ones.
State randomUsedState(const Atlas& atlas, unsigned seed);

// Sum of chemical c over the atlas's used texels, in double.
double usedSum(const State& s, const Atlas& atlas, int c);

// Whether every value of every chemical of tile `tile` is the same in a and b
// (bit for bit: what localized steps promise the tiles they leave alone).
bool tileEqual(const State& a, const State& b, const Atlas& atlas, int tile);

// The three texels at corner 0 of tile `tile` (its corner texel and the two
// corner texels one step across its -x and -y edges).
std::vector<std::uint32_t> cornerTexels(const Atlas& atlas, int tile);

// Non-uniform but flux-symmetric weights: a random area in [0.8, 1.25] per
// used texel and a random conductance K in [0.6, 1] per glued pair of
// neighbours, each side's coefficient K / its area (so c_ij a_i == c_ji a_j
// up to float rounding, and every coefficient is at most 1.25: sums <= 5, in
// gs_coral's explicit limit). Zero-flux links (a step that stays put) get 1.
AtlasWeights symmetricWeights(const Atlas& atlas, unsigned seed);
// symmetricWeights with a 9-point stencil: the axis coefficients halved and a
// random conductance in [0.3, 0.5] on every diagonal pair that has one
// (diagonalMirrors), each side's coefficient K / its area (sums <= 5 still).
AtlasWeights symmetricNinePointWeights(const Atlas& atlas, unsigned seed);

// Sum of area * chemical c over the used texels, in double.
double areaWeightedSum(const State& s, const Atlas& atlas, const AtlasWeights& weights, int c);

} // namespace morphogen::test
