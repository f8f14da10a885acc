#pragma once

#include "core/state.hpp"

namespace morphogen {

// Statistics for comparing long runs by what they look like rather than by
// pixels (RD amplifies differences, so pixels diverge between backends).
struct SpectrumStats {
    double dominantWavelength = 0; // cells, from the radially averaged power spectrum peak
    double nyquistFraction = 0;    // share of (non-DC) power in the outer band |k| > 0.4 (cycles/cell)
    double variance = 0;
};

// Spectrum statistics of one chemical plane (periodic: the grid is one tile).
SpectrumStats spectrumStats(const State& state, int chemical);

} // namespace morphogen
