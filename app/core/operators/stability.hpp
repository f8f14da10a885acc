#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/session/session.hpp"

namespace morphogen {

// Largest explicit Euler dt for which pure diffusion at rate maxD stays
// stable: dt * maxD * |lambda_max| <= 2, with |lambda_max| the stencil's
// largest symbol magnitude (8 for 5-point, 16/3 for 9-point).
float stableDiffusionDt(Stencil stencil, float maxDiffusion);

// The explicit step's stability for a compiled operator on the session's
// grid. For homogeneous operators (Laplacians, 3x3 and 5x5 kernels) it is
// exact: the spectral radius of I + dt A from each chemical's kernel symbol at
// the grid's Fourier modes (periodic grid). For a diffusion map it is a
// Gershgorin bound, so maxStableDt is conservative and spectralRadius is NaN.
struct ExplicitStability {
    std::optional<double> maxStableDt; // nullopt: some mode grows for every dt
    double spectralRadius = 0;         // of I + dt A at the given dt, worst chemical
    double maxRealPart = 0;            // of the symbol, worst chemical
    bool exact = true;
    // How maxStableDt was found, for messages.
    std::string basis = "spectral radius of I + dt A from the kernel's Fourier symbol";
};
ExplicitStability explicitStability(const DiffusionOperator& op, int width, int height, double dt);
// The same on a domain: a grid's Fourier modes, one tile's on a tiled grid.
// An atlas has no Fourier modes: a safe bound instead, Gershgorin's (the
// largest rate times the stencil's bound, diffusionSymbolBound), with
// exact = false and `basis` saying so. A weighted atlas (atlas_weights.hpp)
// bounds its weighted 5-point Laplacian the same way: |lambda| <= 2 * rate *
// maxCoefficientSum.
ExplicitStability explicitStability(const DiffusionOperator& op, const Domain& domain, double dt);
// A weighted atlas with anisotropy (AtlasWeights::tensor): Gershgorin's bound of
// each chemical's combined operator (mixes: sessionTensorMixes at its rates).
ExplicitStability tensorAtlasStability(const AtlasWeights& weights,
                                       const std::vector<std::array<float, 3>>& mixes);

// The semi-implicit solve (I - dt A) x = rhs by Richardson relaxation passes
//   x' = x + omega (rhs - (I - dt A) x).
// With omega = 1 / (1 - dt a0) this is Jacobi, which diverges for kernels
// that are not diagonally dominant (the stabilised rank-4 sets). The
// eigenvalues mu(k) = 1 - dt lambda(k) come from the kernel's symbol, so
// omega is chosen to minimise the contraction max |1 - omega mu(k)| over the
// grid's modes (for a real spectrum [mu_min, mu_max] that is
// 2 / (mu_min + mu_max), which for the 5-point Laplacian is exactly Jacobi).
// Requires Re lambda <= 0 (then Re mu >= 1 and some omega contracts).
struct RelaxationWeight {
    double omega = 1.0;
    double contraction = 0.0; // residual factor per sweep, < 1
};
RelaxationWeight relaxationWeight(const Kernel5& kernel, int width, int height, double dt);

// The kernel of a homogeneous operator for one chemical (Laplacians included).
Kernel5 operatorKernel(const DiffusionOperator& op, int chemical);

// A dt to suggest after a blow-up: below the diffusion limit and below the dt
// that failed.
float suggestDt(const Session& session);

// Finds the first cell whose value is NaN/Inf or outside the model's sane
// range; returns a description ("chemical v = nan at (12, 40)") or nullopt.
std::optional<std::string> findInsaneValue(const State& state, const ReactionModel& model);

// findInsaneValue over a grid read a band of rows at a time (a GPU read-back
// without a whole copy of the state): bands given top to bottom give the
// answer findInsaneValue gives for the whole grid.
class InsaneValueScan {
public:
    explicit InsaneValueScan(const ReactionModel& model);
    // `band` holds full rows y0, y0 + 1, ... of the grid.
    void scanRows(const State& band, int y0);
    std::optional<std::string> result() const;

private:
    const ReactionModel& m_model;
    // Per chemical, its first problem in plane order (findInsaneValue reports
    // the lowest chemical that has one).
    std::vector<std::optional<std::string>> m_first;
};

} // namespace morphogen
