#pragma once

#include <array>

#include "core/domain/atlas_weights.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// Water drops running down a model (Lo et al. section 5.6): the AtlasDrift of
// gravity `direction` (object space, any length) at `strength` model units per
// unit time, for the texel areas of `weights` (surfaceWeights' of the same
// tiles: the drift then conserves what diffusion does).
//
// Lo biases the diffusion between neighbours i, j by g . v_ij. Here the
// velocity is g's projection on the surface at `strength`, v = s P g, and a
// texel passes what that velocity carries across each of its four faces,
// upwind. In a texel's frame, J = [Ju Jv] in model units per texel step, the
// velocity in texel steps per unit time is w = (J^T J)^-1 J^T v = s (J^T J)^-1
// J^T g (J^T n = 0, so the normal part of g drops out): the texel passes the
// fraction max(0, w_u) of its amount per unit time across its +u face,
// max(0, -w_u) across its -u face, and likewise along v. On a flat grid of unit
// squares that is addGravityDrift's kernel (gravity.hpp). Nothing crosses an
// open edge (the water stops there), and a component is capped at `strength`
// over the weights' smallest texel distance, so a squeezed texel cannot force
// a tiny step. Throws InputError for a zero or non-finite direction, a
// negative or non-finite strength or units.
AtlasDrift surfaceDrift(const SurfaceTiles& tiles, const AtlasWeights& weights,
                        const std::array<double, 3>& direction, double strength,
                        double unitsPerWorld);

} // namespace morphogen
