#include "core/output/frames.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/sim/session_run.hpp"

namespace morphogen {

std::vector<int> frameSteps(int totalSteps, std::optional<int> frames, std::optional<int> every) {
    if (frames && every)
        throw InputError("--frames and --every are exclusive: give one");
    if (!frames && !every)
        throw InputError("a frame sequence needs --frames N or --every K");
    if (frames && *frames < 1)
        throw InputError("--frames " + std::to_string(*frames) + ": accepted are 1 or more");
    if (every && *every < 1)
        throw InputError("--every " + std::to_string(*every) + ": accepted are 1 or more steps");
    std::vector<int> steps;
    const long long total = std::max(0, totalSteps);
    if (frames) {
        const long long n = *frames;
        for (long long i = 1; i <= n; ++i) {
            const int step = int((total * i + n - 1) / n);
            if (steps.empty() || steps.back() != step)
                steps.push_back(step);
        }
    } else {
        for (long long s = *every; s <= total; s += *every)
            steps.push_back(int(s));
        if (steps.empty() || steps.back() != total)
            steps.push_back(int(total));
    }
    return steps;
}

int sessionTotalSteps(const Session& session) {
    int total = 0;
    for (const Segment& segment : segmentsOf(session))
        total += segment.session.steps;
    return total;
}

RunResult runWithFrames(const Session& session, const SimulatorFactory& makeSimulator,
                        const RunOptions& options, const std::vector<int>& steps,
                        const FrameSink& sink) {
    const int chunk = std::max(1, options.chunk);
    SessionRun run(session, makeSimulator, chunk);
    run.setSettleCheck(options.settleEvery, options.settleAfter, options.settled);
    std::size_t next = 0;
    bool cancelled = false;
    while (next < steps.size() || !run.finished()) {
        const int done = run.position().stepsDone;
        if (next < steps.size() && (done >= steps[next] || run.finished())) {
            sink(int(next), run.result());
            ++next;
            continue;
        }
        if (options.cancel && options.cancel->load()) {
            cancelled = true;
            break;
        }
        int piece = std::min(chunk, run.segmentRemaining());
        if (next < steps.size())
            piece = std::min(piece, steps[next] - done);
        run.advance(piece);
        if (options.progress)
            options.progress(run.position().stepsDone, run.position().totalSteps);
    }
    RunResult result = run.takeResult();
    result.cancelled = cancelled;
    result.settled = run.settledEarly();
    return result;
}

FrameLevels frameLevels(const ReactionModel& model, int chemical, const std::string& range) {
    if (range.empty()) {
        assert(chemical >= 0 && chemical < int(model.chemicals().size()));
        const std::array<float, 2> r = model.chemicals()[std::size_t(chemical)].displayRange;
        return {r[0], r[1], "model display range"};
    }
    const std::size_t colon = range.find(':');
    const std::string a = range.substr(0, colon);
    const std::string b = colon == std::string::npos ? "" : range.substr(colon + 1);
    char* end0 = nullptr;
    char* end1 = nullptr;
    const float low = std::strtof(a.c_str(), &end0), high = std::strtof(b.c_str(), &end1);
    if (colon == std::string::npos || a.empty() || b.empty() || *end0 || *end1 ||
        !std::isfinite(low) || !std::isfinite(high) || !(low < high))
        throw InputError("--frame-range '" + range +
                         "' is not LO:HIGH chemical values with LO < HIGH (e.g. 0:0.5)");
    return {low, high, "--frame-range"};
}

FrameColouring frameColouring(const ColorMapSpec& spec, const ReactionModel& stage,
                              const FrameLevels& levels) {
    if (spec.chemical.empty() || stage.chemicalIndex(spec.chemical) >= 0)
        return {spec, levels};
    FrameColouring own{spec, {}};
    const int chemical = stage.displayChemical();
    own.spec.chemical = stage.chemicals()[std::size_t(chemical)].name;
    own.levels = frameLevels(stage, chemical, "");
    return own;
}

std::vector<float> applyLockedColormap(const State& state, int chemical, const ColorMapSpec& spec,
                                       const FrameLevels& levels) {
    const ColourMapRows rows(state, chemical, spec, levels.low, levels.high);
    const std::size_t rowLength = std::size_t(state.width()) * 3;
    std::vector<float> rgb(state.cellCount() * 3);
    for (int y = 0; y < state.height(); ++y)
        rows.row(y, rgb.data() + std::size_t(y) * rowLength);
    return rgb;
}

std::string framePath(const std::string& dir, int index) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", index);
    return (std::filesystem::path(dir) / name).string();
}

std::string framePattern(const std::string& dir) {
    return (std::filesystem::path(dir) / "frame_%05d.png").string();
}

VideoFormat videoFormatForPath(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (ext == ".mp4")
        return VideoFormat::Mp4;
    if (ext == ".gif")
        return VideoFormat::Gif;
    throw InputError("--video '" + path + "': unsupported extension '" + ext +
                     "' (accepted: .mp4, .gif)");
}

namespace {

std::string shellQuote(const std::string& s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

} // namespace

std::string ffmpegCommand(const std::string& dir, const std::string& out, double fps) {
    char rate[32];
    std::snprintf(rate, sizeof rate, "%g", fps);
    std::string cmd = "ffmpeg -y -loglevel error -framerate " + std::string(rate) + " -i " +
                      shellQuote(framePattern(dir));
    if (videoFormatForPath(out) == VideoFormat::Mp4)
        // H.264 in yuv420p wants even sides; players expect that pixel format.
        cmd += " -vf " + shellQuote("pad=ceil(iw/2)*2:ceil(ih/2)*2") +
               " -c:v libx264 -pix_fmt yuv420p";
    else
        // One palette made from all frames, so the gif's colours do not shift between frames.
        cmd += " -vf " + shellQuote("split[a][b];[a]palettegen[p];[b][p]paletteuse");
    return cmd + " " + shellQuote(out);
}

} // namespace morphogen
