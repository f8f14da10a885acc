#include "core/numerics/kernel_symbol.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace morphogen {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Samples per axis for the grid-independent analysis: the symbols are
// trigonometric polynomials of degree 2, so their maxima are resolved to
// ~(2 pi / 512)^2 relative, and 512 includes every power-of-two grid's modes
// up to 512.
constexpr int kDenseSamples = 512;

// Calls f(lambda, kx, ky) for every mode of a periodic width x height grid,
// with the exponentials tabulated per axis (width * 5 + height * 5 of them).
template <typename F> void forEachMode(const Kernel5& kernel, int width, int height, F&& f) {
    std::vector<std::complex<double>> ex(std::size_t(width) * 5), ey(std::size_t(height) * 5);
    for (int m = 0; m < width; ++m)
        for (int d = -2; d <= 2; ++d)
            ex[std::size_t(m * 5 + d + 2)] = std::polar(1.0, 2 * kPi * m / width * d);
    for (int n = 0; n < height; ++n)
        for (int d = -2; d <= 2; ++d)
            ey[std::size_t(n * 5 + d + 2)] = std::polar(1.0, 2 * kPi * n / height * d);
    for (int n = 0; n < height; ++n)
        for (int m = 0; m < width; ++m) {
            std::complex<double> lambda = 0;
            for (int dy = -2; dy <= 2; ++dy) {
                std::complex<double> row = 0;
                for (int dx = -2; dx <= 2; ++dx)
                    row += kernel.at(dx, dy) * ex[std::size_t(m * 5 + dx + 2)];
                lambda += row * ey[std::size_t(n * 5 + dy + 2)];
            }
            f(lambda, 2 * kPi * m / width, 2 * kPi * n / height);
        }
}

// Below this |lambda| a mode is the conserved mean (lambda(0) = sum of weights).
constexpr double kNeutral = 1e-12;

} // namespace

std::complex<double> kernelSymbol(const Kernel5& kernel, double kx, double ky) {
    std::complex<double> lambda = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            lambda += kernel.at(dx, dy) * std::polar(1.0, kx * dx + ky * dy);
    return lambda;
}

ExplicitStepReport analyzeExplicitStep(const Kernel5& kernel, int width, int height, double dt) {
    ExplicitStepReport r;
    r.maxRealPart = -std::numeric_limits<double>::infinity();
    double dtBound = std::numeric_limits<double>::infinity();
    bool growing = false;
    forEachMode(kernel, width, height, [&](std::complex<double> lambda, double, double) {
        r.spectralRadius = std::max(r.spectralRadius, std::abs(1.0 + dt * lambda));
        r.maxRealPart = std::max(r.maxRealPart, lambda.real());
        const double mag2 = std::norm(lambda);
        if (mag2 < kNeutral * kNeutral)
            return;
        // Rounding leaves ~1e-15 on modes that are exactly neutral in exact
        // arithmetic (the antisymmetric part's symbol is purely imaginary).
        if (lambda.real() > kNeutral * std::sqrt(mag2) + kNeutral)
            growing = true;
        else
            dtBound = std::min(dtBound, std::max(0.0, -2.0 * lambda.real() / mag2));
    });
    if (!growing)
        r.maxStableDt = dtBound;
    return r;
}

ExplicitStepReport analyzeExplicitStep(const Kernel5& kernel, double dt) {
    return analyzeExplicitStep(kernel, kDenseSamples, kDenseSamples, dt);
}

Kernel5 biharmonicKernel() {
    Kernel5 lap;
    lap.at(0, 0) = -4;
    lap.at(1, 0) = lap.at(-1, 0) = lap.at(0, 1) = lap.at(0, -1) = 1;
    Kernel5 k;
    for (int ay = -1; ay <= 1; ++ay)
        for (int ax = -1; ax <= 1; ++ax)
            for (int by = -1; by <= 1; ++by)
                for (int bx = -1; bx <= 1; ++bx)
                    k.at(ax + bx, ay + by) += lap.at(ax, ay) * lap.at(bx, by);
    return k;
}

StabilizedKernel stabilizeKernel(const Kernel5& kernel, double margin) {
    double worst = -std::numeric_limits<double>::infinity();
    forEachMode(kernel, kDenseSamples, kDenseSamples,
                [&](std::complex<double> lambda, double kx, double ky) {
                    const double sx = std::sin(kx / 2), sy = std::sin(ky / 2);
                    const double b = 16 * (sx * sx + sy * sy) * (sx * sx + sy * sy);
                    if (b < 1e-12)
                        return; // the mean mode
                    worst = std::max(worst, lambda.real() / b);
                });
    StabilizedKernel s;
    s.eta = std::max(0.0, worst + std::max(0.0, margin));
    if (worst <= -std::max(0.0, margin)) {
        s.eta = 0.0;
        s.kernel = kernel;
        return s;
    }
    s.kernel = kernel + biharmonicKernel().scaled(-s.eta);
    return s;
}

} // namespace morphogen
