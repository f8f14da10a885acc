#include "cli/render_output.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>

#include "core/analysis/result_checks.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/operators/stability.hpp"
#include "core/output/colormap.hpp"
#include "core/output/texture_set.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/stability_check.hpp"

namespace morphogen::cli {

void checkStability(Session& session, bool verbose) {
    const StabilityReport report = checkSessionStability(session, verbose);
    for (const StabilityNote& note : report.notes)
        std::fprintf(stderr, "morphogen: %s%s\n", note.warning ? "warning: " : "",
                     note.text.c_str());
    if (report.refused)
        throw InputError(*report.refused);
}

int runChunk(const Session& session) {
    return std::max(50, std::min(500, int(4e7 / double(session.width * session.height))));
}

namespace {

std::vector<std::string> chemicalNames(const ReactionModel& model) {
    std::vector<std::string> names;
    for (const ChemicalSpec& c : model.chemicals())
        names.push_back(c.name);
    return names;
}

} // namespace

void requireFinite(const RunResult& result) {
    const Session& session = result.completed;
    const auto bad = describeNonFinite(result.state, chemicalNames(session.outputModel()));
    if (!bad)
        return;
    std::ostringstream os;
    os << "the result after " << result.stepsDone << " steps holds NaN or infinite values (" << *bad
       << "); nothing was written; try a smaller time step such as --dt " << suggestDt(session);
    throw std::runtime_error(os.str());
}

bool warnIfFlat(const RunResult& result) {
    const Session& session = result.completed;
    const ReactionModel& model = session.outputModel();
    const int chemical = colormapChemical(session.colormap, model);
    const auto flat =
        describeFlatChannel(result.state, chemical, model.chemicals()[std::size_t(chemical)].name);
    if (!flat)
        return false;
    std::ostringstream os;
    os << "warning: the result is uniform: " << *flat << " after " << result.stepsDone
       << " steps, so the image is one colour; ";
    // The likely cause, in the order they are decided: a start with nothing
    // to grow from, a step too large to resolve the pattern, the parameters.
    const std::vector<Session> parts = segmentSessions(session);
    const Session& last = parts.back();
    if (allChannelsFlat(initialState(parts.front()))) {
        os << "it started uniform too, and nothing breaks the symmetry: give the start noise "
              "or seed spots (--init)";
    } else if (last.integrator == Integrator::SemiImplicit) {
        // Stable at any dt, but a step much larger than the reaction's time scale smooths
        // the pattern away instead of growing it.
        os << "semi_implicit at dt " << last.dt
           << " stays stable but a step this large can damp the pattern away: try a smaller "
              "--dt such as "
           << suggestDt(last);
    } else {
        os << "with these parameters the start's perturbations decay: try other values "
              "(--param; `morphogen map` shows where patterns form)";
    }
    std::fprintf(stderr, "morphogen: %s\n", os.str().c_str());
    return true;
}

void writeRenderOutput(const RunResult& result, const std::string& imagePath,
                       const std::string& sessionPath, int bitDepth, OutputFiles& files) {
    requireFinite(result);
    const Session& session = result.completed;
    const ReactionModel& model = session.outputModel(); // the final state's
    if (imageFormatForPath(imagePath) == ImageFormat::Exr) {
        writeRawImage(files.stage(imagePath), result.state, chemicalNames(model));
    } else {
        const int chemical = colormapChemical(session.colormap, model);
        writeColourMapped(files.stage(imagePath),
                          ColourMapRows(result.state, chemical,
                                        colormapOn(session.colormap, session), session.edges),
                          bitDepth);
    }
    saveSessionFile(session, files.stage(sessionPath));
}

} // namespace morphogen::cli

namespace morphogen::cli {

void addTextureSetFlags(CLI::App& cmd, TextureSetFlags& flags) {
    cmd.add_option("--texture-set", flags.dir,
                   "also (or, without --out, only) write a texture set into this folder: albedo, "
                   "height (16-bit PNG and EXR), normal and mask maps, session.json and the "
                   "texture_set.json manifest");
    cmd.add_option("--height-range", flags.heightRange,
                   "LO:HIGH chemical values mapped to height 0 and 1 (default: the model's "
                   "display range)");
    cmd.add_option("--normal-strength", flags.normalStrength,
                   "texels of displacement for a height step of the whole range (default 1)")
        ->each([&flags](const std::string&) { flags.normalStrengthSet = true; });
    cmd.add_option("--normal-format", flags.normalFormat,
                   "normal map green channel: opengl (+Y up) or directx (+Y down); default opengl");
    cmd.add_option("--mask-threshold", flags.maskThreshold,
                   "mask is 255 where the height (0..1 over its range) is above this (default 0.5)")
        ->each([&flags](const std::string&) { flags.maskThresholdSet = true; });
}

namespace {

// "1.5", "-1": a flag's value as the user would have written it.
std::string shortNumber(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

std::array<float, 2> parseHeightRange(const std::string& text) {
    const std::string what = "--height-range '" + text +
                             "': expected LO:HIGH, two finite numbers "
                             "with LO < HIGH (chemical values mapped to height 0 and 1)";
    const std::size_t colon = text.find(':', 1); // a leading '-' is a sign, not the separator
    if (colon == std::string::npos)
        throw InputError(what);
    std::array<float, 2> r{};
    const std::string parts[2] = {text.substr(0, colon), text.substr(colon + 1)};
    for (int i = 0; i < 2; ++i) {
        char* end = nullptr;
        const double v = std::strtod(parts[i].c_str(), &end);
        if (parts[i].empty() || *end != '\0' || !std::isfinite(v) || std::abs(v) > 1e30)
            throw InputError(what);
        r[std::size_t(i)] = float(v);
    }
    if (!(r[0] < r[1]))
        throw InputError(what);
    return r;
}

} // namespace

void applyTextureSetFlags(const TextureSetFlags& flags, Session& session) {
    HeightSpec& h = session.heightMaps;
    if (!flags.heightRange.empty())
        h.range = parseHeightRange(flags.heightRange);
    if (flags.normalStrengthSet) {
        if (!std::isfinite(flags.normalStrength) || flags.normalStrength < 0 ||
            flags.normalStrength > kMaxNormalStrength)
            throw InputError("--normal-strength " + shortNumber(flags.normalStrength) +
                             " is out of range (accepted: 0 to " +
                             std::to_string(int(kMaxNormalStrength)) +
                             " texels of displacement per height range)");
        h.normalStrength = float(flags.normalStrength);
    }
    if (!flags.normalFormat.empty()) {
        const std::optional<NormalFormat> format = parseNormalFormat(flags.normalFormat);
        if (!format)
            throw InputError("--normal-format '" + flags.normalFormat +
                             "' is unknown (accepted: " + normalFormatNames() + ")");
        h.normalFormat = *format;
    }
    if (flags.maskThresholdSet) {
        if (!std::isfinite(flags.maskThreshold) || flags.maskThreshold < 0 ||
            flags.maskThreshold > 1)
            throw InputError("--mask-threshold " + shortNumber(flags.maskThreshold) +
                             " is out of range (accepted: 0 to 1, a height over its range)");
        h.maskThreshold = float(flags.maskThreshold);
    }
    if (!flags.dir.empty())
        prepareTextureSetDir(flags.dir);
}

void writeTextureSetOutput(const RunResult& result, const TextureSetFlags& flags,
                           OutputFiles& files) {
    if (flags.dir.empty())
        return;
    requireFinite(result);
    writeTextureSet(flags.dir, result.state, result.completed, files);
}

} // namespace morphogen::cli
