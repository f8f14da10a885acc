#include "core/domain/atlas_weights.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_diagonals.hpp"

namespace morphogen {

void checkAtlasWeightSizes(const Atlas& atlas, const AtlasWeights& weights) {
    const std::size_t cells = atlas.cellCount();
    if (weights.tensor)
        for (const AtlasTensorWeights::Field& f : weights.tensor->field)
            if (f.links.size() != cells || f.diagonals.size() != cells)
                throw InputError("atlas weights: " + std::to_string(f.links.size()) + " and " +
                                 std::to_string(f.diagonals.size()) +
                                 " anisotropic link and diagonal entries for an atlas of " +
                                 std::to_string(cells) + " cells (accepted: one per atlas cell)");
    if (weights.drift &&
        (weights.drift->inflow.size() != cells || weights.drift->outflow.size() != cells))
        throw InputError("atlas weights: " + std::to_string(weights.drift->inflow.size()) +
                         " and " + std::to_string(weights.drift->outflow.size()) +
                         " drift inflow and outflow entries for an atlas of " +
                         std::to_string(cells) + " cells (accepted: one per atlas cell)");
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
    if (weights.drift)
        for (std::size_t i = 0; i < atlas.cellCount(); ++i) {
            const auto& in = weights.drift->inflow[i];
            const float out = weights.drift->outflow[i];
            const auto bad = [](float v) { return !std::isfinite(v) || v < 0.0f; };
            if (bad(in[0]) || bad(in[1]) || bad(in[2]) || bad(in[3]) || bad(out))
                throw InputError("atlas weights: cell " + std::to_string(i) +
                                 " has a negative or non-finite drift coefficient (accepted: "
                                 "finite values >= 0)");
        }
    const std::vector<std::array<std::uint32_t, 8>> d =
        weights.tensor || weights.hasDiagonals() ? atlasDiagonals(atlas)
                                                 : std::vector<std::array<std::uint32_t, 8>>();
    if (weights.tensor) {
        for (const AtlasTensorWeights::Field& f : weights.tensor->field)
            for (std::size_t i = 0; i < atlas.cellCount(); ++i)
                for (std::size_t s = 0; s < 4; ++s) {
                    if (!std::isfinite(f.links[i][s]) || !std::isfinite(f.diagonals[i][s]))
                        throw InputError("atlas weights: cell " + std::to_string(i) +
                                         " has a non-finite anisotropic weight");
                    if (f.diagonals[i][s] != 0.0f && d[i][s] != d[i][s + 4])
                        throw InputError("atlas weights: cell " + std::to_string(i) +
                                         " has an anisotropic diagonal weight towards an "
                                         "irregular tile corner (accepted there: 0)");
                }
    }
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
    for (std::size_t i = 0; i < cells; ++i)
        for (std::size_t s = 0; s < 4; ++s) {
            const float k = weights.diagonal[i][s];
            // With anisotropy the isotropic stencil is the centred form: signed diagonals.
            if (weights.tensor ? !std::isfinite(k) : bad(k))
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

namespace {

// Texel i's sum as maxCoefficientSum counts it.
float coefficientSum(const AtlasWeights& weights, std::size_t i) {
    const auto& c = weights.coefficients[i];
    float sum = ((c[2] + c[0]) + c[3]) + c[1];
    if (weights.hasDiagonals()) {
        const auto& k = weights.diagonal[i];
        sum += (std::abs(k[0]) + std::abs(k[1])) + (std::abs(k[2]) + std::abs(k[3]));
    }
    return sum;
}

} // namespace

float maxCoefficientSum(const AtlasWeights& weights) {
    float worst = 0.0f;
    for (std::size_t i = 0; i < weights.coefficients.size(); ++i)
        worst = std::max(worst, coefficientSum(weights, i));
    return worst;
}

AtlasWeights capCoefficientSums(const AtlasWeights& weights, float limit, int* capped,
                                float* smallest) {
    assert(limit > 0);
    AtlasWeights out = weights;
    int count = 0;
    float least = 1.0f;
    for (std::size_t i = 0; i < out.coefficients.size(); ++i) {
        const float sum = coefficientSum(out, i);
        if (!(sum > limit))
            continue;
        // Scaled a hair below the limit, so the rounded sum does not land above it.
        const float scale = limit / sum * (1.0f - 1e-6f);
        for (float& v : out.coefficients[i])
            v *= scale;
        if (out.hasDiagonals())
            for (float& v : out.diagonal[i])
                v *= scale;
        out.area[i] /= scale;
        ++count;
        least = std::min(least, scale);
    }
    if (capped)
        *capped = count;
    if (smallest)
        *smallest = least;
    return out;
}

double driftSpectralBound(const AtlasWeights& weights) {
    if (!weights.drift)
        return 0.0;
    double rows = 0, outflow = 0;
    for (std::size_t i = 0; i < weights.drift->outflow.size(); ++i) {
        const auto& in = weights.drift->inflow[i];
        const double out = double(weights.drift->outflow[i]);
        rows = std::max(rows, out + double(in[0]) + double(in[1]) + double(in[2]) + double(in[3]));
        outflow = std::max(outflow, out);
    }
    return std::min(rows, 2.0 * outflow);
}

int weightedSubsteps(const AtlasWeights& weights) {
    const double sum = maxCoefficientSum(weights);
    return sum > 4.0 ? int(std::ceil(sum / 4.0 - 1e-9)) : 1;
}

std::array<float, 3> tensorMix(double theta, double a1, double a2, double rate) {
    const double radians = theta * 3.14159265358979323846 / 180.0;
    const double mean = rate * (a1 * a1 + a2 * a2) / 2, half = rate * (a1 * a1 - a2 * a2) / 2;
    return {float(mean), float(half * std::cos(2 * radians)), float(half * std::sin(2 * radians))};
}

double maxTensorSum(const AtlasWeights& weights, const std::array<float, 3>& mix) {
    assert(weights.tensor);
    const AtlasTensorWeights& t = *weights.tensor;
    double worst = 0;
    for (std::size_t i = 0; i < weights.coefficients.size(); ++i) {
        double s = 0;
        for (std::size_t d = 0; d < 4; ++d) {
            s += std::abs(double(mix[0]) * weights.coefficients[i][d] +
                          double(mix[1]) * t.field[0].links[i][d] +
                          double(mix[2]) * t.field[1].links[i][d]);
            const double iso = weights.hasDiagonals() ? weights.diagonal[i][d] : 0.0;
            s += std::abs(double(mix[0]) * iso + double(mix[1]) * t.field[0].diagonals[i][d] +
                          double(mix[2]) * t.field[1].diagonals[i][d]);
        }
        worst = std::max(worst, s);
    }
    return worst;
}

double maxTensorSumRatio(const AtlasWeights& weights,
                         const std::vector<std::array<float, 3>>& mixes) {
    double worst = 0;
    for (const std::array<float, 3>& m : mixes)
        if (m[0] > 0)
            worst = std::max(worst, maxTensorSum(weights, m) / (4.0 * double(m[0])));
    return worst;
}

int tensorSubsteps(const AtlasWeights& weights, const std::vector<std::array<float, 3>>& mixes) {
    const double ratio = maxTensorSumRatio(weights, mixes);
    return ratio > 1.0 ? int(std::ceil(ratio - 1e-9)) : 1;
}

std::vector<float> tensorPlanes(const AtlasTensorWeights& tensor) {
    const std::size_t cells = tensor.field[0].links.size();
    std::vector<float> planes(16 * cells);
    for (std::size_t k = 0; k < 2; ++k)
        for (std::size_t i = 0; i < cells; ++i)
            for (std::size_t d = 0; d < 4; ++d) {
                planes[(8 * k + d) * cells + i] = tensor.field[k].links[i][d];
                planes[(8 * k + 4 + d) * cells + i] = tensor.field[k].diagonals[i][d];
            }
    return planes;
}

std::array<std::vector<float>, 4> tensorTexels(const AtlasTensorWeights& tensor) {
    std::array<std::vector<float>, 4> texels;
    for (std::size_t k = 0; k < 2; ++k) {
        const auto flatten = [](const std::vector<std::array<float, 4>>& v) {
            std::vector<float> out(4 * v.size());
            for (std::size_t i = 0; i < v.size(); ++i)
                std::copy(v[i].begin(), v[i].end(), out.begin() + std::ptrdiff_t(4 * i));
            return out;
        };
        texels[2 * k] = flatten(tensor.field[k].links);
        texels[2 * k + 1] = flatten(tensor.field[k].diagonals);
    }
    return texels;
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

std::vector<float> driftPlanes(const AtlasWeights& weights) {
    if (!weights.drift)
        return {};
    const std::size_t cells = weights.drift->outflow.size();
    std::vector<float> planes(5 * cells);
    for (std::size_t i = 0; i < cells; ++i) {
        for (std::size_t d = 0; d < 4; ++d)
            planes[d * cells + i] = weights.drift->inflow[i][d];
        planes[4 * cells + i] = weights.drift->outflow[i];
    }
    return planes;
}

std::vector<float> driftInflowTexels(const AtlasWeights& weights) {
    if (!weights.drift)
        return {};
    std::vector<float> texels(4 * weights.drift->inflow.size());
    for (std::size_t i = 0; i < weights.drift->inflow.size(); ++i)
        std::copy(weights.drift->inflow[i].begin(), weights.drift->inflow[i].end(),
                  texels.begin() + std::ptrdiff_t(4 * i));
    return texels;
}

std::vector<float> driftOutflowTexels(const AtlasWeights& weights) {
    return weights.drift ? weights.drift->outflow : std::vector<float>();
}

} // namespace morphogen
