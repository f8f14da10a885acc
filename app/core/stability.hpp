#pragma once

#include <optional>
#include <string>

#include "core/session.hpp"
#include "core/state.hpp"

namespace morphogen {

// Largest explicit Euler dt for which pure diffusion at rate maxD stays
// stable: dt * maxD * |lambda_max| <= 2, with |lambda_max| the stencil's
// largest symbol magnitude (8 for 5-point, 16/3 for 9-point).
float stableDiffusionDt(Stencil stencil, float maxDiffusion);

// A dt to suggest after a blow-up: below the diffusion limit and below the dt
// that failed.
float suggestDt(const Session& session);

// Finds the first cell whose value is NaN/Inf or outside the model's sane
// range; returns a description ("chemical v = nan at (12, 40)") or nullopt.
std::optional<std::string> findInsaneValue(const State& state, const ReactionModel& model);

} // namespace morphogen
