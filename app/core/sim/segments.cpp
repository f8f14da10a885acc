#include "core/sim/segments.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

namespace {

// A level's cell size in model units.
double cellSizeAt(const Session& session, int width) {
    if (session.length > 0 && !session.tiles.active() && !session.atlas)
        return session.length / width;
    return double(session.width) / width; // legacy: the finest level has one unit per cell
}

// Steps per session step at cell size h: explicit steps keep dt within the
// stability limit, which scales as h^2; the semi-implicit step's diffusion is
// implicit, so it keeps its dt.
int substepsAt(const Session& session, double h) {
    if (session.integrator != Integrator::ExplicitEuler)
        return 1;
    // A weighted atlas's coefficients are 1/h^2 of its texels (in units^-2):
    // its limit shrinks with their largest sum as a grid's with 4/h^2.
    if (session.atlas && session.atlasWeights)
        return atlasSubsteps(session);
    if (h >= 1.0)
        return 1;
    return int(std::ceil(1.0 / (h * h) - 1e-9));
}

// McGraw's generalized operators of rank 3 and 4 have terms that grow as
// 1/h^3 and 1/h^4 on a finer grid, faster than the 1/h^2 substepsAt counts on,
// so at ceil(1/h^2) substeps the session's dt would be over the level's limit
// and the stability check would cap it for the whole run: a 1024 render of a
// 128-unit rank-4 preset simulated 1/64 of its time and never grew its
// pattern. Such a level takes as many substeps as its explicit limit is below
// the limit of the same operator at one cell per unit (both on the level's
// Fourier modes), so a dt stable at the base stays stable at every size and
// the simulated time stays the same. `level` is the segment's session, placed.
int higherOrderSubsteps(const Session& level, int substeps) {
    if (level.integrator != Integrator::ExplicitEuler ||
        level.diffusion.type != DiffusionType::Generalized || level.gridSpacing >= 1.0 ||
        level.atlas || level.tiles.active())
        return substeps;
    Session unit = level;
    unit.gridSpacing = 1.0;
    const Domain domain = level.domain();
    const std::optional<double> fine =
        explicitStability(compileDiffusion(level), domain, level.dt).maxStableDt;
    const std::optional<double> base =
        explicitStability(compileDiffusion(unit), domain, level.dt).maxStableDt;
    if (!fine || !base || !(*fine > 0.0))
        return substeps; // an operator that grows for every dt: the check refuses it
    // The tolerance keeps a second-order operator at exactly 1/h^2 (4, not 5).
    const double ratio = *base / *fine * (1.0 - 1e-6);
    if (!(ratio < double(INT_MAX)))
        return INT_MAX;
    return std::max(substeps, int(std::ceil(ratio)));
}

int scaledSteps(long long steps, int substeps, int width, int height) {
    const long long n = steps * substeps;
    if (n > INT_MAX)
        throw InputError("at " + std::to_string(width) + " x " + std::to_string(height) +
                         " the session's " + std::to_string(steps) + " steps take " +
                         std::to_string(n) + " steps of dt/" + std::to_string(substeps) +
                         ", more than the engine runs in one go: use fewer steps or a smaller "
                         "size");
    return int(n);
}

// Sets a segment's size, grid spacing, dt and steps for `sessionSteps`.
void place(Segment& segment, const Session& session, int width, int height, int sessionSteps) {
    Session& s = segment.session;
    s.width = width;
    s.height = height;
    s.gridSpacing = cellSizeAt(session, width);
    segment.substeps = higherOrderSubsteps(s, substepsAt(session, s.gridSpacing));
    segment.sessionDt = s.dt;
    s.dt = float(double(s.dt) / segment.substeps);
    s.steps = scaledSteps(sessionSteps, segment.substeps, width, height);
}

} // namespace

int atlasSubsteps(const Session& session) {
    const double ratio = atlasSubstepRatio(session);
    return ratio > 1.0 ? int(std::ceil(ratio - 1e-9)) : 1;
}

