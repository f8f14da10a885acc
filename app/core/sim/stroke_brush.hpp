#pragma once

#include "core/session/live_edit.hpp"
#include "core/sim/brush.hpp"

namespace morphogen {

// The cells a recorded stroke covers on a grid of `domain`'s size: the disc of
// the stroke's radius swept along its path (a dab for one point), with the
// disc brush's falloff profile of the distance to the path. Canvas fractions
// become cells as cell (x, y) covers [x, x+1) x [y, y+1) of a width x height
// canvas. Periodic edges wrap the stroke; clamped edges cut it.
BrushRegion strokeRegion(const StrokeSpec& stroke, const Domain& domain);

// The brush write of a stroke for the model in force (its chemical and
// parameter names resolved). Throws InputError when the model lacks the
// stroke's chemical or parameter (a stage switched models), naming both.
Brush strokeBrush(const StrokeSpec& stroke, const ReactionModel& model, const Domain& domain);

} // namespace morphogen
