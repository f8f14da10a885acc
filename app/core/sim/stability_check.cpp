#include "core/sim/stability_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/limits.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/segments.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

namespace {

template <typename... Args> std::string format(const char* pattern, Args... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

// A param map of a diffusion rate sets it per cell: the step must be stable at
// the map's largest value, so the check compiles the operator with each mapped
// rate at its map's maximum. Notes name the rates raised. (On an atlas the
// mapped rates raise the substeps instead: atlasSubsteps.)
Session withFastestMappedRates(const Session& part, std::string& raised) {
    Session s = part;
    if (part.atlas)
        return s;
    for (const ChemicalSpec& c : part.reactionModel().chemicals()) {
        auto it = part.paramMaps.find(c.diffusionParam);
        if (c.diffusionParam.empty() || it == part.paramMaps.end())
            continue;
        const float fastest = std::max(it->second.min, it->second.max);
        float& rate = s.params[c.diffusionParam];
        if (rate == fastest)
            continue; // unchanged, or a second chemical of the same rate
        rate = fastest;
        raised += (raised.empty() ? " " : ", ") +
                  format("%s %g", c.diffusionParam.c_str(), double(fastest));
    }
    return s;
}

// The explicit step's stability for one segment: sets report.refused for an
// operator that grows for every dt; returns the session dt to use (capped,
// with a warning, when the segment's dt is above its limit). Values are
// session dts: a segment of substeps runs dt / substeps. `what` names the
// segment in messages.
float checkExplicitStep(const Segment& segment, const std::string& what, bool verbose,
                        StabilityReport& report) {
    std::string raised;
    const Session part = withFastestMappedRates(segment.session, raised);
    const double k = segment.substeps;
    const DiffusionOperator op = compileDiffusion(part);
    if (!raised.empty() && verbose)
        report.notes.push_back(
            {false, what +
                        "the stability check takes each mapped diffusion rate at its map's "
                        "largest value:" +
                        raised});
    const ExplicitStability st =
        part.atlasWeights && part.atlasWeights->tensor &&
                part.diffusion.type == DiffusionType::Anisotropic
            ? tensorAtlasStability(*part.atlasWeights, sessionTensorMixes(part, op.rates.data()))
            : explicitStability(op, part.domain(), part.dt);
    if (!st.maxStableDt) {
        std::ostringstream os;
        os << what
           << "the diffusion operator has Fourier modes that grow for every explicit time step "
              "(max Re(lambda) = "
           << st.maxRealPart
           << "); set \"stabilize\": true in its diffusion block, or use --integrator "
              "semi_implicit";
        report.refused = os.str();
        return segment.sessionDt;
    }
    const double limit = *st.maxStableDt * k;
    const std::string steps =
        segment.substeps > 1 ? format(" (%d steps of dt/%d)", segment.substeps, segment.substeps)
                             : std::string();
    if (part.dt > *st.maxStableDt) {
        const float capped = float(0.9 * limit);
        // A session of a smaller dt could not be read back (nor run in useful time).
        if (!(capped >= float(kMinDt))) {
            report.refused = format(
                "%sthe explicit stability limit is dt %.3g%s (%s), below the smallest accepted dt "
                "%g: the diffusion is too fast for explicit steps; lower its rates or tensor "
                "components, or use --integrator semi_implicit",
                what.c_str(), limit, steps.c_str(), st.basis.c_str(), kMinDt);
            return segment.sessionDt;
        }
        report.notes.push_back(
            {true,
             format("%sdt %g exceeds the explicit stability limit %.4g%s (%s%s); capped to %.4g",
                    what.c_str(), double(segment.sessionDt), limit, steps.c_str(), st.basis.c_str(),
                    raised.empty() ? "" : ("; param maps at their largest:" + raised).c_str(),
                    double(capped))});
        report.capped = true;
        return capped;
    }
    if (!st.exact && verbose)
        report.notes.push_back(
            {false,
             format("%sexplicit step: dt %g within the %s (largest stable dt %.4g%s)", what.c_str(),
                    double(segment.sessionDt), st.basis.c_str(), limit, steps.c_str())});
    if (st.exact && verbose)
        report.notes.push_back(
            {false, format("%sexplicit step: spectral radius of I + dt A = %.4f at dt %g (largest "
                           "stable dt %.4g%s)",
                           what.c_str(), st.spectralRadius, double(segment.sessionDt), limit,
                           steps.c_str())});
    return segment.sessionDt;
}

} // namespace

StabilityReport checkSessionStability(Session& session, bool verbose) {
    StabilityReport report;
    const std::vector<Segment> segments = segmentsOf(session);
    if (session.integrator == Integrator::SemiImplicit) {
        if (!verbose)
            return report;
        // The finest segment's operator is the stiffest.
        const StepConstants k = StepConstants::fromSession(segments.back().session);
        if (k.weighted()) {
            // The chemicals that reach that residual in fewer passes.
            const ReactionModel& model = segments.back().session.reactionModel();
            std::string fewer;
            for (int c = 0; c < k.chemicals; ++c)
                if (const int own = chemicalRelaxationPasses(k, c); own < k.relaxationPasses)
                    fewer += (fewer.empty() ? "" : ", ") + model.chemicals()[std::size_t(c)].name +
                             " " + std::to_string(own);
            report.notes.push_back(
                {false, format("semi-implicit step: %d Jacobi passes on the weighted atlas, "
                               "stable at any dt; the slowest texel's residual factor is %.3g "
                               "per pass (%.2g per step; the others' are smaller)%s%s",
                               k.relaxationPasses, k.contraction,
                               std::pow(k.contraction, k.relaxationPasses),
                               fewer.empty() ? ""
                                             : "; chemicals that get there in fewer passes "
                                               "stop then: ",
                               fewer.c_str())});
            return report;
        }
        report.notes.push_back(
            {false, format("semi-implicit step: %d relaxation passes, residual factor %.3g per "
                           "sweep (%.2g per step) from the operator's symbol",
                           k.relaxationPasses, k.contraction,
                           std::pow(k.contraction, k.relaxationPasses))});
        return report;
    }
    if (session.stages.empty()) {
        // Levels share the session's dt: the lowest limit over them caps it.
        // The finest level is the one reported.
        float dt = session.dt;
        for (std::size_t i = 0; i < segments.size() && !report.refused; ++i) {
            const bool last = i + 1 == segments.size();
            dt = std::min(dt, checkExplicitStep(segments[i], "", verbose && last, report));
        }
        session.dt = dt;
        return report;
    }
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Segment& segment = segments[i];
        // A refinement level continues the last stage.
        const std::size_t stage = std::min(i, session.stages.size() - 1);
        const std::string what =
            session.stages.size() > 1 ? "stage " + std::to_string(stage + 1) + ": " : "";
        const float dt = checkExplicitStep(segment, what, verbose && !segment.refine, report);
        if (report.refused)
            break;
        if (dt == segment.sessionDt)
            continue;
        if (stage == 0 && !session.stages[0].dt)
            session.dt = std::min(session.dt, dt);
        else
            session.stages[stage].dt = std::min(session.stages[stage].dt.value_or(dt), dt);
    }
    return report;
}

} // namespace morphogen
