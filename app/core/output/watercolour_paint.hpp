#pragma once

#include <array>
#include <vector>

#include "core/base/state.hpp"
#include "core/domain/grid_domain.hpp"

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

// The dark edge a wash leaves where it dries, as a render effect (the
// image-space edge darkening of Bousseau et al. 2006, and Curtis et al.
// 1997's darkening at the edge of the wet-area mask), not a flow in the
// simulation: this model's linear diffusion cannot carry pigment to a pinned
// edge (watercolour.hpp), so its own rim is only ~1.08x its middle.
// The wet-area mask is where the paper was wet, m = smoothstep(kWetEdge) of
// the water gone g (smooth: water moves fast; 1 inside a wash however deep
// it was). Its band
//   band = max(0, near(m) - wide(m))
// is 0 inside a wash and on dry paper and peaks just inside the wash's edge,
// fading inwards over the width; near is a box blur of radius
// round(width / 3) cells, wide two box blurs of radius round(width) cells,
// width = edgeWidth x the image's width in cells (the same look at any size,
// as strokes are sized). The painter multiplies a texel's deposits by
// 1 + edgeDarkening band / crispPeak: a wash with a sharp edge is painted
// 1 + edgeDarkening times denser at the band's peak, one whose mask rises
// over several cells less. Suspended (wet) pigment is not darkened. Two
// washes painted into each other wet share one wet area (no edge between
// them, as wet-in-wet has none). Blurs read across the image's border as the
// session's edges do (periodic wraps, clamped repeats the border texel); the
// row passes use running sums (O(1) a texel whatever the width).
class WatercolourEdges {
public:
    // Water gone over which the mask rises from 0 to 1 (a smoothstep).
    static constexpr float kWetEdge[2] = {0.15f, 0.45f};

    WatercolourEdges(const State& state, float edgeWidth, EdgeMode edges);
    // The band at cell (x, y), row-major, width x height.
    const float* band() const { return m_band.data(); }
    // 1 / crispPeak of this state's radii: what the painter scales the band by.
    float scale() const { return m_scale; }
    // The radii in cells (near, wide) for a state `width` cells wide.
    static std::array<int, 2> radii(int width, float edgeWidth);
    // The band's largest value across a sharp, straight edge of a wash for
    // these radii (wider boxes blur the edge further: a smaller peak).
    static float crispPeak(const std::array<int, 2>& radii);

private:
    std::vector<float> m_band;
    float m_scale = 1.0f;
};

// Paints row y of a watercolour-model state (WatercolourModel's chemical
// layout) as interleaved RGB in [0, 1], width * 3 values. With `edges`, the
// deposits are darkened at the edges of the wet area (WatercolourEdges).
void paintWatercolourRow(const State& state, int y, const WatercolourLook& look, float* rgb,
                         const WatercolourEdges* edges = nullptr, float edgeDarkening = 0.0f);

// True when the model's chemicals are the watercolour model's (what the map paints).
bool paintsAsWatercolour(const ReactionModel& model);

} // namespace morphogen
