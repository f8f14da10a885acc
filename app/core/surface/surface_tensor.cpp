#include "core/surface/surface_tensor.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/domain/atlas_diagonals.hpp"
#include "core/surface/surface_weights.hpp"

namespace morphogen {

namespace {

// Below sin(30 degrees) between the direction and the normal's plane, the
// anisotropy fades (SurfaceDirectionField).
constexpr double kTangentFade = 0.5;
// "around": within this fraction of the bounding radius of the axis, it fades.
constexpr double kAxisFade = 0.1;

Eigen::Vector3d vec(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

} // namespace

SurfaceDirectionField surfaceDirectionField(const SurfaceTiles& tiles,
                                            const SurfaceDirection& direction) {
    const Atlas& atlas = *tiles.atlas;
    const std::size_t cells = atlas.cellCount();
    SurfaceDirectionField field;
    field.direction.assign(cells, Eigen::Vector3f::Zero());
    field.strength.assign(cells, 0.0f);
    const Eigen::Vector3d axis = vec(direction.axis).normalized();
    const Eigen::Vector3d through = vec(direction.through);
    double radius = 0;
    if (direction.type == SurfaceDirection::Type::Around) {
        Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
        for (std::size_t c = 0; c < cells; ++c)
            if (atlas.used(std::uint32_t(c))) {
                lo = lo.cwiseMin(tiles.texelPositions[c].cast<double>());
                hi = hi.cwiseMax(tiles.texelPositions[c].cast<double>());
            }
        radius = 0.5 * (hi - lo).norm();
    }
    for (std::size_t c = 0; c < cells; ++c) {
        if (!atlas.used(std::uint32_t(c)))
            continue;
        const Eigen::Vector3d n = tiles.texelNormals[c].cast<double>();
        Eigen::Vector3d d = axis;
        double fade = 1;
        if (direction.type == SurfaceDirection::Type::Around) {
            d = axis.cross(tiles.texelPositions[c].cast<double>() - through);
            const double distance = d.norm();
            fade = radius > 0 ? std::min(1.0, distance / (kAxisFade * radius)) : 0.0;
            if (!(distance > 0))
                continue;
            d /= distance;
        }
        const Eigen::Vector3d tangent = d - d.dot(n) * n;
        const double length = tangent.norm();
        if (!(length > 1e-6))
            continue;
        field.direction[c] = (tangent / length).cast<float>();
        field.strength[c] = float(fade * std::min(1.0, length / kTangentFade));
    }
    return field;
}

AtlasTensorWeights surfaceTensorWeights(const SurfaceTiles& tiles, const AtlasWeights& isotropic,
                                        const SurfaceDirection& direction, double unitsPerWorld,
                                        const std::vector<float>* featureScale,
                                        AtlasTensorWeights::Field* isotropicOut) {
    const Atlas& atlas = *tiles.atlas;
    const std::size_t cells = atlas.cellCount();
    const double scale = unitsPerWorld;
    const TexelFloors floors = texelFloors(tiles, scale);
    const SurfaceDirectionField field = surfaceDirectionField(tiles, direction);

    // Per texel, K of Q1 and Q2 in its own frame: (K_uu, K_vv, K_uv).
    // k[2]: the tangent plane's identity P, the isotropic part (no fade).
    std::array<std::vector<std::array<double, 3>>, 3> k;
    for (auto& kq : k)
        kq.assign(cells, {0.0, 0.0, 0.0});
    for (std::uint32_t i = 0; i < cells; ++i) {
        if (!atlas.used(i))
            continue;
        const Eigen::Matrix<double, 3, 2> J = texelJacobian(tiles, i, scale);
        const Eigen::Matrix2d g = J.transpose() * J;
        const double det = g.determinant();
        if (!(det > 0) || !std::isfinite(det))
            continue;
        const Eigen::Matrix<double, 2, 3> pinv = g.inverse() * J.transpose();
        const double a = isotropic.area[i];
        // The isotropic stencil's trace, with its floored lengths, bounds this one's:
        // K_P = a g^-1 has trace (|Ju|^2 + |Jv|^2) / a unless a texel is at the floors.
        const double lu = std::max(J.col(0).norm(), floors.minDistance);
        const double lv = std::max(J.col(1).norm(), floors.minDistance);
        const double shrink = std::min(1.0, (lu * lu + lv * lv) / a / (a * g.inverse()).trace());
        const double s = double(field.strength[i]) * shrink;
        const Eigen::Vector3d e = field.direction[i].cast<double>();
        const Eigen::Vector3d f = tiles.texelNormals[i].cast<double>().cross(e);
        const Eigen::Vector2d pe = pinv * e, pf = pinv * f;
        const Eigen::Matrix2d q1 = a * s * (pe * pe.transpose() - pf * pf.transpose());
        const Eigen::Matrix2d q2 = a * s * (pe * pf.transpose() + pf * pe.transpose());
        const Eigen::Matrix2d p = a * shrink * g.inverse();
        k[2][i] = {p(0, 0), p(1, 1), p(0, 1)};
        k[0][i] = {q1(0, 0), q1(1, 1), q1(0, 1)};
        k[1][i] = {q2(0, 0), q2(1, 1), q2(0, 1)};
    }

    const std::vector<std::array<std::uint32_t, 8>> diagonals = atlasDiagonals(atlas);
    const std::vector<std::array<int, 4>> mirrors = diagonalMirrors(atlas, diagonals);
    // Slot s of atlas_diagonals.hpp: (-x,-y), (+x,-y), (-x,+y), (+x,+y): sx sy.
    const auto slotSign = [](int slot) {
        return ((slot & 1) ? 1.0 : -1.0) * ((slot & 2) ? 1.0 : -1.0);
    };
    const auto pairScale = [&](std::uint32_t i, std::uint32_t j) {
        return featureScale ? double((*featureScale)[i]) * double((*featureScale)[j]) : 1.0;
    };

    // One discretization per texel for the whole tensor: where the J-based
    // isotropic stencil costs little more than the finite-volume one (its sum
    // within kJacobianGrowth of it), the texel's isotropic wishes are K_P's and
    // it is anisotropic; elsewhere (squeezed or strongly sheared texels, which
    // the finite-volume weights blend towards the 5-point for the time step)
    // its wishes are the finite-volume fluxes and it stays isotropic.
    constexpr double kJacobianGrowth = 2.0;
    std::vector<char> jacobian(cells, 0);
    for (std::uint32_t i = 0; i < cells; ++i) {
        if (!atlas.used(i))
            continue;
        double fv = 0;
        for (int d = 0; d < 4; ++d)
            fv += double(isotropic.coefficients[i][std::size_t(d)]);
        if (isotropic.hasDiagonals())
            for (int d = 0; d < 4; ++d)
                fv += std::abs(double(isotropic.diagonal[i][std::size_t(d)]));
        fv *= isotropic.area[i];
        const double own = 2.0 * (k[2][i][0] + k[2][i][1] + std::abs(k[2][i][2]));
        jacobian[i] = own > 0 && own <= kJacobianGrowth * fv;
        if (!jacobian[i])
            for (std::size_t q = 0; q < 2; ++q)
                k[q][i] = {0.0, 0.0, 0.0};
    }
    const auto fvWish = [&](std::uint32_t i, std::uint32_t j, float weight) {
        return double(weight) * isotropic.area[i] / pairScale(i, j);
    };

    AtlasTensorWeights out;
    AtlasTensorWeights::Field isotropicField;
    for (std::size_t q = 0; q < 3; ++q) {
        AtlasTensorWeights::Field& w = q < 2 ? out.field[q] : isotropicField;
        w.links.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
        w.diagonals.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
        const std::vector<std::array<double, 3>>& kq = k[q];
        for (std::uint32_t i = 0; i < cells; ++i) {
            if (!atlas.used(i))
                continue;
            for (int d = 0; d < 4; ++d) {
                const AtlasStep step = atlas.step(i, Direction(d));
                const std::uint32_t j = step.cell;
                if (j <= i) // j == i: an unglued edge; j < i: set when j was visited
                    continue;
                const int back = int(step.back);
                const auto own = [&](std::uint32_t c, std::uint32_t other, int dir) {
                    return q == 2 && !jacobian[c]
                               ? fvWish(c, other, isotropic.coefficients[c][std::size_t(dir)])
                               : kq[c][std::size_t(dir % 2)];
                };
                const double wish = 0.5 * (own(i, j, d) + own(j, i, back));
                const float flux = float(wish * pairScale(i, j));
                w.links[i][std::size_t(d)] = float(double(flux) / isotropic.area[i]);
                w.links[j][std::size_t(back)] = float(double(flux) / isotropic.area[j]);
            }
            for (int slot = 0; slot < 4; ++slot) {
                const int back = mirrors[i][std::size_t(slot)];
                const std::uint32_t j = diagonals[i][std::size_t(slot)];
                if (back < 0 || j <= i || mirrors[j][std::size_t(back)] != slot ||
                    diagonals[i][std::size_t(slot)] != diagonals[i][std::size_t(slot) + 4])
                    continue;
                const auto own = [&](std::uint32_t c, std::uint32_t other, int sl) {
                    if (q == 2 && !jacobian[c])
                        return isotropic.hasDiagonals()
                                   ? fvWish(c, other, isotropic.diagonal[c][std::size_t(sl)])
                                   : 0.0;
                    return 0.5 * slotSign(sl) * kq[c][2];
                };
                const double wish = 0.5 * (own(i, j, slot) + own(j, i, back));
                const float flux = float(wish * pairScale(i, j));
                w.diagonals[i][std::size_t(slot)] = float(double(flux) / isotropic.area[i]);
                w.diagonals[j][std::size_t(back)] = float(double(flux) / isotropic.area[j]);
            }
        }
    }
    if (isotropicOut)
        *isotropicOut = std::move(isotropicField);
    return out;
}

} // namespace morphogen
