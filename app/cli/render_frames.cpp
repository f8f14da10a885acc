#include "cli/render_frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/operators/stability.hpp"
#include "core/output/colormap.hpp"
#include "core/output/frames.hpp"

namespace morphogen::cli {

namespace fs = std::filesystem;

void addFrameFlags(CLI::App& cmd, FrameFlags& flags) {
    cmd.add_option("--frames", flags.frames,
                   "growth animation: N frames evenly spaced over the one run, the last one the "
                   "final state");
    cmd.add_option("--every", flags.every, "growth animation: a frame every K steps");
    cmd.add_option("--frames-dir", flags.dir,
                   "folder of frame_00000.png ... (default: <out stem>_frames next to --out)");
    cmd.add_option("--frame-range", flags.range,
                   "LO:HIGH chemical values at the colour map's ends in every frame (default: "
                   "the model's display range); locked, so frames do not flicker");
    cmd.add_option("--video", flags.video,
                   "encode the frames to .mp4 or .gif with ffmpeg (when installed)");
    cmd.add_option("--fps", flags.fps, "video frames per second (default 30)");
}

void prepareFrames(FrameFlags& flags, const std::string& out, const Session& session) {
    if (!flags.frames && !flags.every)
        throw InputError("--video needs --frames N or --every K");
    frameSteps(sessionTotalSteps(session), flags.frames, flags.every); // throws on bad values
    if (!flags.video.empty())
        videoFormatForPath(flags.video);
    if (!(flags.fps > 0 && flags.fps <= 1000))
        throw InputError("--fps " + std::to_string(flags.fps) + ": accepted are 0 < F <= 1000");
    const ReactionModel& model = session.outputModel();
    frameLevels(model, colormapChemical(session.colormap, model), flags.range);
    if (flags.dir.empty()) {
        if (out.empty())
            throw InputError("--frames and --every need --out FILE or --frames-dir DIR");
        const fs::path p(out);
        flags.dir = (p.parent_path() / (p.stem().string() + "_frames")).string();
    }
    std::error_code ec;
    fs::create_directories(flags.dir, ec);
    if (ec || !fs::is_directory(flags.dir))
        throw InputError("--frames-dir '" + flags.dir + "' cannot be created: " + ec.message());
    checkWritable(framePath(flags.dir, 0));
}

RunResult renderFrames(const Session& session, const SimulatorFactory& makeSimulator,
                       const RunOptions& options, const FrameFlags& flags, StagedSequence& frames,
                       const FrameDrawer& draw) {
    const std::vector<int> steps =
        frameSteps(sessionTotalSteps(session), flags.frames, flags.every);
    // Levels from the final model (a cascade may change models), fixed for every frame.
    const ReactionModel& model = session.outputModel();
    const FrameLevels levels =
        frameLevels(model, colormapChemical(session.colormap, model), flags.range);
    std::fprintf(stderr, "morphogen: %zu frames into %s, levels %g:%g (%s)\n", steps.size(),
                 flags.dir.c_str(), double(levels.low), double(levels.high), levels.source.c_str());
    int checkedStep = 0; // the last frame's step: its state was sane
    const FrameSink write = [&](int index, const RunResult& sofar) {
        const ReactionModel& m = sofar.completed.outputModel();
        // A frame can fall between the run's blow-up checks: check it before it is drawn.
        if (const auto problem = findInsaneValue(sofar.state, m)) {
            const float dt = suggestDt(sofar.completed);
            std::ostringstream os;
            os << "the simulation blew up between step " << checkedStep + 1 << " and step "
               << sofar.stepsDone << " (" << *problem << ", in frame " << index << ", dt "
               << sofar.completed.dt << "); try a smaller time step such as --dt " << dt;
            throw BlowUpError(os.str(), sofar.stepsDone, dt);
        }
        checkedStep = sofar.stepsDone;
        const FrameColouring colouring = frameColouring(session.colormap, m, levels);
        if (draw) {
            draw(frames.path(index), sofar, colouring);
            frames.written(index);
            return;
        }
        writeColourMapped(frames.path(index),
                          ColourMapRows(sofar.state, colormapChemical(colouring.spec, m),
                                        colouring.spec, colouring.levels.low, colouring.levels.high,
                                        session.edges),
                          8);
        frames.written(index);
    };
    return runWithFrames(session, makeSimulator, options, steps, write);
}

namespace {

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path)
        return false;
    std::stringstream in(path);
    std::string dir;
    while (std::getline(in, dir, ':')) {
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / program;
        if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate))
            return true;
    }
    return false;
}

} // namespace

void encodeVideo(const FrameFlags& flags) {
    if (flags.video.empty())
        return;
    const std::string command = ffmpegCommand(flags.dir, flags.video, flags.fps);
    if (!onPath("ffmpeg")) {
        std::fprintf(stderr,
                     "morphogen: ffmpeg not found: frames are in %s; install it (apt-get install "
                     "ffmpeg) and run:\n%s\n",
                     flags.dir.c_str(), command.c_str());
        return;
    }
    std::fprintf(stderr, "morphogen: %s\n", command.c_str());
    writeFileAtomically(flags.video, [&](const std::string& temporary) {
        const int status = std::system(ffmpegCommand(flags.dir, temporary, flags.fps).c_str());
        if (status != 0)
            throw std::runtime_error("ffmpeg failed (status " + std::to_string(status) +
                                     "); the frames are in " + flags.dir);
    });
    std::printf("%s\n", flags.video.c_str());
}

} // namespace morphogen::cli
