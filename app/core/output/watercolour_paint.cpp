#include "core/output/watercolour_paint.hpp"

#include <algorithm>
#include <cmath>

#include "core/models/reaction_model.hpp"
#include "core/models/watercolour.hpp"

namespace morphogen {

namespace {

// Index i of a line of n samples, read across its ends as the edges say.
int across(int i, int n, EdgeMode edges) {
    if (edges == EdgeMode::Periodic)
        return ((i % n) + n) % n;
    return std::clamp(i, 0, n - 1);
}

// Box blur of radius r along x of every row: running sums in double, so a
// wide box costs what a narrow one does.
void blurRows(const std::vector<float>& in, std::vector<float>& out, int w, int h, int r,
              EdgeMode edges) {
    const double scale = 1.0 / double(2 * r + 1);
#pragma omp parallel if (std::size_t(w) * std::size_t(h) >= 65536)
    {
        // The row with r + 1 texels either side as the edges read them, so
        // the running sum needs no index arithmetic.
        std::vector<float> padded(std::size_t(w + 2 * r + 2));
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            const float* src = in.data() + std::size_t(y) * std::size_t(w);
            float* dst = out.data() + std::size_t(y) * std::size_t(w);
            for (int x = -r - 1; x <= w + r; ++x)
                padded[std::size_t(x + r + 1)] = src[across(x, w, edges)];
            const float* p = padded.data() + r + 1; // p[x] is texel x
            double sum = 0.0;
            for (int j = -r; j <= r; ++j)
                sum += p[j];
            for (int x = 0; x < w; ++x) {
                dst[x] = float(sum * scale);
                sum += double(p[x + r + 1]) - double(p[x - r]);
            }
        }
    }
}

// The same along y, a row of running sums at a time (rows stay contiguous).
void blurColumns(const std::vector<float>& in, std::vector<float>& out, int w, int h, int r,
                 EdgeMode edges) {
    const double scale = 1.0 / double(2 * r + 1);
    const auto row = [&](int y) { return in.data() + std::size_t(y) * std::size_t(w); };
    constexpr int kBand = 256; // columns a thread sums at once
    const int bands = (w + kBand - 1) / kBand;
#pragma omp parallel for schedule(static) if (std::size_t(w) * std::size_t(h) >= 65536)
    for (int b = 0; b < bands; ++b) {
        const int x0 = b * kBand, x1 = std::min(w, x0 + kBand);
        std::vector<double> sum(std::size_t(x1 - x0), 0.0);
        for (int j = -r; j <= r; ++j) {
            const float* src = row(across(j, h, edges));
            for (int x = x0; x < x1; ++x)
                sum[std::size_t(x - x0)] += src[x];
        }
        for (int y = 0; y < h; ++y) {
            float* dst = out.data() + std::size_t(y) * std::size_t(w);
            const float* enter = row(across(y + r + 1, h, edges));
            const float* leave = row(across(y - r, h, edges));
            for (int x = x0; x < x1; ++x) {
                double& s = sum[std::size_t(x - x0)];
                dst[x] = float(s * scale);
                s += double(enter[x]) - double(leave[x]);
            }
        }
    }
}

// A box blur of radius r on both axes (r = 0: the plane itself).
std::vector<float> boxBlur(std::vector<float> plane, int w, int h, int r, EdgeMode edges) {
    if (r <= 0)
        return plane;
    std::vector<float> tmp(plane.size());
    blurRows(plane, tmp, w, h, r, edges);
    blurColumns(tmp, plane, w, h, r, edges);
    return plane;
}

} // namespace

float WatercolourEdges::crispPeak(const std::array<int, 2>& radii) {
    // The band across a straight, sharp edge of a wash: a line of 1s then 0s,
    // long enough that neither blur reaches its ends.
    const int half = 4 * (radii[0] + 2 * radii[1]) + 4, n = 2 * half;
    std::vector<float> line(std::size_t(n), 0.0f);
    std::fill(line.begin(), line.begin() + half, 1.0f);
    const std::vector<float> near = boxBlur(line, n, 1, radii[0], EdgeMode::Clamped);
    const std::vector<float> wide = boxBlur(boxBlur(line, n, 1, radii[1], EdgeMode::Clamped), n, 1,
                                            radii[1], EdgeMode::Clamped);
    float peak = 0.0f;
    for (std::size_t i = 0; i < line.size(); ++i)
        peak = std::max(peak, near[i] - wide[i]);
    return peak;
}

