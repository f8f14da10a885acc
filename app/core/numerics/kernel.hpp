#pragma once

#include <array>
#include <cmath>

namespace morphogen {

// A linear diffusion operator on a grid as a 5x5 convolution: the diffusion
// term at (x, y) is sum over dx, dy in [-2, 2] of at(dx, dy) * c(x + dx, y + dy).
// Isotropic stencils, Witkin-Kass anisotropic masks (3x3, outer ring zero) and
// McGraw's generalized Savitzky-Golay kernels are all of this form; kernels
// are assembled in double and rounded to float once for the backends.
struct Kernel5 {
    std::array<double, 25> w{};

    double& at(int dx, int dy) { return w[std::size_t((dy + 2) * 5 + (dx + 2))]; }
    double at(int dx, int dy) const { return w[std::size_t((dy + 2) * 5 + (dx + 2))]; }

    // 1 when the outer ring is zero (a 3x3 mask), else 2.
    int radius() const {
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
                if ((std::abs(dx) == 2 || std::abs(dy) == 2) && at(dx, dy) != 0.0)
                    return 2;
        return 1;
    }

    Kernel5 scaled(double s) const {
        Kernel5 k;
        for (std::size_t i = 0; i < w.size(); ++i)
            k.w[i] = w[i] * s;
        return k;
    }
    Kernel5 operator+(const Kernel5& o) const {
        Kernel5 k;
        for (std::size_t i = 0; i < w.size(); ++i)
            k.w[i] = w[i] + o.w[i];
        return k;
    }
};

} // namespace morphogen