double atlasSubstepRatio(const Session& session) {
    const AtlasWeights& weights = *session.atlasWeights;
    double ratio = maxCoefficientSum(weights) / 4.0;
    if (weights.tensor && session.diffusion.type == DiffusionType::Anisotropic)
        ratio = std::max(ratio, maxTensorSumRatio(weights, sessionTensorMixes(session, nullptr)));
    // A param map of a diffusion rate (on a mesh) reaches past the session's
    // value: the limit shrinks with its largest value.
    const ReactionModel& model = session.reactionModel();
    double rateFactor = 1.0;
    for (const auto& chemical : model.chemicals()) {
        const auto map = session.paramMaps.find(chemical.diffusionParam);
        const auto value = session.params.find(chemical.diffusionParam);
        if (map != session.paramMaps.end() && value != session.params.end() && value->second > 0)
            rateFactor = std::max(
                rateFactor, double(std::max(std::abs(map->second.min), std::abs(map->second.max))) /
                                double(value->second));
    }
    ratio *= rateFactor;
    // Drops' drift adds its share of the explicit limit, dt * its spectral
    // bound / 2 (driftSpectralBound), to the diffusion's (which the session's
    // dt keeps within 1).
    ratio += double(session.dt) * driftSpectralBound(weights) / 2.0;
    return ratio;
}

int refineSteps() {
    // What a level must correct is the resampling's error, at the scale of
    // its cells: diffusion evens that out in a fixed number of the level's
    // own steps, whatever the cell size (the pattern's shape came from the
    // base). A fixed count keeps refinement's cost in proportion to the cells.
    return 160;
}

ResolutionPlan planResolution(const Session& session) {
    ResolutionPlan plan{session.width, session.height, {}};
    if (session.length <= 0 || !session.coarseToFine || !session.schedule.empty() ||
        session.tiles.active() || session.atlas)
        return plan;
    int halvings = 0;
    while (session.width / double(1 << (halvings + 1)) >= session.length &&
           session.height >> (halvings + 1) >= 8)
        ++halvings;
    if (halvings == 0)
        return plan;
    auto sizeAt = [&](int k) {
        const double f = double(1 << k);
        return std::pair<int, int>{std::max(1, int(std::lround(session.width / f))),
                                   std::max(1, int(std::lround(session.height / f)))};
    };
    std::tie(plan.baseWidth, plan.baseHeight) = sizeAt(halvings);
    for (int k = halvings - 1; k >= 0; --k) {
        const auto [w, h] = sizeAt(k);
        plan.refine.push_back({w, h, 0});
    }
    return plan;
}

std::vector<Segment> segmentsOf(const Session& session) {
    const ResolutionPlan plan = planResolution(session);
    std::vector<Segment> segments;
    Session base = session;
    base.schedule.clear();
    base.stages.clear();
    if (!session.stages.empty()) {
        for (const Stage& stage : session.stages) {
            const bool newModel = !stage.model.empty();
            if (newModel) {
                // The new model starts from its own defaults, not the old model's values.
                const ReactionModel& model = *findModel(stage.model);
                base.model = stage.model;
                base.params.clear();
                for (const ParamSpec& p : model.params())
                    base.params[p.name] = p.defaultValue;
                base.init = stage.init ? *stage.init : model.defaultInit();
                base.dt = model.defaultDt();
                base.paramMaps.clear(); // sessionFromJson refuses maps with a model change
            }
            if (stage.dt)
                base.dt = *stage.dt;
            for (const auto& [name, value] : stage.params)
                base.params[name] = value; // cumulative, as Turk's cascades change s
            Segment segment{base, stage.freeze, stage.reset, newModel};
            place(segment, session, plan.baseWidth, plan.baseHeight, stage.steps);
            segments.push_back(segment);
        }
    } else {
        std::vector<ScheduleLevel> levels = session.schedule;
        if (levels.empty())
            levels.push_back({plan.baseWidth, plan.baseHeight, session.steps});
        for (const ScheduleLevel& level : levels) {
            Segment segment{base, std::nullopt, {}, false};
            place(segment, session, level.width, level.height, level.steps);
            segments.push_back(segment);
        }
    }
    // Refinement continues the last segment's model, parameters and dt.
    for (const ScheduleLevel& level : plan.refine) {
        Segment segment{segments.back().session, std::nullopt, {}, false};
        segment.session.dt = segments.back().sessionDt;
        place(segment, session, level.width, level.height, 0);
        segment.session.steps = refineSteps(); // steps of the level's own dt
        segment.refine = true;
        segments.push_back(segment);
    }
    long long total = 0;
    for (const Segment& segment : segments)
        total += segment.session.steps;
    if (total > INT_MAX)
        throw InputError("at " + std::to_string(session.width) + " x " +
                         std::to_string(session.height) + " the session's segments take " +
                         std::to_string(total) +
                         " steps in all, more than the engine runs in one go: use fewer steps "
                         "or a smaller size");
    return segments;
}

