#pragma once

#include <string>
#include <vector>

#include "core/session/session.hpp"
#include "core/base/state.hpp"

namespace morphogen {

// Colour map names accepted by --colormap and "colormap.name".
const std::vector<std::string>& colormapNames();

// Throws InputError naming the accepted maps.
void checkColormapName(const std::string& name);

// The chemical the colour map shows: spec.chemical, or the model's display chemical.
int colormapChemical(const ColorMapSpec& spec, const ReactionModel& model);

// One chemical, normalised by its own min and max over the grid (de Kleine's
// min-max mapping), windowed by spec.levels, through the named map:
// interleaved RGB in [0, 1].
std::vector<float> applyColormap(const State& state, int chemical, const ColorMapSpec& spec);

} // namespace morphogen
