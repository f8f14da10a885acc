#pragma once

#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "core/io/output_files.hpp"
#include "core/output/frames.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

namespace morphogen::cli {

// `render --frames N | --every K`: a growth animation from the one run, and
// `--video` to encode it with ffmpeg when that program is installed.
struct FrameFlags {
    std::optional<int> frames; // given or not (so --frames 0 is refused, not ignored)
    std::optional<int> every;
    std::string dir;   // empty: <out stem>_frames next to --out
    std::string range; // --frame-range LO:HIGH; empty: the model's display range
    std::string video; // .mp4 or .gif; empty: frames only
    double fps = 30;
    bool wanted() const { return frames || every || !video.empty(); }
};

void addFrameFlags(CLI::App& cmd, FrameFlags& flags);

// Checks the flags (InputError, exit 2) and creates the frame folder, before
// the run; resolves flags.dir from `out` when it is empty.
void prepareFrames(FrameFlags& flags, const std::string& out, const Session& session);

// runSession writing frames: each one the state at its step colour-mapped
// with locked levels (core/output/frames.hpp) into `frames`, a StagedSequence
// for flags.dir (core/io/output_files.hpp), whose commit() replaces the
// frame_NNNNN.png files an earlier run left there, so a video never mixes
// runs and a failed run leaves them. Ctrl-C (options.cancel) stops after the
// current chunk, keeping the frames so far. A frame holding NaN or infinite
// values is a blow-up (BlowUpError naming the steps), never written.
//
// `draw`, when given, writes each frame instead (a session on a model: a
// screenshot of the model, render_surface.hpp), coloured as `colouring` says
// (the locked levels; frameColouring).
using FrameDrawer = std::function<void(const std::string& path, const RunResult& sofar,
                                       const FrameColouring& colouring)>;
RunResult renderFrames(const Session& session, const SimulatorFactory& makeSimulator,
                       const RunOptions& options, const FrameFlags& flags, StagedSequence& frames,
                       const FrameDrawer& draw = {});

// Encodes the frames with ffmpeg when it is on PATH, into a temporary renamed
// into place when ffmpeg succeeds; otherwise prints how to install it and the
// command to run (not an error). No-op without --video.
void encodeVideo(const FrameFlags& flags);

} // namespace morphogen::cli
