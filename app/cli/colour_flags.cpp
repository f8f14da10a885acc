#include "cli/colour_flags.hpp"

#include <cstdlib>

#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/session/gradient.hpp"

namespace morphogen::cli {

void addGradientFlags(CLI::App& cmd, GradientFlags& flags) {
    cmd.add_option("--colours,--colors", flags.colours,
                   "custom gradient: 2 to 16 evenly spaced stops, #rgb or #rrggbb, comma "
                   "separated (e.g. '#1b1b1b,#d9a441,#f4e8c1'); the map becomes 'custom'");
    cmd.add_option("--palette", flags.palette,
                   "custom gradient from a file: a JSON array of hex colours (or {\"colours\": "
                   "[...]}), or text with one colour per line");
}

void applyGradientFlags(const GradientFlags& flags, const std::string& colormapFlag,
                        ColorMapSpec& spec) {
    if (!flags.colours.empty() && !flags.palette.empty())
        throw InputError("--colours and --palette are exclusive: give one");
    const bool stops = !flags.colours.empty() || !flags.palette.empty();
    const bool otherMap = !colormapFlag.empty() && !isCustomColormapName(colormapFlag);
    if (stops && otherMap)
        throw InputError(std::string(flags.colours.empty() ? "--palette" : "--colours") +
                         " makes a custom map; --colormap '" + colormapFlag +
                         "' names another: drop one");
    if (stops) {
        spec.colours = flags.colours.empty() ? loadPaletteFile(flags.palette)
                                             : parseGradient(flags.colours, "--colours");
        spec.name = "custom";
    } else if (otherMap) {
        spec.colours.clear(); // a session's stops belong to its custom map only
    }
    spec.name = canonicalColormapName(spec.name);
    colormapAnchors(spec);
}

std::array<float, 2> parseLevelsFlag(const std::string& flag, const std::string& text) {
    const std::size_t colon = text.find(':');
    const std::string a = text.substr(0, colon);
    const std::string b = colon == std::string::npos ? "" : text.substr(colon + 1);
    char* end0 = nullptr;
    char* end1 = nullptr;
    const float low = std::strtof(a.c_str(), &end0), high = std::strtof(b.c_str(), &end1);
    if (colon == std::string::npos || a.empty() || b.empty() || *end0 || *end1 ||
        !(low >= 0.0f && low < high && high <= 1.0f))
        throw InputError(flag + " '" + text +
                         "' is not LOW:HIGH with 0 <= LOW < HIGH <= 1 (e.g. 0.3:0.5)");
    return {low, high};
}

} // namespace morphogen::cli
