#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/session/session.hpp"

namespace morphogen {

// What a stability check found, for a front end to show: the CLI prints each
// note on stderr ("morphogen: " and, for a warning, "warning: " first).
struct StabilityNote {
    bool warning = false;
    std::string text;
};
struct StabilityReport {
    std::vector<StabilityNote> notes;
    bool capped = false; // some segment's dt was lowered
    // Set when an operator grows for every dt: the session cannot run
    // explicitly (what to change is in the text). The notes before it stand.
    std::optional<std::string> refused;
};

// Checks the time step of every segment of a session before it runs, the
// engine's one place for it (the CLI and the designer call it). Explicit
// steps: the spectral radius of I + dt A from each operator's Fourier symbol
// on the grid (a Gershgorin bound for a diffusion map); an operator that
// grows for every dt is refused (`refused`, checking stops there; a caller
// reports it as bad input), a dt above the limit is capped
// to 0.9 of it in the session (so the written session records it), with a
// warning. Cascade stages are checked in order, each with its own model,
// parameters and dt (a later stage inherits an earlier one's capped dt); a
// schedule's coarse levels are more stable than the finest, which is checked.
// Semi-implicit steps report the relaxation's residual factor. `verbose` adds
// the notes that are not warnings.
StabilityReport checkSessionStability(Session& session, bool verbose);

} // namespace morphogen
