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
//
// With a `reach`, the stretch is local: it acts in full within `reach` of the
// axis (the line through the centre along the direction) and fades to nothing
// over fadeWidth() beyond (a smoothstep of the distance rho from the axis),
// so the model further out stays where it was, as a brush-sized stretch
// should. The fade is at least `reach` wide and wider for strong factors,
// 1.5 |factor - 1| radius, which keeps the shear where it fades (up to
// 1.5 |factor - 1| radius / width) at most 1. A shear squeezes texels across
// its diagonal (by 1.6x at 1), which raises the explicit step's substeps; a
// running session's texels squeezed past its substeps take the weights'
// floor (capCoefficientSums, SessionRun). Measured on the torus preset (8
// substeps, brush radius 0.12 of the model): with a brush-wide fade a 4x
// stretch needed 17 substeps; with this one 2x, 2.5x and 4x all run. The map is
// p + g(p) d with g = (factor - 1) clamp(t, -radius, radius) w(rho); because
// w depends only on the distance from the axis, grad w is across d and the
// Jacobian I + d grad(g)^T has determinant 1 + (factor - 1) w (inside the
// slab) or 1 (outside): positive for every factor > 0, so the surface never
// folds, however hard it is stretched or compressed. Where w fades the
// surface shears (that ring of tiles changes shape too).
struct SlabStretch {
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    float radius = 1;
    Eigen::Vector3f direction = Eigen::Vector3f::UnitX(); // normalised by stretchSurface
    float factor = 2;
    float reach = 0; // 0: the whole slab, across the model

    Eigen::Vector3f apply(const Eigen::Vector3f& p) const;
    // A point with its normal through the map: where it goes, the normal
    // J^-T n (normalised), and whether the map changes shapes there (its
    // Jacobian is not I).
    struct Moved {
        Eigen::Vector3f position, normal;
        bool deforms = false;
    };
    Moved move(const Eigen::Vector3f& p, const Eigen::Vector3f& n) const;
    // How far beyond the reach the stretch fades out (reach > 0).
    float fadeWidth() const;

private:
    // w(rho) and dw/drho at p, and the unit vector away from the axis.
    struct Fade {
        float w = 1, slope = 0;
        Eigen::Vector3f away = Eigen::Vector3f::Zero();
    };
    Fade fade(const Eigen::Vector3f& p) const;
};

// Moves the full mesh and the tiles' geometry by the stretch: positions
// (mesh vertices, simplified mesh, quad corners, texel corners and centres)
// through the map; each texel's Jacobian and area recomputed from its moved
// corners as computeSurfaceGeometry does (central differences), normals
// through A^-T. Mean curvature is left as it was (only a curvature-scaled
// pattern reads it, and it is not re-derived here). Only tiles with a texel
// corner in the slab change shape; the others are translated. Returns those
// tiles (A0 of the re-growth), ascending. Throws InputError for a non-finite
// centre, a radius or factor that is not positive and finite, a reach that
// is negative or not finite, or a zero direction.
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
