#pragma once
// What `map` and `sweep` start every point from, and the sessions their
// --pick writes for one point: pure functions of the flags and the sweep, so
// a pick needs no run.

#include <optional>
#include <string>
#include <string_view>

#include "core/models/initial_condition.hpp"
#include "core/session/session.hpp"
#include "core/sim/sweep.hpp"

namespace morphogen {

class ReactionModel;

enum class ExplorationStart {
    // Perturbations over the whole area: every point shows the pattern it
    // settles to (what a render of that point's values gives).
    Noise,
    // The preset's or model's own start (Gray-Scott: a few seed spots): a
    // map shows growth fronts spreading from the seeds (Pearson's, McGraw's maps).
    Preset,
};
std::string toString(ExplorationStart start);
std::optional<ExplorationStart> parseExplorationStart(std::string_view name);
std::string explorationStartNames();

// The noise start for `model`, made from `own` (a preset's or the model's
// default start). A model that starts from noise keeps `own` if it is noise,
// else `own`'s background with the model's default noise added where `own`
// has none (a preset's stripe initiators become noise over the whole area).
// A model that grows from seeds
// (Gray-Scott: noise around u = 1, v = 0 decays to a uniform state at every
// point) gets its seeds everywhere instead: discs of `own`'s inside values
// on a fully jittered lattice, one per (4 r)^2 cells (about a fifth of the
// area), so every region starts within a few pattern wavelengths of a seed.
// The lattice is set by its spacing, not a count, so it covers any size.
InitialCondition noiseStart(const InitialCondition& own, const ReactionModel& model);

// A tile of a sweep: column from the left, row from the bottom, both from 0
// (as in stats.csv).
struct TilePick {
    int column = 0;
    int row = 0;
};
// "COL,ROW" within a columns x rows grid; InputError naming `flag`, the text
// and the accepted ranges otherwise.
TilePick parseTilePick(const std::string& flag, const std::string& text, int columns, int rows);

// A point of a map: parameter values on its x and y axes.
struct PointPick {
    float x = 0;
    float y = 0;
};
// "X,Y" within the axes' ranges; InputError naming `flag`, the text and the
// axis ranges otherwise.
PointPick parsePointPick(const std::string& flag, const std::string& text, const SweepAxis& x,
                         const SweepAxis& y);

// Tile `pick` of `batched` (batchedSession) as a standalone session of
// size x size cells at the tile's scale (pickedAtSize).
Session pickTile(const Session& batched, TilePick pick, int size);

// The map session `map` (x and y as parameter maps) at one point: the two
// parameters set uniformly to `pick`'s values (also over any cascade stage's
// own values, as the maps override them), at size x size cells at the map's
// scale (pickedAtSize).
Session pickPoint(const Session& map, const SweepAxis& x, const SweepAxis& y, PointPick pick,
                  int size);

// `point`, a standalone session of one unit per cell, at size x size cells
// and the same scale: one unit per cell (length = size), with seed spots as
// dense as they were (their count scaled by the area).
Session pickedAtSize(Session point, int size);

} // namespace morphogen
