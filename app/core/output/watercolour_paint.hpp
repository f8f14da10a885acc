#pragma once

#include <array>

#include "core/base/state.hpp"

namespace morphogen {

class ReactionModel;

// The "watercolour" colour map: the watercolour model's state painted as
// transparent layers of pigment on paper, not one chemical through a
// palette. Each pigment filters the light per channel (Beer-Lambert, the
// thin-glaze limit of Kubelka-Munk): paper * exp(-sum_i K_i (d_i + wet p_i)),
// so overlapping washes multiply (blue over sienna gives a dark neutral, as
// glazes do) and more pigment is a deeper, not a more opaque, colour.
// Suspended pigment counts at `wetShare` (wet paint is lighter: it has not
// settled into the paper yet), and standing water darkens the paper a
// little (the wet sheen). The paper's tint follows its stickiness faintly,
// so its grain shows where no paint is.
struct WatercolourLook {
    std::array<float, 3> paper = {0.97f, 0.955f, 0.915f}; // display (sRGB) values
    // Absorbance per unit density, per channel: ultramarine-like (absorbs red
    // and green) and burnt-sienna-like (absorbs green and blue).
    std::array<std::array<float, 3>, 2> absorbance = {{{2.3f, 1.5f, 0.35f}, {0.35f, 1.3f, 2.1f}}};
    float wetShare = 0.6f;
    float sheen = 0.04f; // darkening of the paper at water depth 1 and more
    float grain = 0.06f; // tint change of the paper per unit of stickiness
};

// Paints row y of a watercolour-model state (WatercolourModel's chemical
// layout) as interleaved RGB in [0, 1], width * 3 values.
void paintWatercolourRow(const State& state, int y, const WatercolourLook& look, float* rgb);

// True when the model's chemicals are the watercolour model's (what the map paints).
bool paintsAsWatercolour(const ReactionModel& model);

} // namespace morphogen
