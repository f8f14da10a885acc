#include "core/surface/surface_weights.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/domain/atlas_diagonals.hpp"
#include "core/surface/surface_drift.hpp"
#include "core/surface/surface_tensor.hpp"

namespace morphogen {

namespace {

// The cross term's cap, a fraction of the smaller axial conductance (see the
// derivation in surfaceWeights): every axis link keeps at least a tenth of it.
constexpr double kCrossCap = 0.9;
// A texel's weight sum with the cross term is held within this factor of its
// 5-point sum, and within the surface's largest 5-point sum or this factor of
// the median one (see surfaceWeights).
// Measured on the sample meshes (surface_curvature_spots_holes, 4x4 tiles):
// the substeps stay 22 (holes), 11 (torus), 16 (blob, 15 without the cross
// term) and 3 (sphere, 2 without); with the better-shaped tiles of issue #11
// (docs/tile_quality.md) 9, 4, 6 and 2 with the cross term.
constexpr double kCrossGrowth = 2.0;

double median(std::vector<double> v) {
    if (v.empty())
        return 0;
    const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

Eigen::Matrix<double, 3, 2> texelJacobian(const SurfaceTiles& tiles, std::uint32_t cell,
                                          double unitsPerWorld) {
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) = tiles.jacobianU[cell].cast<double>() * unitsPerWorld;
    J.col(1) = tiles.jacobianV[cell].cast<double>() * unitsPerWorld;
    return J;
}

TexelFloors texelFloors(const SurfaceTiles& tiles, double unitsPerWorld) {
    const Atlas& atlas = *tiles.atlas;
    std::vector<double> areas;
    areas.reserve(atlas.cellCount());
    double areaSum = 0;
    for (std::size_t c = 0; c < atlas.cellCount(); ++c)
        if (atlas.used(std::uint32_t(c))) {
            const double a = double(tiles.texelArea[c]) * unitsPerWorld * unitsPerWorld;
            areas.push_back(a);
            areaSum += a;
        }
    TexelFloors floors;
    floors.meanArea = areas.empty() ? 1.0 : areaSum / double(areas.size());
    const double medianArea = median(std::move(areas));
    floors.minArea = kFloorArea * medianArea;
    floors.minDistance = kFloorDistance * std::sqrt(medianArea);
    return floors;
}

AtlasWeights surfaceWeights(const SurfaceTiles& tiles, const SurfaceWeightOptions& options) {
    const Atlas& atlas = *tiles.atlas;
    const std::size_t cells = atlas.cellCount();
    const double scale = options.unitsPerWorld;
    if (!(scale > 0) || !std::isfinite(scale))
        throw InputError("surface weights: units per world unit " + std::to_string(scale) +
                         " must be positive and finite");
    const std::vector<float>* f = options.featureScale;
    if (f) {
        if (f->size() != cells)
            throw InputError("surface weights: the feature scale has " + std::to_string(f->size()) +
                             " values; the atlas has " + std::to_string(cells) + " cells");
        for (std::size_t c = 0; c < cells; ++c)
            if (atlas.used(std::uint32_t(c)) && !((*f)[c] > 0 && std::isfinite((*f)[c])))
                throw InputError("surface weights: feature scale " + std::to_string((*f)[c]) +
                                 " at cell " + std::to_string(c) + " must be positive and finite");
    }

    const TexelFloors floors = texelFloors(tiles, scale);
    const double minArea = floors.minArea, minDistance = floors.minDistance;
    const double meanArea = floors.meanArea;

    AtlasWeights w;
    w.coefficients.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
    w.area.assign(cells, 0.0f);
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c)))
            w.area[c] = float(options.metricCorrection
                                  ? std::max(double(tiles.texelArea[c]) * scale * scale, minArea)
                                  : meanArea);

    // The length of texel c along a step in direction d of its own frame, and its width
    // across the step, in model units: its area over its length along the step (|Jv| for a u-step
    // when the frame is orthogonal; less on a sheared texel, which keeps the stencil's spread rate
    // that of the surface: trace 2 of its effective diffusion tensor, as on a square grid).
    const auto length = [&](std::uint32_t c, int d) {
        const Eigen::Vector3f& along = (d % 2 == 0) ? tiles.jacobianU[c] : tiles.jacobianV[c];
        return std::max(double(along.norm()) * scale, minDistance);
    };
    const auto width = [&](std::uint32_t c, int d) {
        return std::max(double(tiles.texelArea[c]) * scale * scale, minArea) / length(c, d);
    };

    // The cross term (the 9-point stencil). In a texel's (u, v) frame, with g = J^T J
    // (J = [Ju Jv], model units per texel step), the Laplace-Beltrami operator is
    //     lap f = (1 / sqrt|g|) d_a (K^ab d_b f),   K = sqrt|g| g^-1
    //           = (1 / A) d_a (K^ab d_b f),         A = sqrt|g| the texel's area,
    //     K = [[G, -F], [-F, E]] / A,  E = Ju.Ju, F = Ju.Jv, G = Jv.Jv.
    // K is dimensionless and positive definite: a finite-volume Laplacian is (1/A_i)
    // times a sum of fluxes K (u_j - u_i) over texel pairs, each flux computed once
    // for the pair, which conserves sum(A u) and makes the operator symmetric in the
    // area inner product (real spectrum, Gershgorin bound as the 5-point's). The
    // 5-point stencil has no d_u d_v: it can only hold K_uu and K_vv, so the surface
    // weights below used to settle for a diagonal tensor of the right trace.
    // The mixed derivative, with s = sign(K_uv) and the diagonal (1, s):
    //     f(+1,+s) + f(-1,-s) - 2 f = f_uu + 2 s f_uv + f_vv + O(h^4),
    // so 2 K_uv f_uv = |K_uv| [(f(+1,+s) - f) + (f(-1,-s) - f)] - |K_uv| (d_uu + d_vv),
    // i.e. the cross term is the flux |K_uv| on the two diagonals along (1, s) and
    // -|K_uv| on the four axis links. The texel's stencil becomes
    //     axis u: K_uu - |K_uv|,  axis v: K_vv - |K_uv|,  diagonals (1, s): |K_uv|,
    // exact for quadratics (its second moment is 2K: the spread in world units is
    // J 2K/A J^T = 2 J g^-1 J^T = 2 P, the tangent plane's identity, isotropic).
    // Every weight is >= 0 when |K_uv| <= min(K_uu, K_vv), i.e. |Ju.Jv| <= min(|Ju|^2,
    // |Jv|^2): true for a kite of an equilateral triangle (60 / 90 / 120 degrees, its
    // sides 1 : 1/sqrt(3) at the worst), so the stencil is monotone (an M-matrix: no
    // new extrema, the clamps unaffected) and its stability bound is the plain sum of
    // its weights. This form needs only two of the four diagonals, and on a texel
    // sheared at 60 degrees its centre weight 2(K_uu + K_vv) - 2|K_uv| equals the
    // trace-2 5-point's (4 sin 60 = 3 / sin 60): no extra substeps. (The centred form,
    // +-K_uv / 2 on all four diagonals, has negative weights: not monotone, and a
    // larger Gershgorin bound.) |K_uv| is capped at kCrossCap min(K_uu, K_vv), so
    // every axis link keeps some flux (a right isosceles triangle's kite, 45 degrees
    // between sides 1 : sqrt(2), is exactly at the bound); a texel sheared or stretched
    // past the cap keeps the 5-point stencil's anisotropy in proportion to the excess
    // (skinny simplified triangles): monotone still.
    // Where a texel lacks one of the two diagonals (a tile corner of valence != 4 on the
    // diagonal's side, an open edge; diagonalMirrors), it keeps the trace-2 5-point
    // weights: a one-texel defect at those corners.
    // The time step: a sheared texel's weights grow as 1 / sin(angle) (the 5-point's
    // shrink as sin(angle)), and the explicit step's limit is set by the largest
    // weight sum on the surface, often a squeezed texel at the floors. So a texel's
    // sum with the cross term (its own wishes, before the pair averages) is held
    // within kCrossGrowth times its 5-point sum (an angle below 33 degrees on a texel
    // of equal sides would exceed it; 45 degrees needs 1.29, 60 degrees 1) and within
    // the surface's budget: its largest 5-point sum, or kCrossGrowth times the median
    // one if more (a uniformly sheared sheet must pay for its exact operator).
    // Where the full 9-point exceeds that, the texel's stencil is the blend
    // (1 - t) 5-point + t 9-point with the largest t that fits: monotone and
    // consistent still, with the 5-point's anisotropy in proportion to 1 - t.
    // Pair fluxes average the two texels' wishes, as the axis links' widths do: the
    // axis flux is (l_i + l_j) / 2 / d_ij with l = (1 - t) width + t (K_uu - |K_uv|) |Ju|
    // for a u-link ((K_uu - |K_uv|) |Ju| is the 5-point width |Jv| on an orthogonal
    // texel), and the diagonal flux (t_i |K_uv|_i + t_j |K_uv|_j) / 2.
    std::vector<double> kappa(cells, 0.0); // t |K_uv| (|K_uv| capped); 0: the 5-point weights
    std::vector<double> blend(cells, 0.0); // t
    std::vector<std::array<double, 2>> axis(cells, {0.0, 0.0}); // K_uu, K_vv when kappa > 0
    std::vector<std::array<std::uint32_t, 8>> diagonals;
    std::vector<std::array<int, 4>> mirrors;
    const bool cross = options.metricCorrection && options.crossTerm;
    if (cross) {
        diagonals = atlasDiagonals(atlas);
        mirrors = diagonalMirrors(atlas, diagonals);
        // Per texel, the 5-point coefficient sum it asks for: 2 (1 / lu^2 + 1 / lv^2).
        const auto sum5 = [&](std::uint32_t i) {
            return 2.0 / (length(i, 0) * length(i, 0)) + 2.0 / (length(i, 1) * length(i, 1));
        };
        double budget = 0;
        std::vector<double> sums;
        for (std::uint32_t i = 0; i < cells; ++i)
            if (atlas.used(i)) {
                sums.push_back(sum5(i));
                budget = std::max(budget, sums.back());
            }
        budget = std::max(budget, kCrossGrowth * median(sums));
        for (std::uint32_t i = 0; i < cells; ++i) {
            if (!atlas.used(i))
                continue;
            const double lu = length(i, 0), lv = length(i, 1), a = w.area[i];
            const double norms = double(tiles.jacobianU[i].norm() * tiles.jacobianV[i].norm());
            const double cosine =
                norms > 0 ? double(tiles.jacobianU[i].dot(tiles.jacobianV[i])) / norms : 0.0;
            const double kuu = lv * lv / a, kvv = lu * lu / a, kuv = -cosine * lu * lv / a;
            // The two diagonals along (1, s): slots (-x,-y), (+x,+y) for s = +1, else
            // (+x,-y), (-x,+y).
            const int s0 = kuv > 0 ? 0 : 1, s1 = kuv > 0 ? 3 : 2;
            const double k = std::min(std::abs(kuv), kCrossCap * std::min(kuu, kvv));
            const auto paired = [&](int slot) {
                const int back = mirrors[i][std::size_t(slot)];
                return back >= 0 &&
                       mirrors[diagonals[i][std::size_t(slot)]][std::size_t(back)] == slot;
            };
            if (!(k > 0 && paired(s0) && paired(s1)))
                continue;
            const double five = sum5(i), nine = (2 * (kuu + kvv) - 2 * k) / a;
            const double limit = std::min(kCrossGrowth * five, budget);
            const double t = nine <= limit ? 1.0 : (limit - five) / (nine - five);
            if (t > 0) {
                blend[i] = t;
                kappa[i] = t * k;
                axis[i] = {kuu, kvv};
            }
        }
        w.diagonal.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
    }
    // What texel c asks of its slot s: kappa on the two diagonals along (1, s).
    const auto diagonalWish = [&](std::uint32_t c, int slot) {
        if (kappa[c] == 0)
            return 0.0;
        const bool along = tiles.jacobianU[c].dot(tiles.jacobianV[c]) > 0
                               ? (slot == 1 || slot == 2)
                               : (slot == 0 || slot == 3);
        return along ? kappa[c] : 0.0;
    };
    // Texel c's face length l for its link d (the 5-point width without the cross term).
    const auto face = [&](std::uint32_t c, int d) {
        if (kappa[c] == 0)
            return width(c, d);
        const double t = blend[c];
        return (1 - t) * width(c, d) + (t * axis[c][std::size_t(d % 2)] - kappa[c]) * length(c, d);
    };

    for (std::uint32_t i = 0; i < cells; ++i) {
        if (!atlas.used(i))
            continue;
        for (int d = 0; d < 4; ++d) {
            const AtlasStep s = atlas.step(i, Direction(d));
            const std::uint32_t j = s.cell;
            // j == i: an unglued edge (zero flux). j < i: set when j was visited.
            if (j <= i)
                continue;
            const int back = int(s.back);
            double c = 1.0;
            if (options.metricCorrection) {
                const double l = 0.5 * (face(i, d) + face(j, back));
                const double dist = std::max(
                    double((tiles.texelPositions[i] - tiles.texelPositions[j]).norm()) * scale,
                    minDistance);
                c = l / dist;
            }
            if (f)
                c *= double((*f)[i]) * double((*f)[j]);
            // One float flux for the pair, so area * coefficient agrees on both sides.
            const float flux = float(c);
            w.coefficients[i][d] = float(double(flux) / w.area[i]);
            w.coefficients[j][back] = float(double(flux) / w.area[j]);
        }
        if (!cross)
            continue;
        for (int slot = 0; slot < 4; ++slot) {
            const int back = mirrors[i][std::size_t(slot)];
            const std::uint32_t j = diagonals[i][std::size_t(slot)];
            if (back < 0 || j <= i || mirrors[j][std::size_t(back)] != slot)
                continue;
            double c = 0.5 * (diagonalWish(i, slot) + diagonalWish(j, back));
            if (c == 0)
                continue;
            if (f)
                c *= double((*f)[i]) * double((*f)[j]);
            const float flux = float(c);
            w.diagonal[i][std::size_t(slot)] = float(double(flux) / w.area[i]);
            w.diagonal[j][std::size_t(back)] = float(double(flux) / w.area[j]);
        }
    }
    if (options.direction) {
        if (!options.metricCorrection)
            throw InputError("surface weights: anisotropic diffusion on a surface needs the metric "
                             "correction (its directions are measured on the surface)");
        AtlasTensorWeights::Field isotropicPart;
        w.tensor = std::make_shared<const AtlasTensorWeights>(
            surfaceTensorWeights(tiles, w, *options.direction, scale, f, &isotropicPart));
        w.coefficients = std::move(isotropicPart.links);
        w.diagonal = std::move(isotropicPart.diagonals);
    }
    if (options.gravity.active())
        w.drift = std::make_shared<const AtlasDrift>(
            surfaceDrift(tiles, w, options.gravity.direction, options.gravity.strength, scale));
    return w;
}

std::vector<float> curvatureScale(const SurfaceTiles& tiles, double strength) {
    if (!(strength >= 0) || !(strength <= kMaxSurfaceScaleStrength))
        throw InputError("curvature scale: strength " + std::to_string(strength) +
                         " is out of range: 0 (no scaling) to " +
                         std::to_string(kMaxSurfaceScaleStrength));
    const Atlas& atlas = *tiles.atlas;
    const std::size_t cells = atlas.cellCount();
    std::vector<double> magnitudes;
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c)))
            magnitudes.push_back(std::abs(double(tiles.meanCurvature[c])));
    const double m = median(magnitudes);
    std::vector<float> f(cells, 1.0f);
    if (!(m > 0) || strength == 0)
        return f;
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c)))
            f[c] = float(1.0 / (1.0 + strength * std::abs(double(tiles.meanCurvature[c])) / m));
    return f;
}

} // namespace morphogen
