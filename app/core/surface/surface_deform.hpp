#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/base/state.hpp"
#include "core/sim/local_relax.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/surface_setup.hpp"
#include "core/surface/surface_weights.hpp"

namespace morphogen {

// Deformation-aware reaction-diffusion (Lo et al. section 5.5): the surface
// moves, the atlas's texels move with it (they are points of the surface, not
// of space), so the metric of the deformed tiles changes; the weights are
// recomputed and the pattern re-grows there with localized RD.

// A stretch of the slab |(p - centre) . direction| <= radius by `factor` along
// `direction`: inside, p -> centre + A (p - centre) with A = I + (factor - 1)
// d d^T; outside, the two halves move rigidly (by +-(factor - 1) radius d), so
// the map is continuous and tiles outside the slab keep their shape.
struct SlabStretch {
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    float radius = 1;
    Eigen::Vector3f direction = Eigen::Vector3f::UnitX(); // normalised by stretchSurface
    float factor = 2;

    Eigen::Vector3f apply(const Eigen::Vector3f& p) const;
};

// Moves the full mesh and the tiles' geometry by the stretch: positions
// (mesh vertices, simplified mesh, quad corners, texel corners and centres)
// through the map; each texel's Jacobian and area recomputed from its moved
// corners as computeSurfaceGeometry does (central differences), normals
// through A^-T. Mean curvature is left as it was (only a curvature-scaled
// pattern reads it, and it is not re-derived here). Only tiles with a texel
// corner in the slab change shape; the others are translated. Returns those
// tiles (A0 of the re-growth), ascending. Throws InputError for a non-finite
// centre, a radius or factor that is not positive and finite, or a zero
// direction.
std::vector<int> stretchSurface(SurfaceTiles& tiles, TriangleMesh& full,
                                const SlabStretch& stretch);

struct DeformResult {
    std::vector<int> deformed; // tiles whose shape changed (A0)
    RelaxResult relax;
    State state; // the re-grown pattern
};

// Stretches setup's surface, recomputes its weights (same unitsPerWorld,
// metric correction and feature scale as `options`), sets `session` to run
// with them (useAtlas) and re-grows `state` from the deformed tiles with
// localized RD on a simulator from `make` (a rebuilt simulator takes the new
// weights, on either backend). growEvery: steps per phase of the active set
// (0: iterationsToCrossTile, Lo's m).
DeformResult deformAndRegrow(Session& session, SurfaceSetup& setup,
                             const SurfaceWeightOptions& options, const SlabStretch& stretch,
                             const SimulatorFactory& make, const State& state,
                             const RelaxOptions& relax = {}, int growEvery = 0);

} // namespace morphogen
