#include "core/surface/surface_colours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/domain/atlas.hpp"
#include "core/output/colormap.hpp"

namespace morphogen {

SurfaceColours surfaceColours(const State& state, const Session& session, const Atlas& atlas) {
    const int chemical = colormapChemical(session.colormap, session.outputModel());
    const float* plane = state.plane(chemical);
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            low = std::min(low, plane[i]);
            high = std::max(high, plane[i]);
        }
    if (!(high > low))
        high = low + 1.0f; // a flat result (warned about already): one colour
    SurfaceColours c;
    c.height.assign(atlas.cellCount(), 0.0f);
    c.colours.assign(atlas.cellCount(), {0, 0, 0, 255});
    const ColourMapRows rows(state, chemical, session.colormap, low, high);
    std::vector<float> rgb(std::size_t(atlas.width()) * 3);
    for (int y = 0; y < atlas.height(); ++y) {
        rows.row(y, rgb.data());
        for (int x = 0; x < atlas.width(); ++x) {
            const std::uint32_t i = atlas.cellAt(x, y);
            if (!atlas.used(i))
                continue;
            c.height[i] = (plane[i] - low) / (high - low);
            for (int k = 0; k < 3; ++k)
                c.colours[i][k] = std::uint8_t(
                    std::lround(std::clamp(rgb[std::size_t(x) * 3 + k], 0.0f, 1.0f) * 255.0f));
        }
    }
    return c;
}

} // namespace morphogen
