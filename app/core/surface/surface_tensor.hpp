#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/domain/atlas_weights.hpp"
#include "core/session/surface_spec.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// A direction field on the tiled surface (SurfaceDirection), per atlas cell:
// the unit tangent e at the texel (world units, zero on unused cells) and the
// anisotropy's strength there in [0, 1]. The strength fades to 0 where the
// direction is undefined: for "along", where the axis is within 30 degrees of
// the normal (strength = sin(angle) / sin(30 degrees), capped at 1); for
// "around", the same for the circle's tangent, times the distance from the
// axis over a tenth of the model's bounding radius (capped at 1), so the pole
// of a sphere and the points on the axis are isotropic, with no seam.
struct SurfaceDirectionField {
    std::vector<Eigen::Vector3f> direction;
    std::vector<float> strength;
};
SurfaceDirectionField surfaceDirectionField(const SurfaceTiles& tiles,
                                            const SurfaceDirection& direction);

// The anisotropic weights (AtlasTensorWeights) of the direction field: the
// operators L_k u = div(s Q_k grad u) on the surface, s the field's strength,
// Q1 = e e^T - f f^T, Q2 = e f^T + f e^T, f = n x e (n the outward normal).
//
// Derivation (as the isotropic one in surface_weights.cpp): in a texel's (u, v)
// frame with J = [Ju Jv] (model units per texel step), a tangent tensor T acts
// as K = A J+ T J+^T, J+ = g^-1 J^T the pseudo-inverse (world to texel steps),
// A the texel's area (the isotropic weights' floored area), so that
// (1/A) d_a(K^ab d_b u) = div(T grad u); T = P gives the isotropic K = A g^-1.
// For Q: K = A (pe pe^T - pf pf^T) and A (pe pf^T + pf pe^T), pe = J+ s^(1/2) e,
// pf = J+ s^(1/2) f. The stencil is the centred 9-point form, linear in K (the
// isotropic weights' one-sided form is not, and a traceless K has no sign to
// choose it by): K_uu on the +-u links, K_vv on the +-v links, and
// sx sy K_uv / 2 on the diagonal (sx, sy); its second moment is 2K, so it is
// exact for quadratics on a flat sheet. Pair fluxes average the two texels'
// wishes, each in its own frame (a link's wish is d^T K d for its step d,
// less the axial part on a diagonal: frame-independent across a rotated tile
// edge), times the feature scale f_i f_j if any, over the texel's area: the
// flux is one number per pair, so mass is conserved. A diagonal that is not one
// texel (an irregular tile corner, an open edge) carries nothing: those
// texels lose the cross derivative, as the isotropic stencil does there.
// Degenerate texels: K is scaled down so its trace stays within the isotropic
// stencil's (floored) one; by construction -K_P <= K_Q <= K_P otherwise.
// isotropicOut (may be null) receives the isotropic part to run with it: per
// texel, K = A g^-1 in the same centred 9-point form (signed diagonals) where
// that costs at most 2x the finite-volume stencil's sum (`isotropic`), else the
// finite-volume fluxes with the texel's anisotropy dropped. An anisotropic
// session's p S must be this one: mixing the J-based tensor part with the
// finite-volume stencil (they differ on sheared texels, which the latter
// blends towards the 5-point for its time step) let p S + q L grow by itself
// (wk_zebra, a1/a2 = 2, on the sphere, blob and holes).
// `isotropic` gives the floored areas; featureScale may be null.
AtlasTensorWeights surfaceTensorWeights(const SurfaceTiles& tiles, const AtlasWeights& isotropic,
                                        const SurfaceDirection& direction, double unitsPerWorld,
                                        const std::vector<float>* featureScale,
                                        AtlasTensorWeights::Field* isotropicOut = nullptr);

} // namespace morphogen
