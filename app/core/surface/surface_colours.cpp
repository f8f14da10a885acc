#include "core/surface/surface_colours.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/domain/atlas.hpp"
#include "core/models/watercolour.hpp"
#include "core/output/colormap.hpp"

namespace morphogen {

namespace {

// The watercolour map paints the paper; its water is shown as water.
void addWater(const State& state, const Atlas& atlas, SurfaceColours& c) {
    const float* water = state.plane(WatercolourModel::W);
    float deepest = 0.0f;
    c.wetness.assign(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        const float w = std::isfinite(water[i]) ? std::max(water[i], 0.0f) : 0.0f;
        // Smooth from a dry film (no gloss below 0.02) to standing water.
        const float x = std::clamp((w - 0.02f) / (kWetDepth - 0.02f), 0.0f, 1.0f);
        c.wetness[i] = x * x * (3.0f - 2.0f * x);
        c.height[i] = w;
        deepest = std::max(deepest, w);
    }
    c.relief = kWaterRelief * std::min(deepest / kWetDepth, 1.0f);
}

// Every chemical interpolated to the display's texels (the watercolour map
// reads them all), then the map applied there at the atlas's levels.
void mapAtDisplay(const State& state, int chemical, const ColorMapSpec& spec, float low, float high,
                  std::shared_ptr<const DisplayAtlas> display, SurfaceColours& c) {
    State fine(display->width(), display->height(), state.channels());
    std::vector<float> cells(state.cellCount());
    for (int k = 0; k < state.channels(); ++k) {
        std::copy(state.plane(k), state.plane(k) + state.cellCount(), cells.begin());
        const std::vector<float> padded = display->pad(cells, 1);
        std::copy(padded.begin(), padded.end(), fine.plane(k));
    }
    const ColourMapRows rows(fine, chemical, spec, low, high);
    c.display.assign(display->texelCount(), {0, 0, 0, 0});
    std::vector<float> rgb(std::size_t(fine.width()) * 3);
    for (int y = 0; y < fine.height(); ++y) {
        rows.row(y, rgb.data());
        for (int x = 0; x < fine.width(); ++x) {
            const std::size_t p = std::size_t(y) * fine.width() + x;
            if (!display->covered(p))
                continue;
            for (int k = 0; k < 3; ++k)
                c.display[p][std::size_t(k)] = std::uint8_t(
                    std::lround(std::clamp(rgb[std::size_t(x) * 3 + k], 0.0f, 1.0f) * 255.0f));
            c.display[p][3] = 255;
        }
    }
    c.displayAtlas = std::move(display);
}

} // namespace

SurfaceColours surfaceColours(const State& state, const Session& session, const Atlas& atlas,
                              const std::optional<std::pair<float, float>>& levels,
                              const SurfaceLook& look, std::shared_ptr<const DisplayAtlas> reuse) {
    const int chemical = colormapChemical(session.colormap, session.outputModel());
    const float* plane = state.plane(chemical);
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    if (levels) {
        low = levels->first;
        high = levels->second;
    } else {
        for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
            if (atlas.used(i)) {
                low = std::min(low, plane[i]);
                high = std::max(high, plane[i]);
            }
    }
    if (!(high > low))
        high = low + 1.0f; // a flat result (warned about already): one colour
    // The watercolour map accepts only the watercolour model's state (ColourMapRows
    // checks); its relief is the water's height, set by addWater.
    const bool water = isWatercolourMap(session.colormap);
    SurfaceColours c;
    c.height.assign(atlas.cellCount(), 0.0f);
    c.colours.assign(atlas.cellCount(), {0, 0, 0, 255});
    const ColourMapRows rows(state, chemical, colormapOn(session.colormap, session), low, high);
    std::vector<float> rgb(std::size_t(atlas.width()) * 3);
    for (int y = 0; y < atlas.height(); ++y) {
        rows.row(y, rgb.data());
        for (int x = 0; x < atlas.width(); ++x) {
            const std::uint32_t i = atlas.cellAt(x, y);
            if (!atlas.used(i))
                continue;
            if (!water)
                c.height[i] = std::clamp((plane[i] - low) / (high - low), 0.0f, 1.0f);
            for (int k = 0; k < 3; ++k)
                c.colours[i][k] = std::uint8_t(
                    std::lround(std::clamp(rgb[std::size_t(x) * 3 + k], 0.0f, 1.0f) * 255.0f));
        }
    }
    if (water)
        addWater(state, atlas, c);
    const int scale = displayScale(atlas, look);
    if (scale > 1) {
        if (!reuse || reuse->scale() != scale || reuse->gutter() != look.gutter ||
            reuse->tileCount() != atlas.tileCount())
            reuse = std::make_shared<const DisplayAtlas>(atlas, look.gutter, scale);
        mapAtDisplay(state, chemical, colormapOn(session.colormap, session), low, high,
                     std::move(reuse), c);
    }
    return c;
}

} // namespace morphogen
