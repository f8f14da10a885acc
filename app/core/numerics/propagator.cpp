#include "core/numerics/propagator.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/errors.hpp"

namespace morphogen {

namespace {

constexpr double kPi = 3.14159265358979323846;

double component(const TensorSequence& s, const char* name) {
    return s.get(name);
}

} // namespace

Propagator::Propagator(const TensorSequence& sequence, double tau) : m_d(sequence), m_tau(tau) {
    if (!(tau > 0) || !std::isfinite(tau))
        throw InputError("propagator tau " + std::to_string(tau) + ": must be positive");
    const double xx = 2 * tau * component(sequence, "xx");
    const double xy = 2 * tau * component(sequence, "xy");
    const double yy = 2 * tau * component(sequence, "yy");
    const double det = xx * yy - xy * xy;
    if (!(xx > 0) || !(det > 0))
        throw InputError("tensor sequence '" + toString(sequence) +
                         "': the rank-2 tensor (xx, xy, yy) must be positive definite "
                         "(xx > 0 and xx*yy > xy^2) for the propagator's Gaussian");
    m_inv[0] = yy / det;
    m_inv[1] = -xy / det;
    m_inv[2] = xx / det;
    m_norm = 1.0 / (2 * kPi * std::sqrt(det));
    // Largest eigenvalue of [[xx, xy], [xy, yy]].
    m_width = std::sqrt(0.5 * (xx + yy) + std::sqrt(0.25 * (xx - yy) * (xx - yy) + xy * xy));
}

double Propagator::operator()(double x, double y) const {
    const TensorSequence& d = m_d;
    const double gauss =
        m_norm * std::exp(-0.5 * (m_inv[0] * x * x + 2 * m_inv[1] * x * y + m_inv[2] * y * y));

    // Full contractions over all index tuples = sums over unique components
    // times their multiplicity (eq. 18).
    double d3rrr = 0, d4rrrr = 0;
    for (std::size_t i = 0; i < d.values.size(); ++i) {
        const TensorComponent& c = tensorComponents()[i];
        const double term = c.multiplicity * d.values[i] * std::pow(x, c.nx) * std::pow(y, c.ny);
        if (c.rank == 3)
            d3rrr += term;
        else if (c.rank == 4)
            d4rrrr += term;
    }
    // D_ijj, the rank-3 tensor's trace over its last pair.
    const double t3x = d.get("xxx") + d.get("xyy");
    const double t3y = d.get("xxy") + d.get("yyy");
    const double h3 = d3rrr - 3 * (t3x * x + t3y * y);

    // D_iikl and its full trace D_iijj.
    const double t4xx = d.get("xxxx") + d.get("xxyy");
    const double t4xy = d.get("xxxy") + d.get("xyyy");
    const double t4yy = d.get("xxyy") + d.get("yyyy");
    const double h4 =
        d4rrrr - 6 * (t4xx * x * x + 2 * t4xy * x * y + t4yy * y * y) + 3 * (t4xx + t4yy);

    return gauss * (1 - m_tau * h3 + m_tau * h4);
}

double Propagator::atAngle(double degrees, double radius) const {
    const double a = degrees * kPi / 180;
    return (*this)(radius * std::cos(a), radius * std::sin(a));
}

std::vector<double> sampleAngular(const Propagator& p, double radius, int n) {
    std::vector<double> v(std::size_t(std::max(n, 3)));
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = p.atAngle(360.0 * double(i) / double(v.size()), radius);
    return v;
}

AngularShape angularShape(const std::vector<double>& samples) {
    bool positive = false;
    for (double v : samples) {
        if (!std::isfinite(v))
            return AngularShape::Empty;
        positive = positive || v > 0;
    }
    if (!positive)
        return AngularShape::Empty;
    return findAngularPeaks(samples).empty() ? AngularShape::Isotropic : AngularShape::Directional;
}

std::vector<double> findAngularPeaks(const std::vector<double>& f) {
    std::vector<double> peaks;
    const int n = int(f.size());
    if (n < 3)
        return peaks;
    const auto [lo, hi] = std::minmax_element(f.begin(), f.end());
    // Rounding ripple on a constant (isotropic) function is not a direction.
    if (*hi - *lo <= 1e-9 * std::max(std::abs(*hi), 1e-300))
        return peaks;
    for (int i = 0; i < n; ++i) {
        const double a = f[std::size_t((i + n - 1) % n)], b = f[std::size_t(i)],
                     c = f[std::size_t((i + 1) % n)];
        if (!(b > a && b >= c))
            continue;
        const double curvature = a - 2 * b + c;
        const double offset = curvature < 0 ? 0.5 * (a - c) / curvature : 0.0;
        double deg = (i + offset) * 360.0 / n;
        deg = std::fmod(deg + 360.0, 360.0);
        peaks.push_back(deg);
    }
    std::sort(peaks.begin(), peaks.end());
    return peaks;
}

std::vector<float> renderPolarPlot(const std::vector<double>& samples, int size) {
    const int n = int(samples.size());
    std::vector<float> rgb(std::size_t(size) * std::size_t(size) * 3, 1.0f);
    const double centre = 0.5 * size;
    const double full = 0.45 * size;
    double vmax = 0;
    for (double v : samples)
        vmax = std::max(vmax, v);
    auto radiusAt = [&](double angle) { // angle in radians, any value
        if (vmax <= 0 || n == 0)
            return 0.0;
        double t = std::fmod(angle / (2 * kPi) * n, double(n));
        if (t < 0)
            t += n;
        const int i = int(t) % n;
        const double w = t - std::floor(t);
        const double v = (1 - w) * samples[std::size_t(i)] + w * samples[std::size_t((i + 1) % n)];
        return full * std::max(0.0, v) / vmax;
    };
    auto blend = [&](int px, int py, const float colour[3], double alpha) {
        if (px < 0 || py < 0 || px >= size || py >= size || alpha <= 0)
            return;
        float* p = &rgb[(std::size_t(py) * std::size_t(size) + std::size_t(px)) * 3];
        for (int c = 0; c < 3; ++c)
            p[c] = float((1 - alpha) * p[c] + alpha * colour[c]);
    };

    // Filled lobes, 4x4 supersampled so their edges do not stair-step.
    const float tint[3] = {0.80f, 0.87f, 1.0f};
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            int inside = 0;
            for (int sy = 0; sy < 4; ++sy)
                for (int sx = 0; sx < 4; ++sx) {
                    const double x = px + (sx + 0.5) / 4 - centre;
                    const double y = py + (sy + 0.5) / 4 - centre;
                    inside += std::hypot(x, y) <= radiusAt(std::atan2(y, x));
                }
            blend(px, py, tint, inside / 16.0);
        }

