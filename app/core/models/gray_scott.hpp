#pragma once

#include "core/reaction_model.hpp"

namespace morphogen {

// Gray-Scott (McGraw eq. 3-4): du/dt = Du lap u - u v^2 + F (1 - u),
//                               dv/dt = Dv lap v + u v^2 - (F + k) v.
// Pearson's scaling: Du = 2e-5, Dv = 1e-5 on a 2.5-wide domain of 256 cells
// gives Du = 0.2097, Dv = 0.105 per cell^2 (we step with dt = 0.9, see the .cpp).
class GrayScottModel : public ReactionModel {
public:
    GrayScottModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
