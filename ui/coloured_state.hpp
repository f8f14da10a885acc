#pragma once

#include <vector>

#include "core/output/colormap.hpp"

namespace morphogen::ui {

// One chemical of a state through a colour map (applyColormap: the image
// writer's colours) as opaque RGBA floats, row 0 first: what a Texture2D of
// the picture uploads (preset thumbnails, the parameter map).
inline std::vector<float> colouredRgba(const State& state, int chemical, const ColorMapSpec& spec,
                                       EdgeMode edges) {
    const std::vector<float> rgb = applyColormap(state, chemical, spec, edges);
    std::vector<float> rgba(rgb.size() / 3 * 4, 1.0f);
    for (std::size_t i = 0; i < rgb.size() / 3; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            rgba[i * 4 + c] = rgb[i * 3 + c];
    return rgba;
}

} // namespace morphogen::ui
