#pragma once

#include "core/reaction_model.hpp"

namespace morphogen {

// Turing's activator-substrate system as McGraw writes it (eq. 2):
//   du/dt = du lap u + u v - u - alpha
//   dv/dt = dv lap v + beta - u v
// alpha = 12, beta = 16 with u = v = 4 is a steady state; beta = 15 patterns.
class TuringMcGrawModel : public ReactionModel {
public:
    TuringMcGrawModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
