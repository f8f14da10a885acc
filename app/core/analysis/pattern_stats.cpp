#include "core/analysis/pattern_stats.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include <unsupported/Eigen/FFT>

namespace morphogen {

SpectrumStats spectrumStats(const State& state, int chemical) {
    const int w = state.width(), h = state.height();
    const float* p = state.plane(chemical);
    SpectrumStats stats;
    double mean = 0;
    for (std::size_t i = 0; i < state.cellCount(); ++i)
        mean += p[i];
    mean /= double(state.cellCount());
    for (std::size_t i = 0; i < state.cellCount(); ++i)
        stats.variance += (p[i] - mean) * (p[i] - mean);
    stats.variance /= double(state.cellCount());

    // 2D FFT as rows then columns.
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> grid(state.cellCount());
    std::vector<double> rowIn(std::size_t(w), 0.0);
    std::vector<std::complex<double>> rowOut, colOut;
    std::vector<std::complex<double>> colIn(static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x)
            rowIn[std::size_t(x)] = p[std::size_t(y) * w + x] - mean;
        fft.fwd(rowOut, rowIn);
        for (int x = 0; x < w; ++x)
            grid[std::size_t(y) * w + x] = rowOut[std::size_t(x)];
    }
    for (int x = 0; x < w; ++x) {
        for (int y = 0; y < h; ++y)
            colIn[std::size_t(y)] = grid[std::size_t(y) * w + x];
        fft.fwd(colOut, colIn);
        for (int y = 0; y < h; ++y)
            grid[std::size_t(y) * w + x] = colOut[std::size_t(y)];
    }

    // Radial average in units of cycles per cell, binned at 1/max(w, h).
    const int n = std::max(w, h);
    std::vector<double> power(std::size_t(n), 0.0), count(std::size_t(n), 0.0);
    double total = 0, outer = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double fx = double(x <= w / 2 ? x : x - w) / w;
            const double fy = double(y <= h / 2 ? y : y - h) / h;
            const double f = std::sqrt(fx * fx + fy * fy);
            if (f == 0)
                continue;
            const double e = std::norm(grid[std::size_t(y) * w + x]);
            total += e;
            if (f > 0.4)
                outer += e;
            const int bin = int(std::lround(f * n));
            if (bin < n) {
                power[std::size_t(bin)] += e;
                count[std::size_t(bin)] += 1;
            }
        }
    int best = 1;
    for (int b = 1; b < n; ++b)
        if (count[std::size_t(b)] > 0 &&
            power[std::size_t(b)] / count[std::size_t(b)] >
                power[std::size_t(best)] / std::max(1.0, count[std::size_t(best)]))
            best = b;
    stats.dominantWavelength = double(n) / best;
    stats.nyquistFraction = total > 0 ? outer / total : 0.0;
    return stats;
}

double OrientationStats::moment(int k) const {
    return std::hypot(re[std::size_t(k)], im[std::size_t(k)]);
}

double OrientationStats::momentPhaseDegrees(int k) const {
    return std::atan2(im[std::size_t(k)], re[std::size_t(k)]) * 180.0 / 3.14159265358979323846;
}

OrientationStats orientationStats(const State& state, int chemical, int bins) {
    constexpr double pi = 3.14159265358979323846;
    const int w = state.width(), h = state.height();
    auto at = [&](int x, int y) { return double(state.at(chemical, (x + w) % w, (y + h) % h)); };
    OrientationStats stats;
    stats.histogram.assign(std::size_t(bins), 0.0);
    stats.re.assign(13, 0.0);
    stats.im.assign(13, 0.0);
    double total = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // Central differences; display y points up, rows grow down.
            const double gx = 0.5 * (at(x + 1, y) - at(x - 1, y));
            const double gy = -0.5 * (at(x, y + 1) - at(x, y - 1));
            const double weight = std::hypot(gx, gy);
            if (weight == 0)
                continue;
            double theta = std::atan2(gy, gx);
            if (theta < 0)
                theta += pi;
            if (theta >= pi)
                theta -= pi;
            stats.histogram[std::min(std::size_t(bins - 1), std::size_t(theta / pi * bins))] +=
                weight;
            for (int k = 2; k <= 12; k += 2) {
                stats.re[std::size_t(k)] += weight * std::cos(k * theta);
                stats.im[std::size_t(k)] += weight * std::sin(k * theta);
            }
            total += weight;
        }
    if (total > 0) {
        for (double& v : stats.histogram)
            v /= total;
        for (std::size_t k = 0; k < stats.re.size(); ++k) {
            stats.re[k] /= total;
            stats.im[k] /= total;
        }
    }
    return stats;
}

std::vector<PatternFeature> findFeatures(const State& state, int chemical, bool periodic) {
    const int w = state.width(), h = state.height();
    const std::size_t cells = state.cellCount();
    const float* p = state.plane(chemical);
    double mean = 0;
    for (std::size_t i = 0; i < cells; ++i)
        mean += p[i];
    mean /= double(std::max<std::size_t>(cells, 1));
    std::size_t above = 0;
    for (std::size_t i = 0; i < cells; ++i)
        above += p[i] > mean;
    const bool countAbove = 2 * above <= cells;
    auto inFeature = [&](std::size_t i) { return countAbove ? p[i] > mean : p[i] < mean; };

    std::vector<int> label(cells, -1), ux(cells, 0), uy(cells, 0);
    std::vector<std::size_t> stack;
    std::vector<PatternFeature> features;
    for (std::size_t start = 0; start < cells; ++start) {
        if (label[start] >= 0 || !inFeature(start))
            continue;
        const int id = int(features.size());
        PatternFeature f;
        label[start] = id;
        ux[start] = int(start % std::size_t(w));
        uy[start] = int(start / std::size_t(w));
        const double ox = ux[start], oy = uy[start]; // moments about the start: small sums
        stack.assign(1, start);
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            ++f.area;
            const double dx = ux[i] - ox, dy = uy[i] - oy;
            f.sx += dx;
            f.sy += dy;
            f.sxx += dx * dx;
            f.syy += dy * dy;
            f.sxy += dx * dy;
            const int x = int(i % std::size_t(w)), y = int(i / std::size_t(w));
            const int ddx[4] = {-1, 1, 0, 0}, ddy[4] = {0, 0, -1, 1};
            for (int k = 0; k < 4; ++k) {
                int xx = x + ddx[k], yy = y + ddy[k];
                if (periodic) {
                    xx = (xx + w) % w;
                    yy = (yy + h) % h;
                } else if (xx < 0 || yy < 0 || xx >= w || yy >= h) {
                    continue;
                }
                const std::size_t j = std::size_t(yy) * std::size_t(w) + std::size_t(xx);
                const int ex = ux[i] + ddx[k], ey = uy[i] + ddy[k];
                if (label[j] < 0 && inFeature(j)) {
                    label[j] = id;
                    ux[j] = ex;
                    uy[j] = ey;
                    stack.push_back(j);
                } else if (label[j] == id && (ux[j] != ex || uy[j] != ey)) {
                    f.wraps = true;
                }
            }
        }
        features.push_back(f);
    }
    return features;
}

int featureCount(const std::vector<PatternFeature>& features) {
    return int(std::count_if(features.begin(), features.end(),
                             [](const PatternFeature& f) { return f.area >= kMinFeatureArea; }));
}

int featureCount(const State& state, int chemical, bool periodic) {
    return featureCount(findFeatures(state, chemical, periodic));
}

} // namespace morphogen
