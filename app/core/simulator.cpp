#include "core/simulator.hpp"

namespace morphogen {

StepConstants StepConstants::fromSession(const Session& session) {
    const ReactionModel& model = session.reactionModel();
    StepConstants k;
    k.chemicals = int(model.chemicals().size());
    k.dt = session.dt;
    k.stencil = session.diffusion.stencil;
    k.domain = session.domain();
    k.params = model.packParams(session.params);
    k.op = compileDiffusion(session);
    for (int c = 0; c < 4; ++c) {
        if (c < k.chemicals) {
            const ChemicalSpec& spec = model.chemicals()[std::size_t(c)];
            k.diffusion[c] = spec.diffusionParam.empty() ? 0.0f
                                                         : session.params.at(spec.diffusionParam);
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
