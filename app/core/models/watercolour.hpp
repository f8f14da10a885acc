#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Watercolour on paper (Lo et al. section 5.6: water and pigment as chemicals
// with different diffusion rates, the paper's absorption power -- its
// "stickiness" -- per texel in the state's fourth component). Chemicals:
//   w       water standing on the paper              diffuses at Dw
//   p1, p2  pigment suspended in that water           diffuse at Dp (< Dw)
//   s       stickiness, 0..1 (the paper)             neither diffuses nor reacts
//   d1, d2  pigment deposited on the paper           no diffusion
//   g       water gone: absorbed plus evaporated     no diffusion
// c[0] = (w, p1, p2, s) is one RGBA texture, so s is its w component as Lo
// stores it; c[1] = (d1, d2, g).
//
// With r = 1 / (w + film) and q = dry / (w + dry):
//   L     = (evaporation + absorption s) w r                 water leaving
//   dw/dt = Dw lap w - L,        dg/dt = L
//   dep_i = p_i s (settle + trap q^2)                         pigment settling
//   dp_i/dt = Dp lap p_i - dep_i,  dd_i/dt = dep_i
// Why these terms:
// - Evaporation and absorption act per unit area (a rate independent of the
//   depth) while the water is deeper than `film`: thin water at the edge of a
//   wash is gone first and the wet area ends at a front, so a stroke with more
//   water stays wet longer, spreads further before its front stops, and bleeds
//   wider (Lo Fig. 9). Below `film` the loss turns linear in w (the w r
//   factor), so w never goes negative under the explicit step.
// - Pigment moves with the water, a little more slowly (Dp < Dw): where the
//   pigment's concentration p / w is even, its flux -Dp grad p is that
//   fraction of the water's flux. Our diffusion is linear, so pigment cannot
//   read the water's flux; instead the trap term settles pigment fast
//   wherever the water is thin (q^2 -> 1 on dry paper, ~0.03 at w = 1 with
//   dry = 0.2; squared so deep water keeps its pigment suspended): pigment
//   that reaches the drying front is caught there, so strokes keep edges and
//   wet-in-wet pigment bleeds softly while the water is deep.
// - Edge darkening: the front is a pigment sink for as long as the wash is
//   wet, so a very wet wash drains some pigment to its rim (measured: a dab
//   with 4 units of water dries ~1.08x darker at its rim than in its middle;
//   a moist one does not). Real washes darken more (outward flow to the
//   pinned edge, Deegan's coffee ring); linear diffusion cannot advect, and
//   that is the limit of this model.
// - Both settling terms scale with the stickiness s, so the paper's grain and
//   fibres show in the deposit (granulation); absorption also scales with s.
// - Conservation: every loss of w is a gain of g and every loss of p_i a
//   gain of d_i, and linear diffusion with periodic or clamped (zero-flux)
//   edges conserves totals, so sum(w + g) and sum(p_i + d_i) are constant
//   (up to float rounding) between strokes.
// Explicit stability: the reaction's largest linear rate is
// (evaporation + absorption) / film for w (0.12 at the defaults) and
// s (settle + trap) for p_i (0.2), added to the diffusion's 8 Dw (1.6): dt 1
// keeps 8 Dw dt + rate dt < 2, and 4 Dw dt + rate dt <= 1 keeps w, p_i >= 0
// (no overshoot below zero, so the clamps at 0 never act at the defaults).
// paper_* parameters only shape the generated stickiness (prepareState).
class WatercolourModel : public ReactionModel {
public:
    static constexpr int kPigments = 2;
    enum Chemical { W = 0, P1 = 1, P2 = 2, S = 3, D1 = 4, D2 = 5, G = 6 };

    struct Cell {
        static constexpr int kChemicals = 7;
        static constexpr bool diffuses(int chemical) { return chemical <= P2; }
        // packParams() order: Dw, Dp, evaporation, absorption, film, dry, settle, trap, paper_*.
        explicit Cell(const float* p)
            : evaporation(p[2]), absorption(p[3]), film(p[4]), dry(p[5]), settle(p[6]), trap(p[7]) {
        }
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            const float w = c[W], s = c[S];
            const float r = 1.0f / (w + film);
            const float leave = (evaporation + absorption * s) * w * r;
            const float q = dry / (w + dry);
            const float settleRate = s * (settle + trap * q * q);
            const float dep1 = c[P1] * settleRate;
            const float dep2 = c[P2] * settleRate;
            dcdt[W] = -leave;
            dcdt[P1] = -dep1;
            dcdt[P2] = -dep2;
            dcdt[S] = 0.0f;
            dcdt[D1] = dep1;
            dcdt[D2] = dep2;
            dcdt[G] = leave;
        }
        float evaporation, absorption, film, dry, settle, trap;
    };

    WatercolourModel();
    void react(const RowView& row, const float* params) const override;
    // Fills s with the generated paper (paper_texture.hpp).
    void prepareState(State& state, const ParamValues& values,
                      const NoiseField& noise) const override;
};

} // namespace morphogen