    // Axes and reference circles at 50% and 100% of the maximum.
    const float grey[3] = {0.55f, 0.55f, 0.55f};
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            const double x = px + 0.5 - centre, y = py + 0.5 - centre;
            const double r = std::hypot(x, y);
            double d = std::min(std::abs(x), std::abs(y));
            if (r > full * 1.05)
                d = 1e9;
            d = std::min({d, std::abs(r - full), std::abs(r - 0.5 * full)});
            blend(px, py, grey, std::clamp(1.0 - d, 0.0, 1.0) * 0.8);
        }

    // The curve: a 4-pixel polyline, anti-aliased by distance to each segment.
    const float strong[3] = {0.80f, 0.10f, 0.10f};
    const double halfWidth = 2.0;
    std::vector<float> cover(std::size_t(size) * std::size_t(size), 0.0f);
    const int steps = std::max(n, 720);
    for (int i = 0; i < steps; ++i) {
        const double a0 = 2 * kPi * i / steps, a1 = 2 * kPi * (i + 1) / steps;
        const double x0 = centre + radiusAt(a0) * std::cos(a0);
        const double y0 = centre + radiusAt(a0) * std::sin(a0);
        const double x1 = centre + radiusAt(a1) * std::cos(a1);
        const double y1 = centre + radiusAt(a1) * std::sin(a1);
        const int bx0 = int(std::floor(std::min(x0, x1) - halfWidth - 1));
        const int bx1 = int(std::ceil(std::max(x0, x1) + halfWidth + 1));
        const int by0 = int(std::floor(std::min(y0, y1) - halfWidth - 1));
        const int by1 = int(std::ceil(std::max(y0, y1) + halfWidth + 1));
        const double ex = x1 - x0, ey = y1 - y0, len2 = ex * ex + ey * ey;
        for (int py = std::max(by0, 0); py <= std::min(by1, size - 1); ++py)
            for (int px = std::max(bx0, 0); px <= std::min(bx1, size - 1); ++px) {
                const double qx = px + 0.5 - x0, qy = py + 0.5 - y0;
                const double t = len2 > 0 ? std::clamp((qx * ex + qy * ey) / len2, 0.0, 1.0) : 0;
                const double d = std::hypot(qx - t * ex, qy - t * ey);
                float& c = cover[std::size_t(py) * std::size_t(size) + std::size_t(px)];
                c = std::max(c, float(std::clamp(halfWidth + 0.5 - d, 0.0, 1.0)));
            }
    }
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px)
            blend(px, py, strong, cover[std::size_t(py) * std::size_t(size) + std::size_t(px)]);
    // Rows were drawn with +y down; flip so +y points up as on the display.
    for (int y = 0; y < size / 2; ++y)
        std::swap_ranges(rgb.begin() + std::ptrdiff_t(y) * size * 3,
                         rgb.begin() + std::ptrdiff_t(y + 1) * size * 3,
                         rgb.begin() + std::ptrdiff_t(size - 1 - y) * size * 3);
    return rgb;
}

} // namespace morphogen
