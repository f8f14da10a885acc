#pragma once

#include <vector>

#include "core/base/state.hpp"

namespace morphogen {

// Statistics for comparing long runs by what they look like rather than by
// pixels (RD amplifies differences, so pixels diverge between backends).
struct SpectrumStats {
    double dominantWavelength = 0; // cells, from the radially averaged power spectrum peak
    double nyquistFraction = 0; // share of (non-DC) power in the outer band |k| > 0.4 (cycles/cell)
    double variance = 0;
};

// Spectrum statistics of one chemical plane (periodic: the grid is one tile).
SpectrumStats spectrumStats(const State& state, int chemical);

// A connected region (4-neighbour, wrapping around a periodic grid) of the
// minority phase: cells above the chemical's mean where those are fewer than
// half, else cells below it. Spots (light or dark) or stripe segments.
// Positions are unwrapped across the seams as the region is walked, so the
// moments (about the region's first cell) describe its connected shape;
// `wraps` is set when the region closes around the torus (an endless stripe).
struct PatternFeature {
    int area = 0;
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    bool wraps = false;
};
std::vector<PatternFeature> findFeatures(const State& state, int chemical, bool periodic = true);

// Regions of fewer than this many cells are noise, not features.
constexpr int kMinFeatureArea = 3;

// The number of features of at least kMinFeatureArea cells.
int featureCount(const State& state, int chemical, bool periodic = true);
int featureCount(const std::vector<PatternFeature>& features);

// How a pattern's edges are oriented: a magnitude-weighted histogram of the
// gradient direction over [0, 180) degrees (display convention: counter-
// clockwise from +x), and its angular Fourier moments. A stripe runs
// perpendicular to its gradient. For a pattern with n preferred gradient
// directions spaced 180/n apart, |moment(2n)| stands out; its phase tells
// where they sit (two directions: Re moment(4) > 0 along the axes, < 0 diagonal).
struct OrientationStats {
    std::vector<double> histogram; // normalised to sum 1
    // Re/Im of mean(w * exp(i k theta)) / mean(w), k = 2, 4, 6, 8, 12.
    double moment(int k) const;
    double momentPhaseDegrees(int k) const;
    std::vector<double> re, im; // index k
};
OrientationStats orientationStats(const State& state, int chemical, int bins = 36);

} // namespace morphogen
