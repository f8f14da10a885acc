#pragma once
// Flags shared by `map` and `sweep`, which both explore two parameters.

#include <string>

#include "core/session/session.hpp"
#include "core/sim/sweep.hpp"

namespace morphogen::cli {

// "PARAM:MIN:MAX" for `flag`; throws InputError naming the flag, the text and
// the parameter's accepted range.
SweepAxis parseAxis(const std::string& flag, const std::string& text, const ReactionModel& model);

// The session an exploration starts from: a preset, or a model's defaults
// (its default dt and start, 10000 steps, viridis). Exactly one of the two
// names must be given.
Session explorationBase(const std::string& model, const std::string& preset,
                        const std::string& name);

// A model's default seed-spot start, about to run on side x side cells, keeps
// the spot density it has on the default grid, so every region of a large
// map or tile starts; a preset's start (`fromPreset`) is left as its author made it.
void keepSeedSpotDensity(Session& s, int side, bool fromPreset);

} // namespace morphogen::cli
