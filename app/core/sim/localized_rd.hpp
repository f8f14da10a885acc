#pragma once

#include <vector>

#include "core/domain/tile_sets.hpp"

namespace morphogen {

class Atlas;
class BrushRegion;
struct StepConstants;

// Localized reaction-diffusion (Lo et al. section 4): after a local change
// to a pattern at equilibrium, step only the tiles the change can have
// reached, A1 = N(A0) from the tiles A0 the change touched, growing to
// A_{k+1} = N(A_k) every `growEvery` iterations, and step everything once |A|
// passes a fraction of the tiles. Simulator::setActiveTiles runs a set.

// The tiles of an atlas a brush region touches (A0), ascending.
std::vector<int> touchedTiles(const Atlas& atlas, const BrushRegion& region);

// Iterations the effect of a change needs to cross one tile of n texels: the
// `m` of the growth schedule. A disturbance spreading by diffusion at rate D
// (texels^2 per unit time) has spread, after time t, to a root-mean-square
// radius sqrt(4 D t) (variance 2 D t per axis in two dimensions); it reaches
// one tile width when 4 D t = n^2, i.e. after t = n^2 / (4 D), that is
//   m = ceil(n^2 / (4 D dt))
// explicit steps of dt. D is the largest diffusion rate of the run times its
// largest per-link coefficient (1 unweighted; a weighted atlas's coefficients
// turn units^-2 into texels^-2). The tails beyond that radius are what A_k's
// one-tile margin (N adds a whole ring of tiles) absorbs. At least 1.
int iterationsToCrossTile(int tileSize, double maxDiffusion, double dt);
// The same from a run's constants (its rates, weights, dt and atlas).
int iterationsToCrossTile(const StepConstants& k);

// The active tile set through the phases A1, A2, ... of one localized run.
class ActiveTileSchedule {
public:
    // A0 = `touched`; the set starts at A1 = N(A0). growEvery >= 1;
    // globalFraction in (0, 1]: global once |A| > globalFraction * tiles.
    ActiveTileSchedule(const TileNeighbourhoods& neighbourhoods, const std::vector<int>& touched,
                       int growEvery, double globalFraction = 0.4);

    // True once the set has passed the threshold: every tile steps.
    bool global() const { return m_global; }
    // A_k, ascending; empty once global (setActiveTiles' "all").
    const std::vector<int>& tiles() const { return m_tiles; }
    int phase() const { return m_phase; } // k of A_k (the phase the set is in)
    // Iterations to run before the set next changes (0 once global: any).
    int iterationsLeft() const { return m_global ? 0 : m_growEvery - m_done; }
    // Another change while the set runs: the set becomes A_k united with
    // N(touched) (the set already holds the earlier change's margin) and
    // its phase starts over. Nothing once global.
    void add(const std::vector<int>& touched);
    // Counts `iterations` run with tiles(); grows the set when a phase is
    // complete. Returns true when the set changed.
    bool advance(int iterations);

private:
    void checkThreshold();

    const TileNeighbourhoods* m_neighbourhoods;
    std::vector<int> m_tiles;
    int m_growEvery;
    double m_globalFraction;
    int m_phase = 1;
    int m_done = 0;
    bool m_global = false;
};

} // namespace morphogen
