#include "core/operators/stability.hpp"

#include "core/domain/atlas_weights.hpp"
#include "core/numerics/kernel_symbol.hpp"
#include "core/operators/diffusion_operator.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <sstream>
#include <vector>

namespace morphogen {

float stableDiffusionDt(Stencil stencil, float maxDiffusion) {
    const float symbol = stencil == Stencil::FivePoint ? 8.0f : 16.0f / 3.0f;
    if (maxDiffusion <= 0.0f)
        return std::numeric_limits<float>::infinity();
    return 2.0f / (symbol * maxDiffusion);
}

Kernel5 operatorKernel(const DiffusionOperator& op, int chemical) {
    const double d = op.rates[std::size_t(chemical)];
    Kernel5 k;
    switch (op.form) {
    case DiffusionOperator::Form::Laplacian5:
        k.at(1, 0) = k.at(-1, 0) = k.at(0, 1) = k.at(0, -1) = d;
        k.at(0, 0) = -4.0 * d;
        return k;
    case DiffusionOperator::Form::Laplacian9:
        k.at(1, 0) = k.at(-1, 0) = k.at(0, 1) = k.at(0, -1) = 4.0 * d / 6.0;
        k.at(1, 1) = k.at(-1, 1) = k.at(1, -1) = k.at(-1, -1) = d / 6.0;
        k.at(0, 0) = -20.0 * d / 6.0;
        return k;
    case DiffusionOperator::Form::Kernel3:
    case DiffusionOperator::Form::Kernel5:
        return op.kernels[std::size_t(chemical)];
    case DiffusionOperator::Form::TensorMap:
        break;
    }
    assert(false && "a diffusion map has no single kernel");
    return k;
}

namespace {

// A Gershgorin bound on |lambda| as the explicit limit dt <= 2 / bound.
ExplicitStability gershgorinStability(double bound, const std::string& basis) {
    ExplicitStability result;
    result.exact = false;
    result.basis = basis;
    result.spectralRadius = std::numeric_limits<double>::quiet_NaN();
    result.maxStableDt = bound > 0 ? 2.0 / bound : std::numeric_limits<double>::infinity();
    return result;
}

} // namespace

ExplicitStability tensorAtlasStability(const AtlasWeights& weights,
                                       const std::vector<std::array<float, 3>>& mixes) {
    double worst = 0;
    for (const std::array<float, 3>& mix : mixes)
        worst = std::max(worst, maxTensorSum(weights, mix));
    return gershgorinStability(
        2.0 * worst + driftSpectralBound(weights),
        weights.drift ? "Gershgorin bound on the weighted atlas domain with anisotropy and gravity "
                        "(twice the largest sum of a texel's combined weights over the chemicals' "
                        "tensors, plus the drift's bound)"
                      : "Gershgorin bound on the weighted atlas domain with anisotropy (twice the "
                        "largest sum of a texel's combined weights over the chemicals' tensors)");
}

ExplicitStability explicitStability(const DiffusionOperator& op, const Domain& domain, double dt) {
    if (const AtlasWeights* weights = domain.atlasWeights()) {
        // The weighted 5-point Laplacian (the only operator a weighted atlas
        // runs): row i has -rate S_i on the diagonal and off-diagonal entries
        // summing to rate S_i, so |lambda| <= 2 rate max S.
        double maxRate = 0;
        for (int c = 0; c < op.chemicals; ++c)
            maxRate = std::max(maxRate, double(op.rates[std::size_t(c)]));
        // Drops' drift (AtlasWeights::drift): driftSpectralBound says why.
        if (weights->drift)
            return gershgorinStability(
                2.0 * maxRate * double(maxCoefficientSum(*weights)) + driftSpectralBound(*weights),
                "Gershgorin bound on the weighted atlas domain with gravity (largest rate times "
                "twice the largest sum of a texel's four weights, plus the drift's: the smaller "
                "of its largest row sum and twice its largest outflow)");
        return gershgorinStability(
            2.0 * maxRate * double(maxCoefficientSum(*weights)),
            "Gershgorin bound on the weighted atlas domain (largest rate times twice the largest "
            "sum of a texel's four weights; an atlas has no Fourier modes)");
    }
    if (domain.kind() == DomainKind::Atlas)
        return gershgorinStability(diffusionSymbolBound(op),
                                   "Gershgorin bound on the atlas domain (largest rate times "
                                   "the stencil's bound; an atlas has no Fourier modes)");
    return explicitStability(op, domain.tileWidth(), domain.tileHeight(), dt);
}

ExplicitStability explicitStability(const DiffusionOperator& op, int width, int height, double dt) {
    ExplicitStability result;
    if (op.form == DiffusionOperator::Form::TensorMap) {
        const double bound = diffusionSymbolBound(op);
        result.exact = false;
        result.basis = "Gershgorin bound of the diffusion map";
        result.spectralRadius = std::numeric_limits<double>::quiet_NaN();
        if (bound > 0)
            result.maxStableDt = 2.0 / bound;
        else
            result.maxStableDt = std::numeric_limits<double>::infinity();
        return result;
    }
    result.maxStableDt = std::numeric_limits<double>::infinity();
    for (int c = 0; c < op.chemicals; ++c) {
        const ExplicitStepReport r = analyzeExplicitStep(operatorKernel(op, c), width, height, dt);
        result.spectralRadius = std::max(result.spectralRadius, r.spectralRadius);
        result.maxRealPart = c == 0 ? r.maxRealPart : std::max(result.maxRealPart, r.maxRealPart);
        if (!r.maxStableDt)
            result.maxStableDt.reset();
        else if (result.maxStableDt)
            result.maxStableDt = std::min(*result.maxStableDt, *r.maxStableDt);
    }
    return result;
}

RelaxationWeight relaxationWeight(const Kernel5& kernel, int width, int height, double dt) {
    // Every mode of a small grid; a dense 256^2 sampling (Nyquist included)
    // of larger ones, whose symbols are smooth in between.
    const int mw = width * height <= 65536 ? width : 256;
    const int mh = width * height <= 65536 ? height : 256;
    constexpr double pi = 3.14159265358979323846;
    std::vector<std::complex<double>> mu;
    mu.reserve(std::size_t(mw) * mh);
    double minOmegaBound = std::numeric_limits<double>::infinity();
    for (int n = 0; n < mh; ++n)
        for (int m = 0; m < mw; ++m) {
            const std::complex<double> value =
                1.0 - dt * kernelSymbol(kernel, 2 * pi * m / mw, 2 * pi * n / mh);
            mu.push_back(value);
            // |1 - omega mu| < 1 needs omega < 2 Re(mu) / |mu|^2.
            minOmegaBound = std::min(minOmegaBound, 2.0 * value.real() / std::norm(value));
        }
    auto contraction = [&](double omega) {
        double worst = 0;
        for (const std::complex<double>& value : mu)
            worst = std::max(worst, std::abs(1.0 - omega * value));
        return worst;
    };
    RelaxationWeight best{minOmegaBound / 2, contraction(minOmegaBound / 2)};
    // The contraction is convex in omega: a golden-section search on (0, bound).
    double lo = 0, hi = minOmegaBound;
    for (int i = 0; i < 60; ++i) {
        const double a = hi - 0.618 * (hi - lo), b = lo + 0.618 * (hi - lo);
        if (contraction(a) < contraction(b))
            hi = b;
        else
            lo = a;
    }
    const double omega = 0.5 * (lo + hi);
    if (contraction(omega) < best.contraction)
        best = {omega, contraction(omega)};
    return best;
}

float suggestDt(const Session& session) {
    const ExplicitStability s =
        explicitStability(compileDiffusion(session), session.domain(), session.dt);
    const float limit =
        s.maxStableDt ? float(*s.maxStableDt) : std::numeric_limits<float>::infinity();
    // 0.8 of the diffusion limit leaves room for the reaction term's own stiffness.
    return std::min(0.5f * session.dt, 0.8f * limit);
}

std::optional<std::string> findInsaneValue(const State& state, const ReactionModel& model) {
    InsaneValueScan scan(model);
    scan.scanRows(state, 0);
    return scan.result();
}

InsaneValueScan::InsaneValueScan(const ReactionModel& model)
    : m_model(model), m_first(model.chemicals().size()) {}

void InsaneValueScan::scanRows(const State& band, int y0) {
    for (int c = 0; c < band.channels(); ++c) {
        if (m_first[std::size_t(c)])
            continue;
        const ChemicalSpec& spec = m_model.chemicals()[std::size_t(c)];
        const float* p = band.plane(c);
        for (std::size_t i = 0; i < band.cellCount(); ++i) {
            const float v = p[i];
            if (std::isfinite(v) && v >= spec.saneMin && v <= spec.saneMax)
                continue;
            std::ostringstream os;
            os << "chemical " << spec.name << " = " << v << " at (" << i % band.width() << ", "
               << std::size_t(y0) + i / band.width() << ")";
            if (std::isfinite(v))
                os << ", outside its sane range [" << spec.saneMin << ", " << spec.saneMax << "]";
            m_first[std::size_t(c)] = os.str();
            break;
        }
    }
}

std::optional<std::string> InsaneValueScan::result() const {
    for (const std::optional<std::string>& first : m_first)
        if (first)
            return first;
    return std::nullopt;
}

} // namespace morphogen
