#include "cli/render_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/colormap.hpp"
#include "core/errors.hpp"
#include "core/image_io.hpp"
#include "core/stability.hpp"

namespace morphogen::cli {

void checkStability(Session& session, bool verbose) {
    if (session.integrator == Integrator::SemiImplicit) {
        if (!verbose)
            return;
        const StepConstants k = StepConstants::fromSession(session);
        std::fprintf(stderr,
                     "morphogen: semi-implicit step: %d relaxation sweeps, residual factor %.3g "
                     "per sweep (%.2g per step) from the operator's symbol\n",
                     k.jacobiSweeps, k.contraction, std::pow(k.contraction, k.jacobiSweeps));
        return;
    }
    const ExplicitStability st =
        explicitStability(compileDiffusion(session), session.width, session.height, session.dt);
    if (!st.maxStableDt) {
        std::ostringstream os;
        os << "the diffusion operator has Fourier modes that grow for every explicit time step "
              "(max Re(lambda) = "
           << st.maxRealPart
           << "); set \"stabilize\": true in its diffusion block, or use --integrator "
              "semi_implicit";
        throw InputError(os.str());
    }
    if (session.dt > *st.maxStableDt) {
        const float capped = float(0.9 * *st.maxStableDt);
        std::fprintf(stderr,
                     "morphogen: warning: dt %g exceeds the explicit stability limit %.4g "
                     "(%s); capped to %.4g\n",
                     session.dt, *st.maxStableDt,
                     st.exact ? "spectral radius of I + dt A from the kernel's Fourier symbol"
                              : "Gershgorin bound of the diffusion map",
                     capped);
        session.dt = capped;
    } else if (st.exact && verbose) {
        std::fprintf(stderr,
                     "morphogen: explicit step: spectral radius of I + dt A = %.4f at dt %g "
                     "(largest stable dt %.4g)\n",
                     st.spectralRadius, session.dt, *st.maxStableDt);
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
