#include "core/operators/diffusion_operator.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/io/image_io.hpp"
#include "core/numerics/kernel_symbol.hpp"
#include "core/numerics/tensor_sequence.hpp"
#include "core/operators/orientation_field.hpp"
#include "core/operators/stability.hpp"
#include "core/session/session.hpp"

namespace morphogen {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

float rateOf(const Session& session, const ChemicalSpec& chemical) {
    return chemical.diffusionParam.empty() ? 0.0f : session.params.at(chemical.diffusionParam);
}

// Tensor components are given in display coordinates (y up), the paper's and
// the propagator's convention; the grid's rows grow downward, so mirror.
Kernel5 displayOriented(const Kernel5& grid) {
    Kernel5 k;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            k.at(dx, dy) = grid.at(dx, -dy);
    return k;
}

} // namespace

Kernel5 anisotropicKernel(const AnisotropicTensor& t, float rate) {
    // Principal direction v = (cos, -sin) in grid coordinates (rows grow downward).
    const double c = std::cos(t.theta * kDegree), s = std::sin(t.theta * kDegree);
    const double a1 = double(t.a1) * t.a1, a2 = double(t.a2) * t.a2;
    const double axx = a1 * c * c + a2 * s * s;
    const double ayy = a1 * s * s + a2 * c * c;
    const double axy = -(a1 - a2) * c * s;
    Kernel5 k;
    k.at(-1, 0) = k.at(1, 0) = axx;
    k.at(0, -1) = k.at(0, 1) = ayy;
    k.at(0, 0) = -2.0 * (axx + ayy);
    // 2 A_xy d2c/dxdy with the 4-corner central difference (corner sum / 4).
    k.at(1, 1) = k.at(-1, -1) = 0.5 * axy;
    k.at(1, -1) = k.at(-1, 1) = -0.5 * axy;
    return k.scaled(rate);
}

namespace {

// McGraw's generalized diffusion: each chemical's tensor sequence as one 5x5
// Savitzky-Golay kernel (3x3 where every kernel fits).
void compileGeneralized(const Session& session, DiffusionOperator& op) {
    const ReactionModel& model = session.reactionModel();
    const DiffusionSpec& spec = session.diffusion;
    GeneralizedOperatorOptions options;
    options.sg.radius = spec.savitzkyGolay.window / 2;
    options.sg.degree = spec.savitzkyGolay.degree;
    options.centralSecondDerivatives = spec.savitzkyGolay.centralSecondOrder;
    int radius = 1;
    for (int c = 0; c < op.chemicals; ++c) {
        const std::string& name = model.chemicals()[std::size_t(c)].name;
        auto it = spec.generalized.find(name);
        // Chemicals without a tensor sequence diffuse isotropically (set (a)).
        TensorSequence sequence =
            it == spec.generalized.end() ? tableTwoSet('a') : parseTensorSequence(it->second);
        // rates[] already holds 1/h^2; ranks 3 and 4 need 1/h and 1/h^2 more.
        for (std::size_t i = 0; i < sequence.values.size(); ++i)
            sequence.values[i] /= std::pow(session.gridSpacing, tensorComponents()[i].rank - 2);
        Kernel5 kernel = displayOriented(generalizedDiffusionKernel(sequence, options))
                             .scaled(op.rates[std::size_t(c)]);
        if (spec.stabilize) {
            const StabilizedKernel stable = stabilizeKernel(kernel);
            kernel = stable.kernel;
            op.stabilization[std::size_t(c)] = stable.eta;
        }
        op.kernels[std::size_t(c)] = kernel;
        radius = std::max(radius, kernel.radius());
    }
    op.form = radius == 1 ? DiffusionOperator::Form::Kernel3 : DiffusionOperator::Form::Kernel5;
}

// A diffusion map's texels: the scale s and s (cos 2 phi, sin 2 phi) of the
// orientation phi, the doubled angle because a tensor's axis has no sign.
State diffusionMapTexels(const DiffusionMapSpec& map, int w, int h, const std::string& baseDir) {
    const std::vector<float> angles = orientationAngles(map.orientation, w, h, baseDir);
    std::vector<float> scale(std::size_t(w) * h, map.scaleMax);
    if (!map.scaleImage.empty()) {
        std::string path = map.scaleImage;
        if (!baseDir.empty() && path.front() != '/')
            path = baseDir + "/" + path;
        const std::vector<float> lum = loadLuminance(path, w, h);
        for (std::size_t i = 0; i < scale.size(); ++i)
            scale[i] =
                map.scaleMin + (map.scaleMax - map.scaleMin) * std::clamp(lum[i], 0.0f, 1.0f);
    }
    State texels(w, h, 3);
    for (std::size_t i = 0; i < scale.size(); ++i) {
        texels.plane(0)[i] = scale[i];
        texels.plane(1)[i] = float(scale[i] * std::cos(2.0 * angles[i]));
        texels.plane(2)[i] = float(scale[i] * std::sin(2.0 * angles[i]));
    }
    return texels;
}

// Witkin-Kass: a 3x3 kernel per chemical, or with a diffusion map the map's
// texels and per chemical the coefficients that turn them into its tensor.
void compileAnisotropic(const Session& session, DiffusionOperator& op) {
    const ReactionModel& model = session.reactionModel();
    const DiffusionSpec& spec = session.diffusion;
    // Chemicals without a tensor diffuse isotropically at their rate.
    auto tensorOf = [&](int c) {
        auto it = spec.anisotropic.find(model.chemicals()[std::size_t(c)].name);
        return it == spec.anisotropic.end() ? AnisotropicTensor{} : it->second;
    };
    if (!spec.map) {
        op.form = DiffusionOperator::Form::Kernel3;
        for (int c = 0; c < op.chemicals; ++c)
            op.kernels[std::size_t(c)] = anisotropicKernel(tensorOf(c), op.rates[std::size_t(c)]);
        return;
    }
    op.form = DiffusionOperator::Form::TensorMap;
    op.map = diffusionMapTexels(*spec.map, session.width, session.height, session.baseDir);
    for (int c = 0; c < op.chemicals; ++c) {
        const AnisotropicTensor t = tensorOf(c);
        const double rate = op.rates[std::size_t(c)];
        const double a1 = double(t.a1) * t.a1, a2 = double(t.a2) * t.a2;
        const double m = rate * (a1 + a2) / 2, d = rate * (a1 - a2) / 2;
        op.mapCoefficients[std::size_t(c)] = {float(m), float(d * std::cos(2 * t.theta * kDegree)),
                                              float(d * std::sin(2 * t.theta * kDegree))};
    }
}

// Drops on a tilted canvas: the operator as 3x3 (or 5x5) kernels with the
// downhill drift added to every chemical that diffuses (gravity.hpp).
void addGravity(const Session& session, DiffusionOperator& op) {
    using Form = DiffusionOperator::Form;
    if (op.form == Form::TensorMap)
        throw InputError("\"gravity\" does not combine with a diffusion map (diffusion.map); use "
                         "a constant tensor or isotropic diffusion");
    if (op.form == Form::Laplacian5 || op.form == Form::Laplacian9) {
        for (int c = 0; c < op.chemicals; ++c)
            op.kernels[std::size_t(c)] = operatorKernel(op, c);
        op.form = Form::Kernel3;
    }
    const ReactionModel& model = session.reactionModel();
    for (int c = 0; c < op.chemicals; ++c)
        if (!model.chemicals()[std::size_t(c)].diffusionParam.empty())
            addGravityDrift(op.kernels[std::size_t(c)], session.gravity, session.gridSpacing);
}

} // namespace

