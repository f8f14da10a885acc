#include "core/analysis/pattern_classifier.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/analysis/pattern_stats.hpp"

namespace morphogen {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Thresholds of classifyPattern.
//
// Power beyond |k| = 0.4 cycles/cell is where an explicit step that is too
// long blows up (a period-2 checkerboard reads ~1). Every real preset pattern
// measures < 0.05 (pattern_behaviour_test); white noise reads ~0.5, and noise
// loud enough to pass the uniform test is not a pattern either.
constexpr double kNyquistUnstable = 0.4;
// Float planes hold values to ~1e-7 relative, and an RD pattern worth the
// name varies by tens of percent; a relative spread of 1e-3 is far from both.
constexpr double kUniformCv = 1e-3;
// Chemicals that settle at 0 (Gray-Scott v in its uniform regime) have no
// mean to be relative to: a spread under 1e-6 absolute counts as flat too.
// Preset chemicals live on scales of 0.1 to 10, so 1e-6 is invisible.
constexpr double kUniformAbsoluteSd = 1e-6;
// Area-weighted share of elongated features (PatternStats::elongatedShare):
// at most kSpotsMaxElongated -> spots, at least kStripesMinElongated ->
// stripes, mixed in between. Measured: spot presets 0.00-0.17 (Turk's small
// spots have a few 2:1 pairs), RD stripes and labyrinths 0.86-1.0. Mazes also
// hold islands, the cut-off ends of walls, which read compact: the sign of a
// random one-wavelength field measures 0.67-0.95 over 40 seeds. Hence the
// band is set lower on the stripe side.
constexpr double kSpotsMaxElongated = 0.25;
constexpr double kStripesMinElongated = 0.6;
// A spot pattern is several spots; one or two compact blobs is more likely a
// seed that has not spread (or a dying pattern).
constexpr int kMinSpots = 3;

double featureElongation(const PatternFeature& f) {
    if (f.wraps)
        return kWrapElongation;
    const double n = f.area;
    const double mx = f.sx / n, my = f.sy / n;
    // + 1/12: each cell is a unit square, not a point; without it a 2x2 spot
    // would read as a degenerate ellipse.
    const double cxx = f.sxx / n - mx * mx + 1.0 / 12.0;
    const double cyy = f.syy / n - my * my + 1.0 / 12.0;
    const double cxy = f.sxy / n - mx * my;
    const double half = 0.5 * (cxx + cyy);
    const double root = std::sqrt(std::max(0.0, 0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy));
    const double major = half + root, minor = std::max(half - root, 1e-12);
    const double axisRatio = std::sqrt(major / minor);
    // A solid ellipse with semi-axes a, b has variances a^2/4, b^2/4.
    const double ellipseArea = 4.0 * kPi * std::sqrt(major * minor);
    return std::min(kWrapElongation, std::max(axisRatio, ellipseArea / n));
}

} // namespace

PatternStats measurePattern(const State& state, int chemical, const Domain& domain) {
    requireGridAxes(domain, "pattern statistics (FFT wavelength and orientation)");
    return measurePattern(state, chemical, domain.edges() == EdgeMode::Periodic);
}

PatternStats measurePattern(const State& state, int chemical, bool periodic) {
    PatternStats stats;
    const std::size_t cells = state.cellCount();
    const float* p = state.plane(chemical);
    stats.min = stats.max = cells > 0 ? p[0] : 0.0;
    for (std::size_t i = 0; i < cells; ++i) {
        if (!std::isfinite(p[i])) {
            stats.finite = false;
            stats.min = stats.max = stats.mean = stats.variance = std::nan("");
            return stats;
        }
        stats.min = std::min(stats.min, double(p[i]));
        stats.max = std::max(stats.max, double(p[i]));
        stats.mean += p[i];
    }
    if (cells == 0)
        return stats;
    stats.mean /= double(cells);

    const SpectrumStats spectrum = spectrumStats(state, chemical);
    stats.variance = spectrum.variance;
    stats.dominantWavelength = spectrum.dominantWavelength;
    stats.nyquistFraction = spectrum.nyquistFraction;
    const OrientationStats orientation = orientationStats(state, chemical);
    for (int k = 2; k <= 12; k += 2)
        stats.orientationStrength = std::max(stats.orientationStrength, orientation.moment(k));
    const std::vector<PatternFeature> features = findFeatures(state, chemical, periodic);
    stats.featureCount = featureCount(features);
    std::size_t minority = 0;
    for (const PatternFeature& f : features)
        minority += std::size_t(f.area);
    stats.minorityFraction = double(minority) / double(cells);

    double area = 0, weighted = 0, elongated = 0;
    int largest = 0;
    for (const PatternFeature& f : features) {
        if (f.area < kMinFeatureArea)
            continue;
        const double e = featureElongation(f);
        area += f.area;
        weighted += e * f.area;
        if (e >= kElongatedFeature)
            elongated += f.area;
        largest = std::max(largest, f.area);
    }
    if (area > 0) {
        stats.meanFeatureArea = area / std::max(1, stats.featureCount);
        stats.elongation = weighted / area;
        stats.elongatedShare = elongated / area;
        stats.largestFeatureShare = largest / area;
    }
    return stats;
}

std::string toString(PatternClass c) {
    switch (c) {
    case PatternClass::Uniform:
        return "uniform";
    case PatternClass::Spots:
        return "spots";
    case PatternClass::Stripes:
        return "stripes/labyrinth";
    case PatternClass::Mixed:
        return "mixed";
    case PatternClass::Unstable:
        return "unstable";
    }
    return "unknown";
}

PatternClass classifyPattern(const PatternStats& stats, const ChemicalSpec* saneRange) {
    if (!stats.finite)
        return PatternClass::Unstable;
    if (saneRange && (stats.min < saneRange->saneMin || stats.max > saneRange->saneMax))
        return PatternClass::Unstable;
    // Before the checkerboard test: round-off noise on a flat field is white,
    // so its spectrum reads like grid-scale noise, but it is invisible.
    const double sd = std::sqrt(std::max(0.0, stats.variance));
    if (sd <= std::max(kUniformCv * std::fabs(stats.mean), kUniformAbsoluteSd))
        return PatternClass::Uniform;
    if (stats.nyquistFraction > kNyquistUnstable)
        return PatternClass::Unstable;
    if (stats.featureCount == 0)
        return PatternClass::Mixed; // structure only in features of < 3 cells
    if (stats.elongatedShare <= kSpotsMaxElongated)
        return stats.featureCount >= kMinSpots ? PatternClass::Spots : PatternClass::Mixed;
    if (stats.elongatedShare >= kStripesMinElongated)
        return PatternClass::Stripes;
    return PatternClass::Mixed;
}

PatternStats statsForClass(PatternStats stats, PatternClass c) {
    if (c != PatternClass::Uniform)
        return stats;
    stats.dominantWavelength = 0;
    stats.nyquistFraction = 0;
    stats.orientationStrength = 0;
    stats.featureCount = 0;
    stats.minorityFraction = 0;
    stats.meanFeatureArea = 0;
    stats.largestFeatureShare = 0;
    stats.elongation = 0;
    stats.elongatedShare = 0;
    return stats;
}

} // namespace morphogen
