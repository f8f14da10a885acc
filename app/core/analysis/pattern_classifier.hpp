#pragma once

#include <string>

#include "core/base/state.hpp"
#include "core/domain/domain.hpp"
#include "core/models/reaction_model.hpp"

namespace morphogen {

// What one chemical plane looks like, in numbers a parameter sweep can sort
// by. Features are the connected regions of the minority phase, as in
// featureCount(): spots (light or dark), stripe segments or labyrinth walls.
struct PatternStats {
    bool finite = true; // no NaN or Inf anywhere
    double min = 0, max = 0;
    double mean = 0, variance = 0;
    double dominantWavelength = 0; // cells (spectrumStats)
    double nyquistFraction = 0;    // share of power at |k| > 0.4 cycles/cell (spectrumStats)
    // Largest |moment(k)|, k = 2..12, of orientationStats: near 1 for parallel
    // stripes, ~0.1 or less for isotropic spots and labyrinths. Reported, not
    // used by classifyPattern (spots on a lattice are anisotropic too).
    double orientationStrength = 0;
    int featureCount = 0;           // features of >= 3 cells
    double minorityFraction = 0;    // share of cells in the minority phase
    double meanFeatureArea = 0;     // cells
    double largestFeatureShare = 0; // share of the minority phase in the largest feature
    // Per feature, elongation = max(major / minor axis of its second moments,
    // area of the ellipse with those moments / its area): 1 for a disc or a
    // square, the length-to-width ratio for a straight bar, and large for a
    // curved worm or branching maze wall, whose moments span far more than it
    // fills. A feature that wraps all the way around the periodic grid (an
    // endless stripe) counts as kWrapElongation. Both parts are area ratios
    // of whole features, so they hardly depend on how finely a feature is
    // pixelated, unlike perimeter-based measures.
    double elongation = 0; // area-weighted mean over features
    // Area-weighted share of features with elongation >= kElongatedFeature.
    double elongatedShare = 0;
};

// A wrapping feature's elongation, a stand-in for "unbounded".
constexpr double kWrapElongation = 20.0;
// Elongation from which a feature is a stripe segment rather than a spot: a
// 2:1 bar is a short worm; Turing spots and dividing Gray-Scott spots read
// well under this, stripes and worms well over.
constexpr double kElongatedFeature = 2.0;

// Measures one chemical plane; `periodic` as for featureCount().
PatternStats measurePattern(const State& state, int chemical, bool periodic = true);
// The same for a state on a domain: its FFT needs grid axes, so an atlas is
// refused by name (requireGridAxes); a tiled grid's tiles are measured one by
// one by the sweep, so here the whole state is measured as one grid.
PatternStats measurePattern(const State& state, int chemical, const Domain& domain);

enum class PatternClass { Uniform, Spots, Stripes, Mixed, Unstable };

// "uniform", "spots", "stripes/labyrinth", "mixed", "unstable".
std::string toString(PatternClass c);

// Unstable: NaN/Inf, values outside saneRange (when given), or a grid-scale
// checkerboard; Uniform: no visible structure; Spots: mostly compact
// isolated features; Stripes: mostly elongated or wrapping features (stripes,
// worms, labyrinths); Mixed: both in comparable amounts. Thresholds are in
// pattern_classifier.cpp with their reasons.
PatternClass classifyPattern(const PatternStats& stats, const ChemicalSpec* saneRange = nullptr);

// `stats` as a report lists them next to their class `c`. A uniform plane has no visible
// structure, so the structure measures that the flat field's round-off or faint noise still
// produced (feature count and areas, wavelength, orientation, elongation) read 0, not a count
// that contradicts "uniform"; mean, variance, min and max are kept. Other classes are unchanged
// (they already agree: spots and stripes need features; "mixed" with 0 features means
// structure only in features of < 3 cells).
PatternStats statsForClass(PatternStats stats, PatternClass c);

} // namespace morphogen