namespace {

// A weighted atlas's plan: its substeps and the stencil it runs.
std::string describeWeightedAtlas(const Session& session) {
    std::ostringstream os;
    os << "weighted atlas (" << session.width << " x " << session.height << " texels)";
    bool said = false;
    if (session.atlasWeights->hasDiagonals()) {
        os << "; the weights' 9-point stencil runs (the cross term of sheared texels)";
        said = true;
    } else if (session.diffusion.type == DiffusionType::Isotropic &&
               session.diffusion.stencil == Stencil::NinePoint) {
        os << "; the 9-point stencil runs as the weighted 5-point Laplacian (the weights have "
              "no diagonals)";
        said = true;
    }
    if (session.atlasWeights->tensor && session.diffusion.type == DiffusionType::Anisotropic) {
        os << "; anisotropic: each chemical's tensor follows the surface's direction field ("
           << toString(session.surface.direction) << ")";
        said = true;
    }
    const int substeps =
        session.integrator == Integrator::ExplicitEuler ? atlasSubsteps(session) : 1;
    if (substeps > 1) {
        os << "; every step runs as " << substeps << " steps of dt/" << substeps
           << " (the largest sum of a texel's weights is "
           << maxCoefficientSum(*session.atlasWeights) << ", above the unit grid's 4)";
        said = true;
    }
    return said ? os.str() : std::string();
}

} // namespace

std::string describePlan(const Session& session) {
    if (session.atlas && session.atlasWeights)
        return describeWeightedAtlas(session);
    if (session.length <= 0 || session.tiles.active() || session.atlas)
        return {};
    const std::vector<Segment> segments = segmentsOf(session);
    auto size = [](const Session& s) {
        return std::to_string(s.width) + " x " + std::to_string(s.height);
    };
    auto steps = [](const Segment& s) {
        std::string text = std::to_string(s.session.steps) + " steps";
        if (s.substeps > 1)
            text += " of dt/" + std::to_string(s.substeps);
        return text;
    };
    std::ostringstream os;
    os << size(session) << " is " << session.length << " units wide (" << session.cellSize()
       << " per cell)";
    const Segment& first = segments.front();
    const bool refines = segments.back().refine;
    if (!refines && first.substeps == 1 && session.cellSize() == 1.0)
        return {};
    if (refines) {
        std::size_t own = 0;
        long long ownSteps = 0;
        for (; own < segments.size() && !segments[own].refine; ++own)
            ownSteps += segments[own].session.steps;
        os << "; coarse-to-fine: the session's steps at " << size(first.session) << " (" << ownSteps
           << " steps" << (first.substeps > 1 ? " of dt/" + std::to_string(first.substeps) : "")
           << "), then refined at";
        for (std::size_t i = own; i < segments.size(); ++i)
            os << (i == own ? " " : ", ") << size(segments[i].session) << " (" << steps(segments[i])
               << ")";
    } else if (first.substeps > 1) {
        os << "; every step runs as " << first.substeps << " steps of dt/" << first.substeps
           << " (the explicit limit shrinks with the cell size squared)";
    }
    return os.str();
}

} // namespace morphogen
