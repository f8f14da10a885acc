#pragma once
// Flags shared by `map` and `sweep`, which both explore two parameters.

#include <string>

#include "core/session/session.hpp"
#include "core/sim/exploration_points.hpp"
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

// --start: noise or preset; InputError naming the text and what is accepted.
ExplorationStart parseStartFlag(const std::string& text);

// Sets the start a map or sweep runs from on side x side cells (a map's grid,
// a sweep's tile): the model's noise start (noiseStart), or the preset's or
// model's own (keepSeedSpotDensity).
void useStart(Session& s, ExplorationStart start, int side, bool fromPreset);

// What a session's description says about its start, for the written sessions.
std::string startDescription(ExplorationStart start);

// --pick-size: a picked session's side in cells.
void checkPickSize(int size);

// Writes a picked session to `path` and says on stdout what was picked
// (`what`, e.g. "column 2, row 5 of the 4x8 grid"), its values of the two
// swept parameters, and where it went.
void writePick(const Session& picked, const std::string& path, const std::string& what,
               const SweepAxis& x, const SweepAxis& y);

} // namespace morphogen::cli
