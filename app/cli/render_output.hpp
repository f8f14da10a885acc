#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "core/io/output_files.hpp"
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

// Refuses (std::runtime_error, exit 1) a result holding NaN or infinite
// values, naming the cells and the steps run: the runs check for blow-up as
// they go, and this is the last check before anything is written.
void requireFinite(const RunResult& result);

// Warns on stderr when the chemical the image shows came out one flat value
// (the image is one colour), saying what likely happened and what to try.
// Only a warning: a uniform result can be the right answer (gs_uniform, a
// parameter study), and its image and session are a true record of it.
// Returns whether it warned.
bool warnIfFlat(const RunResult& result);

// Stages into `files` (core/io/output_files.hpp) result.state as `imagePath`
// (.png/.tif colour-mapped by the session's colour map at `bitDepth`; .exr
// raw floats) and then result.completed, the session that reproduces it, as
// `sessionPath`: files.commit() renames them into place, the session last,
// and a failure before that leaves the previous image and session untouched.
void writeRenderOutput(const RunResult& result, const std::string& imagePath,
                       const std::string& sessionPath, int bitDepth, OutputFiles& files);

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

// Stages the set of result for flags.dir into `files` (core/output/texture_set.hpp);
// does nothing without a folder.
void writeTextureSetOutput(const RunResult& result, const TextureSetFlags& flags,
                           OutputFiles& files);

} // namespace morphogen::cli
