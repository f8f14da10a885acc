#include "core/models/paper_texture.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/random.hpp"

namespace morphogen {

namespace {

// Smooth value noise in [-1, 1): lattice values one unit apart, blended with
// a smoothstep so no lattice lines show in the paper.
double valueNoise(std::uint64_t seed, std::uint64_t stream, double x, double y) {
    const double fx = std::floor(x), fy = std::floor(y);
    const auto lattice = [&](double i, double j) {
        const auto ix = std::uint64_t(std::int64_t(i)) & 0xffffffffull;
        const auto iy = std::uint64_t(std::int64_t(j)) & 0xffffffffull;
        return uniformSigned(seed, stream, ix | iy << 32);
    };
    const double tx = x - fx, ty = y - fy;
    const double sx = tx * tx * (3 - 2 * tx), sy = ty * ty * (3 - 2 * ty);
    const double a = lattice(fx, fy) + sx * (lattice(fx + 1, fy) - lattice(fx, fy));
    const double b = lattice(fx, fy + 1) + sx * (lattice(fx + 1, fy + 1) - lattice(fx, fy + 1));
    return a + sy * (b - a);
}

} // namespace

std::vector<float> makePaper(const PaperSpec& spec, int width, int height) {
    constexpr int kFibreDirections = 3;
    constexpr double kFibreStretch = 6.0;
    const double scale = std::max(0.5, double(spec.scale));
    double angle[kFibreDirections];
    for (int k = 0; k < kFibreDirections; ++k)
        angle[k] = 3.14159265358979 * uniform01(spec.seed, 7000, std::uint64_t(k));
    std::vector<float> paper(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            // Two octaves of tooth: coarse lumps and fine grain.
            const double grain = 0.65 * valueNoise(spec.seed, 7100, x / scale, y / scale) +
                                 0.35 * valueNoise(spec.seed, 7101, 2 * x / scale, 2 * y / scale);
            // A fibre is where stretched noise crosses zero: 1 on the ridge,
            // falling to 0 within a fraction of a cell width.
            double fibre = 0;
            for (int k = 0; k < kFibreDirections; ++k) {
                const double c = std::cos(angle[k]), s = std::sin(angle[k]);
                const double u = (c * x + s * y) / (kFibreStretch * scale);
                const double v = (-s * x + c * y) / scale;
                const double n = valueNoise(spec.seed, 7200 + std::uint64_t(k), u, v);
                fibre = std::max(fibre, std::pow(std::max(0.0, 1.0 - 4.0 * std::fabs(n)), 3.0));
            }
            const double value =
                spec.mean * (1.0 + spec.grain * grain + spec.fibres * (2.0 * fibre - 0.5));
            paper[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                float(std::clamp(value, 0.02, 1.0));
        }
    return paper;
}

} // namespace morphogen
