#include "core/domain/atlas_weights.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_diagonals.hpp"

namespace morphogen {

void checkAtlasWeightSizes(const Atlas& atlas, const AtlasWeights& weights) {
    const std::size_t cells = atlas.cellCount();
    if (weights.hasDiagonals() && weights.diagonal.size() != cells)
        throw InputError("atlas weights: " + std::to_string(weights.diagonal.size()) +
                         " diagonal entries for an atlas of " + std::to_string(cells) +
                         " cells (accepted: none, or one per atlas cell)");
    if (weights.coefficients.size() != cells || weights.area.size() != cells)
        throw InputError("atlas weights: " + std::to_string(weights.coefficients.size()) +
                         " coefficient and " + std::to_string(weights.area.size()) +
                         " area entries for an atlas of " + std::to_string(atlas.width()) + " x " +
                         std::to_string(atlas.height()) + " = " + std::to_string(cells) +
                         " cells (accepted: one entry per atlas cell in both)");
}

void checkAtlasWeights(const Atlas& atlas, const AtlasWeights& weights) {
    checkAtlasWeightSizes(atlas, weights);
    const std::size_t cells = atlas.cellCount();
    const auto bad = [](float v) { return !std::isfinite(v) || v < 0.0f; };
    for (std::size_t i = 0; i < cells; ++i) {
        const auto& c = weights.coefficients[i];
        if (bad(c[0]) || bad(c[1]) || bad(c[2]) || bad(c[3]) || bad(weights.area[i]))
            throw InputError("atlas weights: cell " + std::to_string(i) + " (x " +
                             std::to_string(i % std::size_t(atlas.width())) + ", y " +
                             std::to_string(i / std::size_t(atlas.width())) +
                             ") has a negative or non-finite coefficient or area (accepted: "
                             "finite values >= 0)");
    }
    if (!weights.hasDiagonals())
        return;
    const auto d = atlasDiagonals(atlas);
    for (std::size_t i = 0; i < cells; ++i)
        for (std::size_t s = 0; s < 4; ++s) {
            const float k = weights.diagonal[i][s];
            if (bad(k))
                throw InputError("atlas weights: cell " + std::to_string(i) +
                                 " has a negative or non-finite diagonal coefficient (accepted: "
                                 "finite values >= 0)");
            if (k != 0.0f && d[i][s] != d[i][s + 4])
                throw InputError("atlas weights: cell " + std::to_string(i) +
                                 " has a diagonal coefficient towards an irregular tile corner, "
                                 "where the diagonal is not one texel (accepted there: 0)");
        }
}

AtlasWeights uniformAtlasWeights(const Atlas& atlas, float coefficient) {
    AtlasWeights w;
    w.coefficients.assign(atlas.cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    w.area.assign(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            w.coefficients[i] = {coefficient, coefficient, coefficient, coefficient};
            w.area[i] = 1.0f;
        }
    return w;
}

float maxCoefficientSum(const AtlasWeights& weights) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < weights.coefficients.size(); ++i) {
        const auto& c = weights.coefficients[i];
        float sum = ((c[2] + c[0]) + c[3]) + c[1];
        if (weights.hasDiagonals()) {
            const auto& k = weights.diagonal[i];
            sum += (std::abs(k[0]) + std::abs(k[1])) + (std::abs(k[2]) + std::abs(k[3]));
        }
        worst = std::max(worst, sum);
    }
    return worst;
}

int weightedSubsteps(const AtlasWeights& weights) {
    const double sum = maxCoefficientSum(weights);
    return sum > 4.0 ? int(std::ceil(sum / 4.0 - 1e-9)) : 1;
}

std::vector<float> coefficientPlanes(const AtlasWeights& weights) {
    const std::size_t cells = weights.coefficients.size();
    std::vector<float> planes(4 * cells);
    for (std::size_t i = 0; i < cells; ++i)
        for (std::size_t d = 0; d < 4; ++d)
            planes[d * cells + i] = weights.coefficients[i][d];
    return planes;
}

std::vector<float> coefficientTexels(const AtlasWeights& weights) {
    std::vector<float> texels(4 * weights.coefficients.size());
    for (std::size_t i = 0; i < weights.coefficients.size(); ++i)
        std::copy(weights.coefficients[i].begin(), weights.coefficients[i].end(),
                  texels.begin() + std::ptrdiff_t(4 * i));
    return texels;
}

std::vector<float> diagonalPlanes(const AtlasWeights& weights) {
    const std::size_t cells = weights.diagonal.size();
    std::vector<float> planes(4 * cells);
    for (std::size_t i = 0; i < cells; ++i)
        for (std::size_t s = 0; s < 4; ++s)
            planes[s * cells + i] = weights.diagonal[i][s];
    return planes;
}

std::vector<float> diagonalTexels(const AtlasWeights& weights) {
    std::vector<float> texels(4 * weights.diagonal.size());
    for (std::size_t i = 0; i < weights.diagonal.size(); ++i)
        std::copy(weights.diagonal[i].begin(), weights.diagonal[i].end(),
                  texels.begin() + std::ptrdiff_t(4 * i));
    return texels;
}

} // namespace morphogen
