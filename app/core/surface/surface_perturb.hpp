#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/sim/brush.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// A local disturbance of a pattern on a surface (Lo et al. section 5.3): the
// texels within `radius` (world units, straight-line distance from the texel
// centres, which for radii small against the curvature is the surface
// distance) of a world-space point, and the tiles they lie in (A0 of
// localized reaction-diffusion).
struct SurfacePerturbation {
    Brush brush;              // the write; its region holds the texels
    std::vector<int> touched; // A0, ascending
};

// Randomises chemical `chemical` by +-value (Lo's distort) in the ball of
// `radius` round `centre`. Throws InputError naming `what` (the flag or field)
// for a non-finite centre, a radius that is not positive and finite, or a ball
// that holds no texel (the message gives the mesh's bounding box).
SurfacePerturbation perturbSurface(const SurfaceTiles& tiles, const Domain& domain,
                                   const Eigen::Vector3f& centre, float radius, int chemical,
                                   float value, std::uint64_t seed,
                                   const char* what = "perturbation");

// Lo's distort adds noise to what is there: a spot under it stays a spot
// (on a Turing pattern +-2 of one chemical barely moves the other). These
// brushes set every chemical in the perturbation's region to its mean there
// first, so the features it covers are erased and only the noise seeds them
// again. `state`: the finished pattern the region lies in, of which the
// first `chemicals` planes are the model's chemicals.
std::vector<Brush> erasingBrushes(const SurfacePerturbation& perturbation, const State& state,
                                  int chemicals);

} // namespace morphogen
