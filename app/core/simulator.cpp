#include "core/simulator.hpp"

#include "core/errors.hpp"
#include "core/kernel_symbol.hpp"
#include "core/param_map.hpp"
#include "core/stability.hpp"

namespace morphogen {

void Simulator::setFrozen(const std::vector<std::uint8_t>& frozen) {
    if (!frozen.empty())
        throw InputError("the " + backendName() + " backend cannot freeze cells");
}

StepConstants StepConstants::fromSession(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    StepConstants k;
    k.chemicals = int(model.chemicals().size());
    k.dt = session.dt;
    k.stencil = session.diffusion.stencil;
    k.domain = session.domain();
    k.params = model.packParams(session.params);

    // A mapped diffusion rate: compile the operator at rate 1 for it.
    Session unitRates = session;
    if (session.paramMaps.size() > 4)
        throw InputError("at most 4 parameters can vary per cell (param_maps has " +
                         std::to_string(session.paramMaps.size()) + ")");
    k.paramMaps = State(session.width, session.height, int(session.paramMaps.size()));
    for (const auto& [name, spec] : session.paramMaps) {
        const int index = int(k.mappedParams.size());
        for (std::size_t p = 0; p < model.params().size(); ++p)
            if (model.params()[p].name == name)
                k.mappedParams.push_back(int(p));
        const std::vector<float> values =
            evaluateParamMap(spec, session.width, session.height, session.seed, session.baseDir);
        std::copy(values.begin(), values.end(), k.paramMaps.plane(index));
        for (int c = 0; c < k.chemicals; ++c)
            if (model.chemicals()[std::size_t(c)].diffusionParam == name) {
                k.mappedRate[std::size_t(c)] = index;
                unitRates.params[name] = 1.0f;
            }
    }
    k.op = compileDiffusion(unitRates);
    if (session.integrator == Integrator::SemiImplicit)
        for (int m : k.mappedRate)
            if (m >= 0)
                throw InputError("the semi_implicit integrator needs constant diffusion rates; "
                                 "a param_maps entry varies one");
    k.integrator = session.integrator;
    k.jacobiSweeps = session.jacobiSweeps;
    if (k.integrator == Integrator::SemiImplicit) {
        if (k.op.form == DiffusionOperator::Form::TensorMap)
            throw InputError("the semi_implicit integrator does not support diffusion maps "
                             "(its Jacobi sweep needs a constant kernel); use explicit_euler");
        for (int c = 0; c < k.chemicals; ++c) {
            const Kernel5 kernel = operatorKernel(k.op, c);
            if (analyzeExplicitStep(kernel, session.width, session.height, k.dt).maxRealPart > 1e-9)
                throw InputError("the semi_implicit solve needs a diffusion operator without "
                                 "growing modes; set \"stabilize\": true");
            const RelaxationWeight weight =
                relaxationWeight(kernel, session.width, session.height, k.dt);
            k.omega[std::size_t(c)] = float(weight.omega);
            k.contraction = std::max(k.contraction, weight.contraction);
        }
    }
    for (int c = 0; c < 4; ++c) {
        if (c < k.chemicals) {
            const ChemicalSpec& spec = model.chemicals()[std::size_t(c)];
            // Scaled to the level's grid spacing, as the operator's rates are.
            k.diffusion[c] = k.op.rates[std::size_t(c)];
            k.clampMin[c] = spec.clampMin;
            k.clampMax[c] = spec.clampMax;
        } else {
            k.diffusion[c] = 0.0f;
            k.clampMin[c] = -std::numeric_limits<float>::infinity();
            k.clampMax[c] = std::numeric_limits<float>::infinity();
        }
    }
    return k;
}

} // namespace morphogen
