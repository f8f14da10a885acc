#include "cli/render_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/output/colormap.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/sim/runner.hpp"
#include "core/operators/stability.hpp"

namespace morphogen::cli {

namespace {

// The explicit step's stability for one segment: throws for an operator that
// grows for every dt; returns the dt to use (capped, with a warning, when `dt`
// is above the limit). `what` names the segment in messages.
float checkExplicitStep(const Session& segment, const std::string& what, bool verbose) {
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
        throw InputError(os.str());
    }
    if (segment.dt > *st.maxStableDt) {
        const float capped = float(0.9 * *st.maxStableDt);
        std::fprintf(stderr,
                     "morphogen: warning: %sdt %g exceeds the explicit stability limit %.4g "
                     "(%s); capped to %.4g\n",
                     what.c_str(), segment.dt, *st.maxStableDt,
                     st.basis.c_str(), capped);
        return capped;
    }
    if (!st.exact && verbose)
        std::fprintf(stderr,
                     "morphogen: %sexplicit step: dt %g within the %s (largest stable dt %.4g)\n",
                     what.c_str(), segment.dt, st.basis.c_str(), *st.maxStableDt);
    if (st.exact && verbose)
        std::fprintf(stderr,
                     "morphogen: %sexplicit step: spectral radius of I + dt A = %.4f at dt %g "
                     "(largest stable dt %.4g)\n",
                     what.c_str(), st.spectralRadius, segment.dt, *st.maxStableDt);
    return segment.dt;
}

} // namespace

void checkStability(Session& session, bool verbose) {
    if (session.integrator == Integrator::SemiImplicit) {
        if (!verbose)
            return;
        const StepConstants k = StepConstants::fromSession(session);
        std::fprintf(stderr,
                     "morphogen: semi-implicit step: %d relaxation passes, residual factor %.3g "
                     "per sweep (%.2g per step) from the operator's symbol\n",
                     k.relaxationPasses, k.contraction, std::pow(k.contraction, k.relaxationPasses));
        return;
    }
    // A schedule's coarse levels are more stable than the finest (the session
    // itself). Cascade stages may change rates, dt or the model, so each is
    // checked in order (a later stage inherits an earlier one's capped dt).
    if (session.stages.empty()) {
        session.dt = checkExplicitStep(session, "", verbose);
        return;
    }
    for (std::size_t i = 0; i < session.stages.size(); ++i) {
        const Session stage = segmentSessions(session)[i];
        const std::string what =
            session.stages.size() > 1 ? "stage " + std::to_string(i + 1) + ": " : "";
        const float dt = checkExplicitStep(stage, what, verbose);
        if (dt == stage.dt)
            continue;
        if (i == 0 && !session.stages[0].dt)
            session.dt = dt;
        else
            session.stages[i].dt = dt;
    }
}

int runChunk(const Session& session) {
    return std::max(50, std::min(500, int(4e7 / double(session.width * session.height))));
}

void writeRenderOutput(const RunResult& result, const std::string& imagePath,
                       const std::string& sessionPath, int bitDepth) {
    const Session& session = result.completed;
    const ReactionModel& model = session.outputModel(); // the final state's
    if (imageFormatForPath(imagePath) == ImageFormat::Exr) {
        std::vector<std::string> names;
        for (const ChemicalSpec& c : model.chemicals())
            names.push_back(c.name);
        writeRawImage(imagePath, result.state, names);
    } else {
        const int chemical = colormapChemical(session.colormap, model);
        writeRgbImage(imagePath, applyColormap(result.state, chemical, session.colormap),
                      session.width, session.height, bitDepth);
    }
    saveSessionFile(session, sessionPath);
}

} // namespace morphogen::cli
