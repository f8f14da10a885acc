#pragma once

#include <array>
#include <string>

#include "core/base/state.hpp"
#include "core/numerics/kernel.hpp"

namespace morphogen {

struct Session;
struct AnisotropicTensor;

// The diffusion term as the backends run it, compiled once from a session's
// DiffusionSpec and the model's diffusion rates.
struct DiffusionOperator {
    enum class Form {
        Laplacian5, // rate * 5-point Laplacian (the fast path)
        Laplacian9, // rate * 9-point Laplacian
        Kernel3,    // a per-chemical 3x3 mask (constant anisotropic tensor)
        Kernel5,    // a per-chemical 5x5 kernel (generalized diffusion)
        TensorMap,  // div(A(x) grad c) with A varying per texel, in conservative form
    };
    Form form = Form::Laplacian5;
    int chemicals = 0;
    std::array<float, kMaxChemicals> rates = {}; // Laplacian5/9: each chemical's rate
    std::array<Kernel5, kMaxChemicals> kernels =
        {}; // Kernel3/5: each chemical's kernel, rate included

    // TensorMap. Per texel: (s, s cos 2theta, s sin 2theta) of the map. Per
    // chemical (m, dc, ds), with m = rate (a1^2 + a2^2) / 2, d = rate (a1^2 - a2^2) / 2,
    // dc = d cos 2phi, ds = d sin 2phi for the chemical's own angle phi; then in grid
    // coordinates (x right, rows down) A_xx = m s + dc C - ds S, A_yy = m s - dc C + ds S,
    // A_xy = -(dc S + ds C), where C = s cos 2theta, S = s sin 2theta.
    State map;
    std::array<std::array<float, 3>, kMaxChemicals> mapCoefficients = {};

    // Generalized: the isotropic damping added so that no Fourier mode grows
    // (0 when none was needed), per chemical; see kernel_symbol.hpp.
    std::array<double, kMaxChemicals> stabilization = {};
};

// Throws InputError for specs that cannot be built (unknown tensor sets, a
// missing image).
DiffusionOperator compileDiffusion(const Session& session);

// Witkin-Kass's mask (eq. 7, h = 1) for a constant tensor times rate.
Kernel5 anisotropicKernel(const AnisotropicTensor& tensor, float rate);

// The largest symbol magnitude bound of the operator's diffusion part,
// for the explicit time step limit dt <= 2 / bound (a Gershgorin bound:
// sum of |weights| per chemical, maximised; exact for the Laplacians).
double diffusionSymbolBound(const DiffusionOperator& op);

} // namespace morphogen
