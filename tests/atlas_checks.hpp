#pragma once
// Sessions and states on atlas domains, shared by the CPU and GPU atlas tests.

#include <memory>
#include <vector>

#include "core/base/state.hpp"
#include "core/domain/atlas.hpp"
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

// The three texels at corner 0 of tile `tile` (its corner texel and the two
// corner texels one step across its -x and -y edges).
std::vector<std::uint32_t> cornerTexels(const Atlas& atlas, int tile);

} // namespace morphogen::test
