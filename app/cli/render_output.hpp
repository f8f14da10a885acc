#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

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

// `render --texture-set DIR` and the flags that set the session's "height" block.
struct TextureSetFlags {
    std::string dir;         // empty: no texture set
    std::string heightRange; // LO:HIGH; empty: the session's or the model's levels
    // Numbers count only when given (the *Set flags), so a session's value stays otherwise.
    double normalStrength = 0;
    bool normalStrengthSet = false;
    std::string normalFormat;
    double maskThreshold = 0;
    bool maskThresholdSet = false;
};

// Registers --texture-set and its flags on `cmd`.
void addTextureSetFlags(CLI::App& cmd, TextureSetFlags& flags);

// Applies the flags to session.heightMaps (InputError for a bad value) and, with a
// folder, creates it and checks it is writable: all before the run.
void applyTextureSetFlags(const TextureSetFlags& flags, Session& session);

// Writes the set of result into flags.dir (core/output/texture_set.hpp) and
// prints its manifest's path; does nothing without a folder.
void writeTextureSetOutput(const RunResult& result, const TextureSetFlags& flags);

} // namespace morphogen::cli
