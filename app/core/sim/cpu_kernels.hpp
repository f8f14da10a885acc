#pragma once

#include "core/models/reaction_model.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

// The CPU backend's fused row kernels: each visits a cell once, with the
// diffusion stencil, the reaction (a model's Cell, inlined) and the update in
// one vectorised loop, and an AVX2 clone picked at run time. They cover the
// homogeneous operators (Laplacian5/9, Kernel3/5) and the models with a Cell;
// a null kernel means the caller's generic path must run.

// Steps rows [y0, y1) of in into out.
using StepRowsKernel = void (*)(const StepConstants& k, const State& in, State& out, int y0,
                                int y1);
// One relaxation pass of rows [y0, y1): x' = clamp(x + omega (rhs - x + dt A x)).
using RelaxRowsKernel = void (*)(const StepConstants& k, const State& x, const State& rhs,
                                 State& out, int y0, int y1);

// Explicit Euler: out = clamp(c + dt (react(c) + A c)). Null for other models,
// models with more than four chemicals (the per-cell arrays stop vectorising:
// measured at 256^2, the generic path is 3.4x faster for meinhardt_stripes and
// 4-5x for the 3- and 5-direction Witkin-Kass models), the tensor map,
// per-cell parameters, or a diffusion operator that is zero on a chemical that
// normally diffuses (or not zero on one that does not): the generic path's
// term is then exactly 0.
// On an atlas domain the kernel treats the texture as a clamped grid: right
// for interior texels only, so the caller must redo the tile-border texels.
StepRowsKernel fusedExplicitStep(const ReactionModel& model, const StepConstants& k);

// Semi-implicit right-hand side: out = c + dt react(c). Null for other models,
// more than four chemicals and per-cell parameters.
StepRowsKernel fusedRhsPass(const ReactionModel& model, const StepConstants& k);

// Semi-implicit sweep; null for the tensor map and per-cell parameters.
RelaxRowsKernel fusedRelaxation(const StepConstants& k);

} // namespace morphogen
