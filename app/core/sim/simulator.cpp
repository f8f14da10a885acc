#include "core/sim/simulator.hpp"

#include <cassert>

#include "core/base/errors.hpp"
#include "core/numerics/kernel_symbol.hpp"
#include "core/session/param_map.hpp"
#include "core/operators/stability.hpp"

namespace morphogen {

StepConstants StepConstants::fromSession(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    StepConstants k;
    k.chemicals = int(model.chemicals().size());
    k.dt = session.dt;
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
        if (spec.field == ParamMapSpec::Field::Tiles) {
            if (spec.tilesX < 1 || spec.tilesY < 1 || session.width % spec.tilesX ||
                session.height % spec.tilesY ||
                spec.tileValues.size() != std::size_t(spec.tilesX) * std::size_t(spec.tilesY))
                throw InputError("param_maps '" + name + "': the tiles must split the " +
                                 std::to_string(session.width) + " x " +
                                 std::to_string(session.height) +
                                 " grid evenly, with one value per tile");
            const std::array<int, 2> tile = {session.width / spec.tilesX,
                                             session.height / spec.tilesY};
            if (k.tiled() && k.tile != tile)
                throw InputError("param_maps '" + name + "': every tiles map needs the same tiles");
            if (tile[0] < 4 || tile[1] < 4)
                throw InputError("param_maps '" + name + "': tiles need at least 4 x 4 cells");
            if (session.edges != EdgeMode::Periodic)
                throw InputError("param_maps '" + name + "': tiles need periodic edges");
            k.tile = tile;
        }
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
    // Its map texture would need tile-local fetches too; sweeps of tensor
    // fields are left to one-by-one runs.
    if (k.tiled() && k.op.form == DiffusionOperator::Form::TensorMap)
        throw InputError("tiled param_maps do not support a diffusion tensor map");
    if (session.integrator == Integrator::SemiImplicit)
        for (int m : k.mappedRate)
            if (m >= 0)
                throw InputError("the semi_implicit integrator needs constant diffusion rates; "
                                 "a param_maps entry varies one");
    k.integrator = session.integrator;
    k.relaxationPasses = session.relaxationPasses;
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
    for (int c = 0; c < kMaxChemicals; ++c) {
        if (c < k.chemicals) {
            const ChemicalSpec& spec = model.chemicals()[std::size_t(c)];
            k.clampMin[c] = spec.clampMin;
            k.clampMax[c] = spec.clampMax;
        } else {
            k.clampMin[c] = -std::numeric_limits<float>::infinity();
            k.clampMax[c] = std::numeric_limits<float>::infinity();
        }
    }
    return k;
}

bool updateLiveConstants(StepConstants& k, const Session& session) {
    // The whole derivation again keeps one source of truth for every value;
    // its cost is host work only (no GL), small next to a frame.
    StepConstants fresh = StepConstants::fromSession(session);
    assert(fresh.chemicals == k.chemicals && fresh.integrator == k.integrator);
    // A 5x5 pass runs a kernel that shrank to 3x3 (zero outer taps) as it is;
    // any other change of form needs another program.
    using Form = DiffusionOperator::Form;
    const bool sameForm = fresh.op.form == k.op.form ||
                          (k.op.form == Form::Kernel5 && fresh.op.form == Form::Kernel3);
    if (!sameForm) {
        k = std::move(fresh);
        return false;
    }
    k.dt = fresh.dt;
    k.params = std::move(fresh.params);
    k.op.rates = fresh.op.rates;
    k.op.kernels = fresh.op.kernels;
    k.op.mapCoefficients = fresh.op.mapCoefficients;
    k.op.stabilization = fresh.op.stabilization;
    k.omega = fresh.omega;
    k.contraction = fresh.contraction;
    return true;
}

} // namespace morphogen
