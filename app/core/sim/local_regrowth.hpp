#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/base/state.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/sim/localized_rd.hpp"

namespace morphogen {

// Localized re-growth after a stroke on a surface, as a run follows it step
// by step (SessionRun, for strokes that ask for it: StrokeSpec::localized).
// Lo et al. section 4 inside a live run: the tiles the stroke touched (A0)
// start the set A1 = N(A0), and only its tiles step. Every `checkEvery`
// steps the state is compared with the previous check:
//  - where the set's outer ring of tiles (those with a neighbour outside it)
//    changed by more than `spreadAbove` per step, the change has reached the
//    set's edge and the set grows by a ring (A_{k+1} = N(A_k));
//  - once no texel changes by `settledBelow` per step (re-equilibrium), or
//    the set passes `globalFraction` of the tiles, the re-growth is over and
//    every tile steps again.
// The set grows where the change has actually spread, not on a schedule
// from the diffusion rate (Lo's m, iterationsToCrossTile): on a real mesh the
// fastest texels (small ones, 4-20x the median weight) make m a step or two
// and the set went global before a spot re-formed. Measured growth keeps a
// stroke local as long as its effect is. Everything counts steps, never
// time, so a session replays it identically: same edits at the same steps,
// same sets, same pixels.
//
// The rest of the surface holds its values while the set runs: right for a
// stroke on a settled pattern (what Lo's localized RD is for); on a pattern
// still growing, growth outside the set pauses until the re-growth ends.
struct LocalRegrowthOptions {
    int checkEvery = 25;
    float settledBelow = 2e-5f; // as RelaxOptions: a settled pattern drifts by far less
    float spreadAbove = 2e-4f;  // a change arriving moves a texel by 1e-3 or more per step
    double globalFraction = 0.4;
};

class LocalRegrowth {
public:
    // `touched` non-empty.
    LocalRegrowth(std::shared_ptr<const TileNeighbourhoods> neighbourhoods,
                  std::shared_ptr<const Atlas> atlas, const std::vector<int>& touched,
                  const LocalRegrowthOptions& options = {});

    // Another change while it runs (the next piece of a drag, another
    // stroke): the set takes N(touched) in, and the checks start over.
    void touch(const std::vector<int>& touched);

    // Over: every tile steps again (re-equilibrium, or the set grew past the
    // threshold).
    bool over() const { return m_over; }
    bool settled() const { return m_settled; }
    // The active set now (ascending); every tile once over.
    const std::vector<int>& tiles() const { return m_schedule.tiles(); }
    int phase() const { return m_phase; } // k of A_k
    int tileCount() const { return m_neighbourhoods->tileCount(); }
    // Steps the run may take before the next check (>= 1).
    int stepsBeforeChange() const;
    // Counts `steps` (at most stepsBeforeChange()) run with tiles(). At a
    // check, `readState` gives the state now (the atlas's cells). Returns
    // true when tiles() or over() changed.
    bool stepped(int steps, const std::function<State()>& readState);

private:
    std::shared_ptr<const TileNeighbourhoods> m_neighbourhoods;
    LocalRegrowthOptions m_options;
    std::shared_ptr<const Atlas> m_atlas;
    ActiveTileSchedule m_schedule; // its own growth off: the checks grow it
    int m_phase = 1;
    int m_sinceCheck = 0;
    std::optional<State> m_previous; // the state at the last check
    bool m_over = false;
    bool m_settled = false;
};

// The largest change of any value of any chemical between two states of the
// same size, per step over `steps` steps: over every cell, or over the
// cells of the given tiles of an atlas.
float maxChangePerStep(const State& now, const State& before, int steps);
float maxChangePerStep(const State& now, const State& before, int steps, const Atlas& atlas,
                       const std::vector<int>& tiles);

} // namespace morphogen
