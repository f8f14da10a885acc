#pragma once

#include <string>

#include "core/sim/runner.hpp"
#include "core/session/session.hpp"

namespace morphogen::cli {

// The pieces of a render shared by `render` and `gallery`, so both produce the
// same pixels and the same reproducing session for the same input.

// The engine's checkSessionStability (core/sim/stability_check.hpp), its notes
// printed on stderr: refuses (InputError) an operator that grows for every dt
// and caps a dt above the limit (the written session records the capped dt).
// `verbose` also reports a stable step and the semi-implicit residual factor,
// which a batch of presets does not need.
void checkStability(Session& session, bool verbose = true);

// Steps per chunk of runSession: bounds how long Ctrl-C waits and how often
// blow-up is checked, about the same wall time per chunk at any grid size.
int runChunk(const Session& session);

// Writes result.state to `imagePath` (.png/.tif colour-mapped by the session's
// colour map at `bitDepth`; .exr raw floats) and result.completed, the session
// that reproduces it, to `sessionPath`.
void writeRenderOutput(const RunResult& result, const std::string& imagePath,
                       const std::string& sessionPath, int bitDepth);

} // namespace morphogen::cli
