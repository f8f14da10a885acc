#include "core/stability.hpp"

#include "core/diffusion_operator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace morphogen {

float stableDiffusionDt(Stencil stencil, float maxDiffusion) {
    const float symbol = stencil == Stencil::FivePoint ? 8.0f : 16.0f / 3.0f;
    if (maxDiffusion <= 0.0f)
        return std::numeric_limits<float>::infinity();
    return 2.0f / (symbol * maxDiffusion);
}

float suggestDt(const Session& session) {
    const double bound = diffusionSymbolBound(compileDiffusion(session));
    const float limit = bound > 0 ? float(2.0 / bound) : std::numeric_limits<float>::infinity();
    // 0.8 of the diffusion limit leaves room for the reaction term's own stiffness.
    return std::min(0.5f * session.dt, 0.8f * limit);
}

std::optional<std::string> findInsaneValue(const State& state, const ReactionModel& model) {
    for (int c = 0; c < state.channels(); ++c) {
        const ChemicalSpec& spec = model.chemicals()[std::size_t(c)];
        const float* p = state.plane(c);
        for (std::size_t i = 0; i < state.cellCount(); ++i) {
            const float v = p[i];
            if (std::isfinite(v) && v >= spec.saneMin && v <= spec.saneMax)
                continue;
            std::ostringstream os;
            os << "chemical " << spec.name << " = " << v << " at (" << i % state.width() << ", "
               << i / state.width() << ")";
            if (std::isfinite(v))
                os << ", outside its sane range [" << spec.saneMin << ", " << spec.saneMax << "]";
            return os.str();
        }
    }
    return std::nullopt;
}

} // namespace morphogen
