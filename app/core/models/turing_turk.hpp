#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Turing's spot system as Turk 1991 writes it:
//   da/dt = s (16 - a b) + Da lap a
//   db/dt = s (a b - b - beta) + Db lap b,   b >= 0
// beta is a per-cell field, beta_mean +- beta_noise, drawn once from the seed:
// it is stored as a third chemical that neither diffuses nor reacts.
//
// Scaling: Turk's literal Da = 0.125, Db = 0.03125 with dt = 1 puts the
// s = 0.2 pattern at the grid's Nyquist mode (a 2-pixel checkerboard). We keep
// his 4:1 ratio and scale both rates by 8 (Da = 1, Db = 0.25), with dt = 0.18
// (stable up to ~0.22): s = 0.05 then gives spots of wavelength ~14 cells and
// s = 0.2 ~7 cells. The 4:1 ratio sits exactly on the Turing threshold, so the
// pattern grows from the beta noise and the nonlinearity: large spots need
// ~5000 steps. b must be clamped at 0 or both sizes blow up.
class TuringTurkModel : public ReactionModel {
public:
    struct Cell {
        static constexpr int kChemicals = 3;
        // beta is a fixed per-cell field, not a chemical that spreads.
        static constexpr bool diffuses(int chemical) { return chemical != 2; }
        explicit Cell(const float* p) : s(p[0]) {}
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            const float ab = c[0] * c[1];
            dcdt[0] = s * (16.0f - ab);
            dcdt[1] = s * (ab - c[1] - c[2]);
            dcdt[2] = 0.0f;
        }
        float s;
    };

    TuringTurkModel();
    void react(const RowView& row, const float* params) const override;
    void prepareState(State& state, const ParamValues& values,
                      const NoiseField& noise) const override;
};

} // namespace morphogen