std::array<int, 2> WatercolourEdges::radii(int width, float edgeWidth) {
    const float wide = edgeWidth * float(width);
    return {int(std::lround(wide / 3.0f)), std::max(1, int(std::lround(wide)))};
}

WatercolourEdges::WatercolourEdges(const State& state, float edgeWidth, EdgeMode edges) {
    using M = WatercolourModel;
    const int w = state.width(), h = state.height();
    const std::array<int, 2> r = radii(w, edgeWidth);
    // Where the paper was wet: the water gone (absorbed and evaporated),
    // saturated, so the wash's inside is 1 whatever its depth and the paper's
    // grain does not show in it.
    const float* gone = state.plane(M::G);
    std::vector<float> wet(state.cellCount());
    const auto n = std::ptrdiff_t(wet.size());
#pragma omp parallel for schedule(static) if (n >= 65536)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const float g = std::isfinite(gone[i]) ? std::max(0.0f, gone[i]) : 0.0f;
        const float t = std::clamp((g - kWetEdge[0]) / (kWetEdge[1] - kWetEdge[0]), 0.0f, 1.0f);
        wet[i] = t * t * (3.0f - 2.0f * t);
    }
    const std::vector<float> near = boxBlur(wet, w, h, r[0], edges);
    std::vector<float> wide =
        boxBlur(boxBlur(std::move(wet), w, h, r[1], edges), w, h, r[1], edges);
#pragma omp parallel for schedule(static) if (n >= 65536)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        wide[std::size_t(i)] = std::max(0.0f, near[std::size_t(i)] - wide[std::size_t(i)]);
    m_band = std::move(wide);
    m_scale = 1.0f / crispPeak(r);
}

void paintWatercolourRow(const State& state, int y, const WatercolourLook& look, float* rgb,
                         const WatercolourEdges* edges, float edgeDarkening) {
    using M = WatercolourModel;
    const std::size_t w = std::size_t(state.width());
    const std::size_t row = std::size_t(y) * w;
    const float* water = state.plane(M::W) + row;
    const float* stick = state.plane(M::S) + row;
    const float* wet[2] = {state.plane(M::P1) + row, state.plane(M::P2) + row};
    const float* dry[2] = {state.plane(M::D1) + row, state.plane(M::D2) + row};
    const float* band = edges ? edges->band() + row : nullptr;
    for (std::size_t x = 0; x < w; ++x) {
        const float rim = band ? 1.0f + edgeDarkening * edges->scale() * band[x] : 1.0f;
        const float tint =
            1.0f - look.grain * (stick[x] - 0.5f) - look.sheen * std::clamp(water[x], 0.0f, 1.0f);
        for (int c = 0; c < 3; ++c) {
            float optical = 0.0f;
            for (int k = 0; k < 2; ++k) {
                const float settled = dry[k][x] * rim;
                optical +=
                    look.absorbance[k][c] * std::max(0.0f, settled + look.wetShare * wet[k][x]);
            }
            const float v = look.paper[c] * tint * std::exp(-optical);
            rgb[x * 3 + c] = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
        }
    }
}

bool paintsAsWatercolour(const ReactionModel& model) {
    using M = WatercolourModel;
    return model.chemicals().size() == std::size_t(M::Cell::kChemicals) &&
           model.chemicalIndex("w") == M::W && model.chemicalIndex("s") == M::S &&
           model.chemicalIndex("p1") == M::P1 && model.chemicalIndex("p2") == M::P2 &&
           model.chemicalIndex("d1") == M::D1 && model.chemicalIndex("d2") == M::D2;
}

} // namespace morphogen
