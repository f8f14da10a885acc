#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/session/cascade.hpp"
#include "core/session/session.hpp"

namespace morphogen {

// How a session reaches its size (issue: the same look at any size). A
// session's steps and dt are for a grid of one cell per model unit (h = 1);
// a finer grid takes `substeps` steps of dt / substeps per session step, so
// the simulated time, and with it the pattern, stays the same (an explicit
// step's stability limit shrinks as h^2). A large size (h < 1/2) runs the
// session's own steps at a base size of about one cell per unit and then
// refines: short runs at each doubling up to the size, each from the
// previous one resampled (coarse-to-fine), so a 4x larger image costs about
// the cells, not the cells times the steps. The refined image is the base's
// pattern at more detail: the layout is decided at the base.
struct ResolutionPlan {
    int baseWidth = 0; // where the session's steps (or stages) run
    int baseHeight = 0;
    // Finer levels the engine adds, coarsest first, each of refineSteps()
    // steps. Empty: the base is the session's size.
    std::vector<ScheduleLevel> refine;
};

// Steps (of the level's own dt) run at each refinement level.
int refineSteps();

// The plan for `session`: refinement only for a grid session with a length,
// no schedule of its own, coarseToFine set and a size at least twice its
// length; else the base is the session's size.
ResolutionPlan planResolution(const Session& session);

// One segment of a session: a schedule level, a cascade stage or a
// refinement level.
struct Segment {
    Session session; // its model, size, steps, params, dt and grid spacing, as run
    std::optional<FreezeRule> freeze;
    std::map<std::string, float> reset;
    bool newModel = false; // starts session.model afresh from session.init
    // Steps run per session step (dt / substeps): 1 unless the grid is finer
    // than one cell per model unit.
    int substeps = 1;
    float sessionDt = 1.0f; // the session's dt for this segment (session.dt * substeps)
    bool refine = false;    // added by planResolution: not a level or stage of the session
};

// The segments a session runs, in order (one for a plain session). Throws
// InputError when a segment's step count passes the engine's limit.
std::vector<Segment> segmentsOf(const Session& session);

// A weighted atlas's explicit steps per session step (session.atlasWeights set):
// its weights' limit, with anisotropy its chemicals' mixes', and with a param
// map of a diffusion rate that map's largest value.
int atlasSubsteps(const Session& session);
// The same before rounding up: the explicit limit's share one engine step at
// the session's dt would take (atlasSubsteps = ceil of it, at least 1).
double atlasSubstepRatio(const Session& session);

// One line on how `session` reaches its size: units per cell, the base size
// and the refinement levels, substeps; empty for a session that runs as
// written at one unit per cell.
std::string describePlan(const Session& session);

} // namespace morphogen
