#pragma once

#include <array>
#include <cstdint>

#include "core/models/reaction_model.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

// The CPU backend's fused row kernels: each visits a cell once, with the
// diffusion stencil, the reaction (a model's Cell, inlined) and the update in
// one vectorised loop, and an AVX2 clone picked at run time. They cover the
// homogeneous operators (Laplacian5/9, Kernel3/5) and the models with a Cell;
// a null kernel means the caller's generic path must run.

// How both CPU paths sum a Kernel3/Kernel5 operator's taps, so that the fused
// kernels and the generic path agree bit for bit: the centre first, then each
// ring outwards, row by row (glsl/step.frag's order). When every chemical's
// kernel is centrally symmetric, each tap equal in float to its point mirror
// (even-order terms only: Table 2 sets a, b, d, e, f and every Witkin-Kass
// mask), the sum is folded: after the centre, each tap of the first half of a
// ring stands for itself and its mirror, w * (c(dx, dy) + c(-dx, -dy)), 13
// multiplies for a 5x5 kernel instead of 25 (5 instead of 9 for a 3x3). One
// decision for all chemicals, because a fused kernel sums them all one way.
struct KernelTap {
    int dx = 0, dy = 0;
    float weight = 0.0f;
};
struct KernelTaps {
    bool folded = false;
    int radius = 1; // 1: 3x3, 2: 5x5
    int count = 0;  // taps[0, count) in summation order
    std::array<KernelTap, 25> taps{};
};
bool foldsKernels(const DiffusionOperator& op);
KernelTaps kernelTaps(const DiffusionOperator& op, int chemical);

// Steps rows [y0, y1) of in into out.
using StepRowsKernel = void (*)(const StepConstants& k, const State& in, State& out, int y0,
                                int y1);
// One relaxation pass of rows [y0, y1): x' = clamp(x + omega (rhs - x + dt A x)).
using RelaxRowsKernel = void (*)(const StepConstants& k, const State& x, const State& rhs,
                                 State& out, int y0, int y1);

// Explicit Euler: out = clamp(c + dt (react(c) + A c)). Null for other models
// (not built in), the tensor map,
// per-cell parameters, or a diffusion operator that is zero on a chemical that
// normally diffuses (or not zero on one that does not): the generic path's
// term is then exactly 0.
// On an atlas domain the kernel treats the texture as a clamped grid: right
// for interior texels only, so the caller must redo the tile-border texels.
// Null on a weighted atlas: see fusedWeightedStep.
StepRowsKernel fusedExplicitStep(const ReactionModel& model, const StepConstants& k);

// Steps rows [y0, y1), columns [x0, x1) of in into out.
using StepTileKernel = void (*)(const StepConstants& k, const State& in, State& out, int y0, int y1,
                                int x0, int x1);
// Explicit Euler on a weighted atlas whose tiles are padded by halos
// (PaddedAtlasStep), with the weights' planes laid out as the padded texture.
// Null where fusedExplicitStep would be null on a grid, and for other domains.
StepTileKernel fusedWeightedStep(const ReactionModel& model, const StepConstants& k);

// Semi-implicit right-hand side: out = c + dt react(c). Null for other models
// and per-cell parameters.
StepRowsKernel fusedRhsPass(const ReactionModel& model, const StepConstants& k);

// The same on rows [y0, y1), columns [x0, x1) of a weighted atlas padded by
// halos (PaddedAtlasStep). Null for other models and per-cell parameters.
StepTileKernel fusedRhsTilePass(const ReactionModel& model, const StepConstants& k);

// Semi-implicit sweep; null for the tensor map and per-cell parameters.
RelaxRowsKernel fusedRelaxation(const StepConstants& k);

// One Jacobi pass of rows [y0, y1), columns [x0, x1) of a weighted atlas
// padded by halos (PaddedAtlasStep): x' = clamp((rhs + dt r sides) / (1 + dt r
// S)), S the texel's weight sum (StepConstants), for the kernel's count of
// chemicals, listed in `chemicals` (the others' planes are not touched).
using RelaxTileKernel = void (*)(const StepConstants& k, const std::uint8_t* chemicals,
                                 const State& x, const State& rhs, State& out, int y0, int y1,
                                 int x0, int x1);
// The pass for every count of chemicals (byCount[n] relaxes n of them; [0] is
// null). All null unless the atlas is weighted, isotropic, without drift and
// with constant rates.
struct RelaxTileKernels {
    std::array<RelaxTileKernel, kMaxChemicals + 1> byCount{};
    explicit operator bool() const { return byCount[1] != nullptr; }
};
RelaxTileKernels weightedRelaxation(const StepConstants& k);

} // namespace morphogen
