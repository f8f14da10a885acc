#pragma once

#include <complex>
#include <optional>

#include "core/numerics/kernel.hpp"

namespace morphogen {

// Fourier analysis of a homogeneous operator A = convolution by a Kernel5 on a
// periodic W x H grid. A is circulant, so its eigenvectors are the grid's
// Fourier modes and its eigenvalues are the kernel's symbol at the grid's
// frequencies kx = 2 pi m / W, ky = 2 pi n / H: everything below is exact, not
// an estimate (no power iteration, no Gershgorin bound).

// lambda(kx, ky) = sum w(dx, dy) exp(i (kx dx + ky dy)).
std::complex<double> kernelSymbol(const Kernel5& kernel, double kx, double ky);

struct ExplicitStepReport {
    double spectralRadius = 0; // max |1 + dt lambda| over the grid's modes
    double maxRealPart = 0;    // max Re(lambda); > 0 means growth for every dt
    // Largest dt with spectral radius <= 1: min over modes of -2 Re / |lambda|^2.
    // nullopt when some mode has Re(lambda) > 0 (no dt is stable).
    std::optional<double> maxStableDt;
};

// The explicit step u <- (I + dt A) u of eq. 27 on a periodic width x height grid.
ExplicitStepReport analyzeExplicitStep(const Kernel5& kernel, int width, int height, double dt);

// The same, grid-independent: over a dense sampling of the whole frequency
// square, which contains every periodic grid's frequencies.
ExplicitStepReport analyzeExplicitStep(const Kernel5& kernel, double dt);

// The 13-point biharmonic Laplacian^2, the 5-point Laplacian convolved with
// itself. Its symbol (4 sin^2(kx/2) + 4 sin^2(ky/2))^2 is real, isotropic to
// leading order and > 0 at every non-zero frequency.
Kernel5 biharmonicKernel();

struct StabilizedKernel {
    Kernel5 kernel; // input - eta * biharmonicKernel()
    double eta = 0; // 0 when the input needed no damping
};

// Keeps a generalized operator whose symbol has Re(lambda) > 0 (Table 2's
// rank-4 sets (d), (e), (f): a positive 4th-order term is anti-diffusion)
// from growing under any time step, by adding the smallest isotropic
// hyperdiffusion -eta * Laplacian^2 with
//     eta = max over k != 0 of Re(lambda(k)) / B(k) + margin,  B = symbol of Laplacian^2,
// so that Re(lambda_stabilized(k)) <= -margin * B(k) <= 0 at every frequency.
//
// Why Laplacian^2: it is the isotropic rank-4 tensor (D_xxxx, D_xxyy, D_yyyy
// each lowered by eta, eta / 3, eta), of the same order as the offending
// term, so it changes no preferred direction: in the propagator it adds a
// constant on |r| = 1 and in the symbol it subtracts eta |k|^4 from
// cos(4 theta)-shaped lobes. The rank-2 tensor (pattern scale) is untouched,
// and because B ~ |k|^4 the long wavelengths that form the pattern are barely
// affected; only the grid-scale modes that blew up are damped. A damping
// Laplacian instead would rescale D^(2) and shift the pattern's wavelength.
// The 13-point stencil, not the fitted SG one, because the fitted kernels'
// symbols vanish at some Nyquist modes where they could not damp anything.
//
// eta is computed over the whole frequency square, so the result is stable
// on every periodic grid. margin >= 0 (a small one, e.g. 1e-3, keeps grid-scale
// modes strictly decaying rather than neutral).
StabilizedKernel stabilizeKernel(const Kernel5& kernel, double margin = 1e-3);

} // namespace morphogen
