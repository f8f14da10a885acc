#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Turing's activator-substrate system as McGraw writes it (eq. 2):
//   du/dt = du lap u + u v - u - alpha
//   dv/dt = dv lap v + beta - u v
// alpha = 12, beta = 16 with u = v = 4 is a steady state; beta = 15 patterns.
//
// Scaling: McGraw's dt = 0.1 comes with his own grid spacing. On a unit grid a
// visible wavelength (~8 cells) needs du = 2, dv = 8, and explicit Euler is
// then stable only for dt <~ 0.025 (u peaks near 30 in the transient), so the
// default is dt = 0.02. The semi-implicit solver is the way to larger steps.
// u, v >= 0 is enforced: without it every run tried went to NaN.
class TuringMcGrawModel : public ReactionModel {
public:
    struct Cell {
        static constexpr int kChemicals = 2;
        static constexpr bool diffuses(int) { return true; }
        explicit Cell(const float* p) : alpha(p[0]), beta(p[1]) {}
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            const float uv = c[0] * c[1];
            dcdt[0] = uv - c[0] - alpha;
            dcdt[1] = beta - uv;
        }
        float alpha, beta;
    };

    TuringMcGrawModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
