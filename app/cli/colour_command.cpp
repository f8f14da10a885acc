// `morphogen colour`: re-colours a raw state written by `render --out FILE.exr`
// with the code render colours with (applyColormap), without re-simulating.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/colour_flags.hpp"
#include "cli/commands.hpp"
#include "core/analysis/result_checks.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"

namespace morphogen::cli {

namespace {

struct ColourFlags {
    std::string raw;
    std::string out;
    std::string sessionFile;
    std::string colormap;
    std::string chemical;
    std::string levels;
    int bitDepth = 8;
    GradientFlags gradient;
};

// The raw image's planes in the model's chemical order, matched by channel
// name (OpenEXR stores channels sorted by name, not in the order written).
State modelOrdered(const RawImage& raw, const ReactionModel& model, const std::string& rawPath,
                   const std::string& sessionPath) {
    std::vector<std::string> chemicals;
    for (const ChemicalSpec& c : model.chemicals())
        chemicals.push_back(c.name);
    const std::string mismatch = rawPath + ": channels (" + joinNames(raw.channelNames) +
                                 ") are not the chemicals of model " + model.name() + " in " +
                                 sessionPath + " (" + joinNames(chemicals) +
                                 "); accepted: the .exr that render --out wrote with this session";
    if (raw.channelNames.size() != chemicals.size())
        throw InputError(mismatch);
    State state(raw.state.width(), raw.state.height(), int(chemicals.size()));
    for (std::size_t c = 0; c < chemicals.size(); ++c) {
        std::size_t k = 0;
        while (k < raw.channelNames.size() && raw.channelNames[k] != chemicals[c])
            ++k;
        if (k == raw.channelNames.size())
            throw InputError(mismatch);
        std::copy(raw.state.plane(int(k)), raw.state.plane(int(k)) + state.cellCount(),
                  state.plane(int(c)));
    }
    return state;
}

void colour(const ColourFlags& f) {
    if (imageFormatForPath(f.raw) == ImageFormat::Png)
        throw InputError(f.raw + ": a PNG holds colours, not the raw state (accepted: the .exr "
                                 "or .tif that render --out FILE.exr wrote)");
    const ImageFormat outFormat = imageFormatForPath(f.out);
    if (outFormat == ImageFormat::Exr)
        throw InputError("--out " + f.out +
                         ": colour writes a colour image (accepted: .png, "
                         ".tif, .tiff)");
    if (f.bitDepth != 8 && f.bitDepth != 16)
        throw InputError("--bit-depth " + std::to_string(f.bitDepth) +
                         " is not supported (accepted: 8, 16)");
    const std::string sessionPath =
        f.sessionFile.empty() ? std::filesystem::path(f.raw).replace_extension(".json").string()
                              : f.sessionFile;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(f.raw, ec))
        throw InputError(f.raw + ": raw state image not found (accepted: the .exr that render "
                                 "--out FILE.exr wrote)");
    if (f.sessionFile.empty() && !std::filesystem::is_regular_file(sessionPath, ec))
        throw InputError(f.raw + ": no session " + sessionPath +
                         " next to it (it names the model, chemicals and colour map): give "
                         "--session FILE");
    Session session = loadSessionFile(sessionPath);
    ColorMapSpec& spec = session.colormap;
    if (!f.colormap.empty())
        spec.name = f.colormap;
    if (!f.chemical.empty())
        spec.chemical = f.chemical;
    if (!f.levels.empty())
        spec.levels = parseLevelsFlag("--levels", f.levels);
    applyGradientFlags(f.gradient, f.colormap, spec);
    const ReactionModel& model = session.outputModel();
    const int chemical = colormapChemical(spec, model);
    checkWritable(f.out);

    const RawImage raw = readRawImage(f.raw);
    const State state = modelOrdered(raw, model, f.raw, sessionPath);
    std::vector<std::string> names;
    for (const ChemicalSpec& c : model.chemicals())
        names.push_back(c.name);
    // NaN cells would be painted the low colour, a pattern that is not there.
    if (const auto bad = describeNonFinite(state, names))
        throw InputError(f.raw + ": " + *bad +
                         "; accepted: a finite state, as render writes (it refuses a blow-up)");
    if (const auto flat = describeFlatChannel(state, chemical, names[std::size_t(chemical)]))
        std::fprintf(stderr, "morphogen: warning: %s: %s, so the image is one colour\n",
                     f.raw.c_str(), flat->c_str());
    writeColourMapped(f.out, ColourMapRows(state, chemical, spec, session.edges), f.bitDepth);
    std::printf("%s\n", f.out.c_str());
}

} // namespace

void addColourCommand(CLI::App& app) {
    auto flags = std::make_shared<ColourFlags>();
    CLI::App* cmd = app.add_subcommand(
        "colour", "Re-colour a raw state (render --out FILE.exr) into a PNG/TIFF without "
                  "re-simulating, with the same colour mapping as render");
    cmd->alias("color");
    cmd->add_option("raw", flags->raw, "the raw .exr (or float .tif) that render wrote")
        ->required();
    cmd->add_option("--out", flags->out, "output image: .png or .tif")->required();
    cmd->add_option("--session", flags->sessionFile,
                    "session JSON with the model and colour map (default: the raw file's name "
                    "with .json, as render writes it)");
    cmd->add_option("--colormap", flags->colormap, joinNames(colormapNames()));
    cmd->add_option("--chemical", flags->chemical, "chemical to show (default: the session's)");
    cmd->add_option("--levels", flags->levels,
                    "LOW:HIGH window on the min-max normalised value (default: the session's)");
    cmd->add_option("--bit-depth", flags->bitDepth, "8 or 16 bits per channel");
    addGradientFlags(*cmd, flags->gradient);
    cmd->callback([flags] { colour(*flags); });
}

} // namespace morphogen::cli
