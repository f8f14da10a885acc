#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace morphogen {

// Custom colour gradients ("colormap": {"name": "custom", "colours": [...]},
// `--colours`, `--palette`): 2..kMaxGradientStops sRGB stops, evenly spaced.

// The GPU display pass's uniform array holds this many anchors.
constexpr int kMaxGradientStops = 16;

// The map name a custom gradient goes by ("custom", in any case).
bool isCustomColormapName(std::string_view name);

// "#rgb" or "#rrggbb" (hex digits in either case) as sRGB in [0, 1]; nullopt otherwise.
std::optional<std::array<float, 3>> parseHexColour(std::string_view text);

// "#rrggbb" of a colour (components rounded to 8 bits): what sessions write.
std::string hexColour(const std::array<float, 3>& rgb);

// Checks a gradient's stop count; throws InputError naming `what` and the accepted range.
void checkGradientStops(std::size_t count, const std::string& what);

// "#1b1b1b,#d9a441,#f4e8c1": throws InputError naming `what` (the flag or file)
// and the bad item for a malformed colour or a stop count outside 2..16.
std::vector<std::array<float, 3>> parseGradient(const std::string& list, const std::string& what);

// A palette file: a JSON array of hex strings, or {"colours": [...]}, or text
// with one colour per line or separated by commas or spaces (lines starting
// with "//" are comments). Throws InputError naming the file.
std::vector<std::array<float, 3>> loadPaletteFile(const std::string& path);

} // namespace morphogen