DiffusionOperator compileDiffusion(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    DiffusionOperator op;
    op.chemicals = int(model.chemicals().size());
    // On a coarse level (cells h times the finest) an order-n derivative
    // shrinks by h^n: second-order terms by h^2.
    const double spacing = session.gridSpacing;
    for (int c = 0; c < op.chemicals; ++c)
        op.rates[std::size_t(c)] =
            float(rateOf(session, model.chemicals()[std::size_t(c)]) / (spacing * spacing));

    switch (session.diffusion.type) {
    case DiffusionType::Isotropic:
        op.form = session.diffusion.stencil == Stencil::FivePoint
                      ? DiffusionOperator::Form::Laplacian5
                      : DiffusionOperator::Form::Laplacian9;
        break;
    case DiffusionType::Generalized:
        compileGeneralized(session, op);
        break;
    case DiffusionType::Anisotropic:
        compileAnisotropic(session, op);
        break;
    }
    // On a model the drift is part of the surface's weights (AtlasWeights::drift).
    if (session.gravity.active() && !session.atlas) {
        if (!session.gravity.carrier.empty())
            throw InputError("gravity.carrier: drops that cling where their carrier is thin run "
                             "on a model (a session with \"surface\"); on a flat canvas leave "
                             "out \"carrier\"");
        addGravity(session, op);
    }
    if (session.gravity.active() && session.atlas &&
        !(session.atlasWeights && session.atlasWeights->drift))
        throw InputError("\"gravity\" on an atlas needs the surface's drift weights (a session "
                         "on a mesh); this atlas has none");
    return op;
}

double diffusionSymbolBound(const DiffusionOperator& op) {
    double bound = 0;
    for (int c = 0; c < op.chemicals; ++c) {
        const std::size_t i = std::size_t(c);
        switch (op.form) {
        case DiffusionOperator::Form::Laplacian5:
            bound = std::max(bound, 8.0 * op.rates[i]);
            break;
        case DiffusionOperator::Form::Laplacian9:
            bound = std::max(bound, 16.0 / 3.0 * op.rates[i]);
            break;
        case DiffusionOperator::Form::Kernel3:
        case DiffusionOperator::Form::Kernel5: {
            double sum = 0;
            for (double w : op.kernels[i].w)
                sum += std::fabs(w);
            bound = std::max(bound, sum);
            break;
        }
        case DiffusionOperator::Form::TensorMap: {
            // |A| <= s (|m| + |d|); the conservative stencil's weights sum to at most 8 |A|.
            float smax = 0;
            for (std::size_t k = 0; k < op.map.cellCount(); ++k)
                smax = std::max(smax, std::fabs(op.map.plane(0)[k]));
            const auto& mc = op.mapCoefficients[i];
            const double d = std::hypot(mc[1], mc[2]);
            bound = std::max(bound, 8.0 * smax * (std::fabs(mc[0]) + d));
            break;
        }
        }
    }
    return bound;
}

} // namespace morphogen
