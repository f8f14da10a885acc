#include "core/surface/surface_drift.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/session/gravity.hpp"
#include "core/surface/surface_weights.hpp"

namespace morphogen {

AtlasDrift surfaceDrift(const SurfaceTiles& tiles, const AtlasWeights& weights,
                        const std::array<double, 3>& direction, double strength,
                        double unitsPerWorld) {
    checkGravityDirection(direction, "direction");
    if (!(strength >= 0) || !std::isfinite(strength))
        throw InputError("surface drift: strength " + std::to_string(strength) +
                         " must be finite and >= 0");
    if (!(unitsPerWorld > 0) || !std::isfinite(unitsPerWorld))
        throw InputError("surface drift: units per world unit " + std::to_string(unitsPerWorld) +
                         " must be positive and finite");
    const Atlas& atlas = *tiles.atlas;
    const std::size_t cells = atlas.cellCount();
    const Eigen::Vector3d g =
        Eigen::Vector3d(direction[0], direction[1], direction[2]).normalized();
    // The cap: at most `strength` over the floor of a texel's centre distance
    // (texelFloors, as the weights' guard), in texel steps per unit time.
    const double cap = strength / texelFloors(tiles, unitsPerWorld).minDistance;

    // Per texel, the fraction of its amount leaving across each face per unit time.
    std::vector<std::array<double, 4>> leaving(cells, {0.0, 0.0, 0.0, 0.0});
    for (std::uint32_t i = 0; i < cells; ++i) {
        if (!atlas.used(i))
            continue;
        const Eigen::Matrix<double, 3, 2> J = texelJacobian(tiles, i, unitsPerWorld);
        const Eigen::Matrix2d metric = J.transpose() * J;
        const double det = metric.determinant();
        if (!(det > 1e-12 * metric.trace() * metric.trace()))
            continue; // a degenerate texel: no direction to run in
        const Eigen::Vector2d w = strength * metric.inverse() * (J.transpose() * g);
        const double wu = std::clamp(w.x(), -cap, cap), wv = std::clamp(w.y(), -cap, cap);
        // Direction order +x, +y, -x, -y; an open edge (the step stays put) passes nothing.
        const std::array<double, 4> along = {wu, wv, -wu, -wv};
        for (int d = 0; d < 4; ++d)
            if (atlas.step(i, Direction(d)).cell != i)
                leaving[i][std::size_t(d)] = std::max(0.0, along[std::size_t(d)]);
    }

    AtlasDrift drift;
    drift.inflow.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
    drift.outflow.assign(cells, 0.0f);
    for (std::uint32_t j = 0; j < cells; ++j) {
        if (!atlas.used(j))
            continue;
        double out = 0;
        for (int e = 0; e < 4; ++e) {
            const double a = leaving[j][std::size_t(e)];
            if (a == 0)
                continue;
            const AtlasStep s = atlas.step(j, Direction(e));
            // The amount j passes reaches s.cell from s.cell's direction s.back.
            const float flux = float(double(weights.area[j]) * a);
            out += double(flux) / double(weights.area[j]);
            drift.inflow[s.cell][std::size_t(s.back)] =
                float(double(flux) / double(weights.area[s.cell]));
        }
        drift.outflow[j] = float(out);
    }
    return drift;
}

} // namespace morphogen
