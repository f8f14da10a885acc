#include "core/sim/stability_check.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/operators/stability.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

namespace {

template <typename... Args> std::string format(const char* pattern, Args... args) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, pattern, args...);
    return buffer;
}

// The explicit step's stability for one segment: sets report.refused for an
// operator that grows for every dt; returns the dt to use (capped, with a
// warning, when `dt` is above the limit). `what` names the segment in messages.
float checkExplicitStep(const Session& segment, const std::string& what, bool verbose,
                        StabilityReport& report) {
    const ExplicitStability st =
        explicitStability(compileDiffusion(segment), segment.domain(), segment.dt);
    if (!st.maxStableDt) {
        std::ostringstream os;
        os << what
           << "the diffusion operator has Fourier modes that grow for every explicit time step "
              "(max Re(lambda) = "
           << st.maxRealPart
           << "); set \"stabilize\": true in its diffusion block, or use --integrator "
              "semi_implicit";
        report.refused = os.str();
        return segment.dt;
    }
    if (segment.dt > *st.maxStableDt) {
        const float capped = float(0.9 * *st.maxStableDt);
        report.notes.push_back(
            {true, format("%sdt %g exceeds the explicit stability limit %.4g (%s); capped to %.4g",
                          what.c_str(), double(segment.dt), *st.maxStableDt, st.basis.c_str(),
                          double(capped))});
        report.capped = true;
        return capped;
    }
    if (!st.exact && verbose)
        report.notes.push_back(
            {false, format("%sexplicit step: dt %g within the %s (largest stable dt %.4g)",
                           what.c_str(), double(segment.dt), st.basis.c_str(), *st.maxStableDt)});
    if (st.exact && verbose)
        report.notes.push_back(
            {false, format("%sexplicit step: spectral radius of I + dt A = %.4f at dt %g (largest "
                           "stable dt %.4g)",
                           what.c_str(), st.spectralRadius, double(segment.dt), *st.maxStableDt)});
    return segment.dt;
}

} // namespace

StabilityReport checkSessionStability(Session& session, bool verbose) {
    StabilityReport report;
    if (session.integrator == Integrator::SemiImplicit) {
        if (!verbose)
            return report;
        const StepConstants k = StepConstants::fromSession(session);
        report.notes.push_back(
            {false, format("semi-implicit step: %d relaxation passes, residual factor %.3g per "
                           "sweep (%.2g per step) from the operator's symbol",
                           k.relaxationPasses, k.contraction,
                           std::pow(k.contraction, k.relaxationPasses))});
        return report;
    }
    if (session.stages.empty()) {
        session.dt = checkExplicitStep(session, "", verbose, report);
        return report;
    }
    for (std::size_t i = 0; i < session.stages.size(); ++i) {
        const Session stage = segmentSessions(session)[i];
        const std::string what =
            session.stages.size() > 1 ? "stage " + std::to_string(i + 1) + ": " : "";
        const float dt = checkExplicitStep(stage, what, verbose, report);
        if (report.refused)
            break;
        if (dt == stage.dt)
            continue;
        if (i == 0 && !session.stages[0].dt)
            session.dt = dt;
        else
            session.stages[i].dt = dt;
    }
    return report;
}

} // namespace morphogen
