#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Meinhardt's five-chemical stripe system (Meinhardt 1982, "Models of
// Biological Pattern Formation"), as given in the appendix of Turk 1991,
// "Generating Textures on Arbitrary Surfaces Using Reaction-Diffusion":
//   dg1/dt = c s2 g1^2 sub / r - alpha g1 + Dg lap g1 + rho0
//   dg2/dt = c s1 g2^2 / r     - alpha g2 + Dg lap g2 + rho0
//   dr/dt  = c s2 g1^2 sub + c s1 g2^2 - beta r          (r does not diffuse)
//   ds1/dt = gamma (g1 - s1) + Ds lap s1 + rho1
//   ds2/dt = gamma (g2 - s2) + Ds lap s2 + rho1
// g1 and g2 mark the two stripe colours; r makes them exclude each other
// locally; s1, s2 (each made by one colour, each feeding the other colour)
// limit a stripe's width. `sub` is Turk's "substrate": a per-cell field that
// neither diffuses nor reacts (a sixth channel, like turing_turk's beta),
// 1 + U(-0.005, 0.005) in the default start. Its noise is the only thing that
// breaks the symmetry: with sub = 1 everywhere the homogeneous steady state
//   g1 = g2 = s1 = s2 = beta / (2 alpha),  r = 2 c g^3 / beta
// (the default start) never changes, and a single cell with a raised sub (or
// raised g1) is a "stripe initiator" from which regular stripes radiate.
//
// Parameters map to Turk's program (his port of Meinhardt's FORTRAN) as:
// c = 0.01, alpha = 0.04, beta = 0.06, gamma = 0.04, rho0 = rho1 = 0 and his
// two diffusion rates Dx -> Dg (g1, g2) and Dy -> Ds (s1, s2). The defaults
// keep these rates and his diffusion rates unscaled: Dg = 0.009, Ds = 0.2 on
// the 5-point Laplacian (neighbours - 4 centre) with dt = 1. Unlike Turk's
// Turing rates (turing_turk.hpp) they need no scaling on our grid: the stripe
// period is ~8.5 cells (each colour ~4 cells wide), growing like sqrt(Dg)
// (measured at 128^2: Dg 0.02 ~13 cells, Turk's lionfish Dg 0.1 ~32). Dg
// must stay well below Ds (Dg = Ds = 0.2 gives a single blob). Explicit
// Euler needs Ds dt <= 0.25 for the 5-point stencil: Ds above ~0.24 needs a
// smaller dt.
//
// The local kinetics of g and r are an activator-inhibitor pair that is only
// stable while r is faster than g (beta > alpha: damped oscillations with a
// period of ~130 time units). A cell that also loses g by diffusion to frozen
// neighbours with g ~ 0 (a pocket in a cascade) has an effectively larger
// alpha, and its oscillation can grow into spikes that explicit Euler at
// dt = 1 turns into a blow-up (stopped by the sane-range check): seen with
// turk_giraffe's rule widened to b <= 6 (dt 0.5 got through). Freeze rules
// that leave wider gaps (turk_giraffe: b <= 3) avoid such pockets.
//
// r is divided by: it is clamped to >= 1e-4 after every step, and the reaction
// divides by max(r, 1e-4), so a start or reset with r = 0 cannot produce a NaN.
class MeinhardtStripesModel : public ReactionModel {
public:
    static constexpr float kMinR = 1e-4f;

    struct Cell {
        static constexpr int kChemicals = 6;
        // g1, g2, s1, s2 diffuse; r and the substrate do not.
        static constexpr bool diffuses(int chemical) {
            return chemical == 0 || chemical == 1 || chemical == 3 || chemical == 4;
        }
        // packParams() order: c, alpha, beta, gamma, Dg, Ds, rho0, rho1.
        explicit Cell(const float* p)
            : c(p[0]), alpha(p[1]), beta(p[2]), gamma(p[3]), rho0(p[6]), rho1(p[7]) {}
        MORPHOGEN_CELL_REACT void react(const float* x, float* dcdt) const {
            const float g1 = x[0], g2 = x[1], r = x[2], s1 = x[3], s2 = x[4], sub = x[5];
            // A select, not a branch: it vectorises.
            const float rSafe = r > kMinR ? r : kMinR;
            const float p1 = c * s2 * g1 * g1 * sub;
            const float p2 = c * s1 * g2 * g2;
            dcdt[0] = p1 / rSafe - alpha * g1 + rho0;
            dcdt[1] = p2 / rSafe - alpha * g2 + rho0;
            dcdt[2] = p1 + p2 - beta * r;
            dcdt[3] = gamma * (g1 - s1) + rho1;
            dcdt[4] = gamma * (g2 - s2) + rho1;
            dcdt[5] = 0.0f;
        }
        float c, alpha, beta, gamma, rho0, rho1;
    };

    MeinhardtStripesModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
