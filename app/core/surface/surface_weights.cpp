#include "core/surface/surface_weights.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace morphogen {

namespace {

double median(std::vector<double> v) {
    if (v.empty())
        return 0;
    const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

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

    std::vector<double> areas;
    areas.reserve(cells);
    double areaSum = 0;
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c))) {
            const double a = double(tiles.texelArea[c]) * scale * scale;
            areas.push_back(a);
            areaSum += a;
        }
    const double medianArea = median(areas);
    const double minArea = 0.05 * medianArea;
    const double minDistance = 0.2 * std::sqrt(medianArea);
    const double meanArea = areas.empty() ? 1.0 : areaSum / double(areas.size());

    AtlasWeights w;
    w.coefficients.assign(cells, {0.0f, 0.0f, 0.0f, 0.0f});
    w.area.assign(cells, 0.0f);
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c)))
            w.area[c] = float(options.metricCorrection
                                  ? std::max(double(tiles.texelArea[c]) * scale * scale, minArea)
                                  : meanArea);

    // The width of texel c across a step in direction d of its own frame, in model units:
    // its area over its length along the step (|Jv| for a u-step when the frame is
    // orthogonal; less on a sheared texel, which keeps the stencil's spread rate that of
    // the surface: trace 2 of its effective diffusion tensor, as on a square grid).
    const auto width = [&](std::uint32_t c, int d) {
        const Eigen::Vector3f& along = (d % 2 == 0) ? tiles.jacobianU[c] : tiles.jacobianV[c];
        const double length = std::max(double(along.norm()) * scale, minDistance);
        return std::max(double(tiles.texelArea[c]) * scale * scale, minArea) / length;
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
                const double l = 0.5 * (width(i, d) + width(j, back));
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
    }
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
    // Normalised so the area-weighted mean of f^2 (the diffusion rate's factor) is 1: the
    // pattern keeps its overall scale and only redistributes it.
    double weighted = 0, area = 0;
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c))) {
            const double g = 1.0 / (1.0 + strength * std::abs(double(tiles.meanCurvature[c])) / m);
            f[c] = float(g);
            weighted += tiles.texelArea[c] * g * g;
            area += tiles.texelArea[c];
        }
    const double norm = weighted > 0 && area > 0 ? std::sqrt(area / weighted) : 1.0;
    for (std::size_t c = 0; c < cells; ++c)
        if (atlas.used(std::uint32_t(c)))
            f[c] = float(f[c] * norm);
    return f;
}

} // namespace morphogen
