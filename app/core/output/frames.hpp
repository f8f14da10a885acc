#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

namespace morphogen {

// A growth animation's frames are taken from one run at these steps (counted
// over all stages or schedule levels), ascending, the last one the run's
// final step. `frames` N >= 1: N frames evenly spaced, frame i (from 0) at
// ceil(total * (i + 1) / N), repeats dropped when N > total; `every` K >= 1:
// a frame every K steps, plus the final step when K does not divide the total.
// Exactly one must be given; otherwise, or for a value below 1, throws
// InputError naming the flag (--frames, --every).
std::vector<int> frameSteps(int totalSteps, std::optional<int> frames, std::optional<int> every);

// The steps a session runs over all its stages or schedule levels.
int sessionTotalSteps(const Session& session);

// Called for frame `index` (from 0) with the run so far: its steps, and its
// state at the session's final size (a coarse schedule level's state is
// resampled, so every frame has one size).
using FrameSink = std::function<void(int index, const RunResult& sofar)>;

// runSession (core/sim/runner.hpp) taking frames from the one run: chunks end
// at every step of `steps` (frameSteps over the steps of all stages or
// levels), where `sink` gets the state. options.cancel stops after the
// current chunk, the frames so far written. The result is runSession's, to
// the last pixel (the run is the same, only cut into other pieces).
RunResult runWithFrames(const Session& session, const SimulatorFactory& makeSimulator,
                        const RunOptions& options, const std::vector<int>& steps,
                        const FrameSink& sink);

// The chemical values mapped to the two ends of the colour map for every
// frame of a sequence. They are fixed for the whole sequence, not each
// frame's min and max, so a region that holds its value keeps its colour
// (per-frame min-max normalisation makes a growing pattern flicker).
struct FrameLevels {
    float low = 0.0f;
    float high = 1.0f;
    std::string source; // "--frame-range" or "model display range"
};

// `range` "LO:HIGH" when given (InputError unless LO < HIGH, both finite),
// else the model's display range of `chemical`.
FrameLevels frameLevels(const ReactionModel& model, int chemical, const std::string& range);

// How a frame of a run whose current stage has model `stage` is coloured:
// `spec` with the run's locked `levels`, or, in an earlier stage of a cascade
// whose model lacks the colour map's chemical (turk_giraffe's spots before the
// net's g2), the same map on that stage's display chemical over its display
// range.
struct FrameColouring {
    ColorMapSpec spec;
    FrameLevels levels;
};
FrameColouring frameColouring(const ColorMapSpec& spec, const ReactionModel& stage,
                              const FrameLevels& levels);

// One chemical mapped through spec's colour map with locked levels: t =
// (value - low) / (high - low), then windowed by spec.levels and clamped.
// Non-finite values map to the low end. Interleaved RGB in [0, 1].
std::vector<float> applyLockedColormap(const State& state, int chemical, const ColorMapSpec& spec,
                                       const FrameLevels& levels);

// DIR/frame_00042.png, and the pattern ffmpeg reads them by.
std::string framePath(const std::string& dir, int index);
std::string framePattern(const std::string& dir);

enum class VideoFormat { Mp4, Gif };
// By the extension of `path` (.mp4 or .gif, any case); InputError otherwise.
VideoFormat videoFormatForPath(const std::string& path);

// The ffmpeg command line that encodes the frames in `dir` into `out` at
// `fps` frames per second, each argument shell-quoted (runnable as printed).
// mp4: H.264, yuv420p, sides padded to even; gif: a palette pass.
std::string ffmpegCommand(const std::string& dir, const std::string& out, double fps);

} // namespace morphogen
