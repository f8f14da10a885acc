#pragma once

#include "core/session/live_edit.hpp"
#include "core/sim/brush.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace morphogen {

// Per atlas cell, its centre on the mesh (Session::atlasPositions).
using AtlasPositions = std::vector<std::array<float, 3>>;

// The cells a recorded stroke covers on a grid of `domain`'s size: the disc of
// the stroke's radius swept along its path (a dab for one point), with the
// disc brush's falloff profile of the distance to the path. Canvas fractions
// become cells as cell (x, y) covers [x, x+1) x [y, y+1) of a width x height
// canvas. Periodic edges wrap the stroke; clamped edges cut it.
// A surface stroke: the used atlas texels whose centre (`positions`) lies
// within the radius of the path in 3D, with the same profile; InputError
// without positions.
BrushRegion strokeRegion(const StrokeSpec& stroke, const Domain& domain,
                         const AtlasPositions* positions = nullptr);

// The distance from a surface stroke's path to the nearest used texel centre
// (`atlas` null: every position counts); infinity without positions. A stroke
// whose distance passes its radius paints nothing.
double nearestTexelDistance(const StrokeSpec& stroke, const AtlasPositions& positions,
                            const Atlas* atlas);

// The brush write of a stroke for the model in force (its chemical and
// parameter names resolved). Throws InputError when the model lacks the
// stroke's chemical or parameter (a stage switched models), naming both.
Brush strokeBrush(const StrokeSpec& stroke, const ReactionModel& model, const Domain& domain,
                  const AtlasPositions* positions = nullptr);

// What a stroke has covered so far, per cell: the largest weight any of its
// pieces gave the cell (chemical modes).
using StrokeCoverage = std::unordered_map<std::uint32_t, float>;
// A stroke's coverage per chemical it writes: a watercolour brush lays water
// and pigment along one drag, piece by piece, each up to its own amount.
using StrokeCoverages = std::unordered_map<std::string, StrokeCoverage>;

// The part of `piece` (one piece of a stroke) that the stroke has not
// covered yet: each cell's weight becomes the rise of its coverage, and
// cells the stroke already covered as much drop out; `coverage` is updated.
// A chemical brush then changes a cell by at most its full amount over the
// stroke, whatever the order and overlap of the pieces.
BrushRegion uncoveredPart(const BrushRegion& piece, StrokeCoverage& coverage, const Domain& domain);

} // namespace morphogen
