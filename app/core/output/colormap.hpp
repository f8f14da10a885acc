#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/session/session.hpp"

namespace morphogen {

// Colour map names accepted by --colormap and "colormap.name".
const std::vector<std::string>& colormapNames();

// The table's spelling of a map ("grey" for "gray"); throws InputError naming
// the accepted maps.
std::string canonicalColormapName(const std::string& name);

// The chemical the colour map shows: spec.chemical, or the model's display chemical.
int colormapChemical(const ColorMapSpec& spec, const ReactionModel& model);

// The map as evenly spaced anchors, interpolated piecewise linearly: grey is
// black to white, two-colour spec.low to spec.high, custom spec.colours
// (InputError without them; other maps ignore them) (what applyColormap and
// the GPU display pass both sample).
std::vector<std::array<float, 3>> colormapAnchors(const ColorMapSpec& spec);

// Most anchors a map has (the GPU display pass's uniform array).
constexpr int kMaxColormapAnchors = 16;

// One chemical, normalised by its own min and max over the grid (de Kleine's
// min-max mapping), windowed by spec.levels, through the named map:
// interleaved RGB in [0, 1].
std::vector<float> applyColormap(const State& state, int chemical, const ColorMapSpec& spec);

} // namespace morphogen
