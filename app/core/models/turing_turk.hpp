#pragma once

#include "core/reaction_model.hpp"

namespace morphogen {

// Turing's spot system as Turk 1991 writes it:
//   da/dt = s (16 - a b) + Da lap a
//   db/dt = s (a b - b - beta) + Db lap b,   b >= 0
// beta is a per-cell field, beta_mean +- beta_noise, drawn once from the seed:
// it is stored as a third chemical that neither diffuses nor reacts.
class TuringTurkModel : public ReactionModel {
public:
    TuringTurkModel();
    void react(const RowView& row, const float* params) const override;
    void prepareState(State& state, const ParamValues& values, std::uint64_t seed) const override;
};

} // namespace morphogen
