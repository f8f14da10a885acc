#include "core/sim/simulator.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/numerics/kernel_symbol.hpp"
#include "core/operators/stability.hpp"
#include "core/session/param_map.hpp"
#include "core/session/surface_geometry.hpp"
#include "core/sim/brush.hpp"

namespace morphogen {

namespace {

int paramIndex(const ReactionModel& model, const std::string& name) {
    for (std::size_t p = 0; p < model.params().size(); ++p)
        if (model.params()[p].name == name)
            return int(p);
    return -1;
}

// Adds a per-cell parameter `name`; returns its plane. A chemical whose
// diffusion rate it is gets a mapped rate, and unitRates compiles it at 1.
float* addMappedParam(StepConstants& k, const ReactionModel& model, const std::string& name,
                      Session& unitRates) {
    const int index = int(k.mappedParams.size());
    k.mappedParams.push_back(paramIndex(model, name));
    for (int c = 0; c < k.chemicals; ++c)
        if (model.chemicals()[std::size_t(c)].diffusionParam == name) {
            k.mappedRate[std::size_t(c)] = index;
            unitRates.params[name] = 1.0f;
        }
    return k.paramMaps.plane(index);
}

// The session's param_maps, or a tiled grid's per-tile values: both become
// per-cell planes (constant per tile for the latter) plus, for tiles, the
// full per-tile parameter table.
void loadVaryingParams(StepConstants& k, const Session& session, Session& unitRates) {
    const ReactionModel& model = session.reactionModel();
    const std::size_t varying = session.paramMaps.size() + session.tiles.params.size();
    if (varying > 4)
        throw InputError("at most 4 parameters can vary per cell (param_maps and tiles.params "
                         "have " +
                         std::to_string(varying) + ")");
    if (k.tiled() && !session.paramMaps.empty())
        throw InputError("param_maps cannot vary a parameter over a tiled grid domain (a batched "
                         "sweep); tiles.params sets per-tile values");
    if (session.atlas && !session.paramMaps.empty() &&
        !(session.atlasPositions && session.surfaceGeometry))
        throw InputError("param_maps (fields in grid x and y) cannot vary a parameter over an "
                         "atlas domain that is not a mesh's (on a mesh they are fields in space)");
    k.paramMaps = State(session.width, session.height, int(varying));
    std::vector<bool> used;
    if (session.atlas && !session.paramMaps.empty())
        for (std::uint32_t i = 0; i < session.atlas->cellCount(); ++i)
            used.push_back(session.atlas->used(i));
    for (const auto& [name, spec] : session.paramMaps) {
        const std::vector<float> values =
            session.atlas
                ? evaluateSurfaceParamMap(spec, name, *session.atlasPositions, used,
                                          session.surfaceGeometry->unitsPerMesh(), session.seed)
                : evaluateParamMap(spec, session.width, session.height, session.seed,
                                   session.baseDir, session.layoutCellSize());
        std::copy(values.begin(), values.end(), addMappedParam(k, model, name, unitRates));
    }
    if (!k.tiled())
        return;
    const Domain& d = k.domain;
    const int columns = d.columns(), rows = d.rows(), tw = d.tileWidth(), th = d.tileHeight();
    // Storage row ty (from the top) is sweep row rows - 1 - ty (from the bottom).
    k.tileParams.resize(std::size_t(columns) * std::size_t(rows) * k.params.size());
    for (int ty = 0; ty < rows; ++ty)
        for (int tx = 0; tx < columns; ++tx) {
            ParamValues values = session.params;
            for (const auto& [name, perTile] : session.tiles.params)
                values[name] = session.tiles.value(name, tx, rows - 1 - ty);
            const std::vector<float> packed = model.packParams(values);
            std::copy(packed.begin(), packed.end(),
                      k.tileParams.begin() +
                          std::ptrdiff_t((std::size_t(ty) * columns + tx) * k.params.size()));
        }
    for (const auto& [name, perTile] : session.tiles.params) {
        float* plane = addMappedParam(k, model, name, unitRates);
        const int p = k.mappedParams.back();
        for (int y = 0; y < session.height; ++y)
            for (int x = 0; x < session.width; ++x)
                plane[std::size_t(y) * session.width + x] = k.tileParamsAt(x / tw, y / th)[p];
    }
}

std::string operatorName(DiffusionOperator::Form form) {
    using Form = DiffusionOperator::Form;
    switch (form) {
    case Form::Laplacian5:
        return "isotropic 5-point Laplacian";
    case Form::Laplacian9:
        return "isotropic 9-point Laplacian (stencil 9-point)";
    case Form::Kernel3:
        return "anisotropic 3x3 tensor (Witkin-Kass)";
    case Form::Kernel5:
        return "generalized 5x5 kernel (McGraw)";
    case Form::TensorMap:
        return "anisotropic tensor map (diffusion map)";
    }
    return "diffusion";
}

// An anisotropic session on a surface: each chemical's Witkin-Kass tensor,
// measured from the surface's direction field, as a mix of the isotropic and
// the two tensor operators (AtlasTensorWeights); the weights are the stencil.
void loadTensorMixes(StepConstants& k, const Session& session, const AtlasWeights& weights) {
    k.tensorPlanes = std::make_shared<const std::vector<float>>(tensorPlanes(*weights.tensor));
    k.tensorMixes = sessionTensorMixes(session, k.op.rates.data());
    k.op.form = DiffusionOperator::Form::Laplacian5;
}

// Refuses operators and integrators the domain cannot run (see core/domain/domain.hpp).
void checkOperatorOnDomain(const StepConstants& k) {
    using Form = DiffusionOperator::Form;
    if (k.domain.kind() == DomainKind::Atlas) {
        // Only the four neighbours of the connectivity map and the 9-point
        // stencil's averaged diagonals (atlas_diagonals.hpp) are defined
        // everywhere; distance-2 taps and tensor cross terms are not.
        if (k.op.form != Form::Laplacian5 && k.op.form != Form::Laplacian9)
            throw InputError("the " + operatorName(k.op.form) +
                             " diffusion operator cannot run on an atlas domain (accepted there: "
                             "isotropic diffusion, 5-point or 9-point stencil; anisotropic "
                             "tensors on a mesh, whose surface gives them a direction field)");
        if (k.integrator == Integrator::SemiImplicit && !k.weighted())
            throw InputError("the semi_implicit integrator runs on a weighted atlas (a model's "
                             "surface) only, not on an unweighted atlas domain; use "
                             "explicit_euler");
        if (k.integrator == Integrator::SemiImplicit && (k.tensorWeighted() || k.drifting()))
            throw InputError(std::string("the semi_implicit integrator on a model needs "
                                         "isotropic diffusion without drops: ") +
                             (k.drifting() ? "\"gravity\" (drops running down) is set"
                                           : "the diffusion is anisotropic") +
                             "; use explicit_euler");
    }
    // Its map texture would need tile-local fetches too; sweeps of tensor
    // fields are left to one-by-one runs.
    if (k.tiled() && k.op.form == Form::TensorMap)
        throw InputError("a diffusion tensor map cannot run on a tiled grid domain (a batched "
                         "sweep); run the tiles one by one");
}

// On a weighted atlas there are no Fourier modes: each texel's sweep is
// Jacobi's, x' = (rhs + dt r sides) / (1 + dt r S) with S its weight sum (the
// backends compute it per texel; omega stays 0). Jacobi's sweep is a convex
// combination of rhs and the neighbours' values, so it is stable at any dt;
// its residual factor at a texel is at most sigma / (1 + sigma), sigma = dt r
// S: the worst texel's is `contraction`.
void loadAtlasRelaxation(StepConstants& k) {
    const double largest = maxCoefficientSum(*k.domain.atlasWeights());
    for (int c = 0; c < k.chemicals; ++c) {
        const double sigma = double(k.dt) * std::abs(double(k.op.rates[std::size_t(c)])) * largest;
        k.chemicalContraction[std::size_t(c)] = sigma / (1.0 + sigma);
        k.contraction = std::max(k.contraction, sigma / (1.0 + sigma));
    }
}

// The semi-implicit solve's per-chemical Richardson weights.
void loadRelaxationWeights(StepConstants& k) {
    for (int m : k.mappedRate)
        if (m >= 0)
            throw InputError("the semi_implicit integrator needs constant diffusion rates; "
                             "a param_maps or tiles entry varies one");
    if (k.op.form == DiffusionOperator::Form::TensorMap)
        throw InputError("the semi_implicit integrator does not support diffusion maps "
                         "(its Jacobi sweep needs a constant kernel); use explicit_euler");
    if (k.weighted()) {
        loadAtlasRelaxation(k);
        return;
    }
    // The Fourier analysis of a tiled grid is that of one periodic tile.
    const int w = k.domain.tileWidth(), h = k.domain.tileHeight();
    for (int c = 0; c < k.chemicals; ++c) {
        const Kernel5 kernel = operatorKernel(k.op, c);
        if (analyzeExplicitStep(kernel, w, h, k.dt).maxRealPart > 1e-9)
            throw InputError("the semi_implicit solve needs a diffusion operator without "
                             "growing modes; set \"stabilize\": true");
        const RelaxationWeight weight = relaxationWeight(kernel, w, h, k.dt);
        k.omega[std::size_t(c)] = float(weight.omega);
        k.contraction = std::max(k.contraction, weight.contraction);
    }
}

void loadClamps(StepConstants& k, const ReactionModel& model) {
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
}

} // namespace

bool StepConstants::paramsPerTileOnly() const {
    if (!tiled())
        return false;
    for (int m : mappedRate)
        if (m >= 0)
            return false;
    return true;
}

std::vector<std::array<float, 3>> sessionTensorMixes(const Session& session, const float* rates) {
    const ReactionModel& model = session.reactionModel();
    std::vector<std::array<float, 3>> mixes;
    for (std::size_t c = 0; c < model.chemicals().size(); ++c) {
        const auto it = session.diffusion.anisotropic.find(model.chemicals()[c].name);
        const AnisotropicTensor t =
            it == session.diffusion.anisotropic.end() ? AnisotropicTensor{} : it->second;
        mixes.push_back(tensorMix(t.theta, t.a1, t.a2, rates ? rates[c] : 1.0));
    }
    return mixes;
}

namespace {

// The GPU step reads the carrier from the first state texture, next to the
// chemicals it carries: every drifting chemical and the carrier are among its
// first four.
void loadDriftCarrier(StepConstants& k, const Gravity& gravity, const ReactionModel& model) {
    const int carrier = model.chemicalIndex(gravity.carrier);
    if (carrier < 0)
        throw InputError("gravity.carrier: '" + gravity.carrier + "' is not a chemical of " +
                         model.name() + " (chemicals: " + model.chemicalNames() + ")");
    for (int c = 0; c < k.chemicals; ++c)
        if ((k.drifts[std::size_t(c)] != 0.0f || c == carrier) && c >= 4)
            throw InputError("gravity.carrier: " + model.name() + "'s chemical " +
                             model.chemicals()[std::size_t(c)].name +
                             " is past its first four; a carrier needs the carrier and every "
                             "diffusing chemical among them");
    k.driftCarrier = carrier;
    k.driftCling = float(gravity.cling);
}

} // namespace

StepConstants StepConstants::fromSession(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    StepConstants k;
    k.chemicals = int(model.chemicals().size());
    k.dt = session.dt;
    k.domain = session.domain();
    k.params = model.packParams(session.params);

    Session unitRates = session; // a mapped diffusion rate is compiled at rate 1
    loadVaryingParams(k, session, unitRates);
    k.op = compileDiffusion(unitRates);
    // The backends scale a mapped rate's whole term, which would scale the drift too.
    if (session.gravity.active())
        for (int m : k.mappedRate)
            if (m >= 0)
                throw InputError("\"gravity\" does not combine with a param map of a diffusion "
                                 "rate: drops would run at the map's speed; map another "
                                 "parameter, or leave out one of them");
    k.integrator = session.integrator;
    k.relaxationPasses = session.relaxationPasses;
    if (const AtlasWeights* weights = k.domain.atlasWeights()) {
        k.weightPlanes = std::make_shared<const std::vector<float>>(coefficientPlanes(*weights));
        if (weights->hasDiagonals())
            k.diagonalPlanes =
                std::make_shared<const std::vector<float>>(morphogen::diagonalPlanes(*weights));
        if (weights->drift) {
            if (weights->tensor && k.op.form == DiffusionOperator::Form::Kernel3)
                throw InputError("\"gravity\" on a model does not combine with anisotropic "
                                 "diffusion yet; use isotropic diffusion for drops");
            k.driftPlanes =
                std::make_shared<const std::vector<float>>(morphogen::driftPlanes(*weights));
            for (int c = 0; c < k.chemicals; ++c)
                k.drifts[std::size_t(c)] =
                    model.chemicals()[std::size_t(c)].diffusionParam.empty() ? 0.0f : 1.0f;
            if (!session.gravity.carrier.empty())
                loadDriftCarrier(k, session.gravity, model);
        }
        if (weights->tensor && k.op.form == DiffusionOperator::Form::Kernel3)
            loadTensorMixes(k, session, *weights);
        // The weights are the stencil: their links (with their diagonals,
        // if any) run whether the session asked for 5 or 9 points.
        if (k.op.form == DiffusionOperator::Form::Laplacian9) {
            k.op.form = DiffusionOperator::Form::Laplacian5;
            k.nineToFivePoint = !weights->hasDiagonals();
        }
    }
    checkOperatorOnDomain(k);
    if (k.integrator == Integrator::SemiImplicit)
        loadRelaxationWeights(k);
    loadClamps(k, model);
    return k;
}

int chemicalRelaxationPasses(const StepConstants& k, int chemical) {
    return chemicalRelaxationPasses(k, chemical, k.relaxationPasses);
}

int chemicalRelaxationPasses(const StepConstants& k, int chemical, int passes) {
    assert(chemical >= 0 && chemical < k.chemicals);
    if (!k.weighted() || k.integrator != Integrator::SemiImplicit)
        return passes;
    const double own = k.chemicalContraction[std::size_t(chemical)], worst = k.contraction;
    if (own >= worst)
        return passes;
    if (own <= 0)
        return 1;
    // own^p <= worst^passes; the margin keeps an exact ratio from rounding up.
    const double p = std::ceil(double(passes) * std::log(worst) / std::log(own) - 1e-9);
    return std::clamp(int(p), 1, passes);
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
    k.tensorMixes = fresh.tensorMixes;
    k.omega = fresh.omega;
    k.contraction = fresh.contraction;
    k.chemicalContraction = fresh.chemicalContraction;
    return true;
}

std::vector<int> checkActiveTiles(const Domain& domain, const std::vector<int>& tiles) {
    if (tiles.empty())
        return {};
    const Atlas* atlas = domain.atlasMap();
    if (!atlas)
        throw InputError("active tiles (localized reaction-diffusion) need an atlas domain; this "
                         "one is a " +
                         domain.name());
    std::vector<int> sorted = tiles;
    std::sort(sorted.begin(), sorted.end());
    sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
    if (sorted.front() < 0 || sorted.back() >= atlas->tileCount())
        throw InputError(
            "active tile " + std::to_string(sorted.front() < 0 ? sorted.front() : sorted.back()) +
            " is out of range (accepted: 0.." + std::to_string(atlas->tileCount() - 1) + ")");
    return sorted;
}

std::optional<std::string> Simulator::insaneValue(const ReactionModel& model) const {
    return findInsaneValue(state(), model);
}

std::optional<float> Simulator::cellParam(const std::string& name, int x, int y) const {
    const StepConstants& k = stepConstants();
    const int m = mappedIndex(k, liveSession().reactionModel(), name);
    if (m < 0 || x < 0 || y < 0 || x >= k.paramMaps.width() || y >= k.paramMaps.height())
        return std::nullopt;
    return k.paramMaps.at(m, x, y);
}

} // namespace morphogen
