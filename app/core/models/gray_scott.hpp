#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Gray-Scott (McGraw eq. 3-4): du/dt = Du lap u - u v^2 + F (1 - u),
//                               dv/dt = Dv lap v + u v^2 - (F + k) v.
// Pearson's scaling: Du = 2e-5, Dv = 1e-5 on a 2.5-wide domain of 256 cells
// gives Du = 0.2097, Dv = 0.105 per cell^2 (we step with dt = 0.9, see the .cpp).
class GrayScottModel : public ReactionModel {
public:
    struct Cell {
        static constexpr int kChemicals = 2;
        static constexpr bool diffuses(int) { return true; }
        explicit Cell(const float* p) : F(p[0]), k(p[1]) {}
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            const float uvv = c[0] * c[1] * c[1];
            dcdt[0] = -uvv + F * (1.0f - c[0]);
            dcdt[1] = uvv - (F + k) * c[1];
        }
        float F, k;
    };

    GrayScottModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
