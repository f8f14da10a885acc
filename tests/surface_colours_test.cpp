// The colours a surface's textures show: at a scale above 1 the chemical is
// interpolated to the texture's texels and mapped there (so a colour map's
// bands keep their own colours instead of blends of neighbouring texels').

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/base/state.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/textured_surface.hpp"
#include "surface_fixtures.hpp"

using namespace morphogen;

namespace {

// The colour `value` maps to at levels low..high, through a one-texel state.
std::array<float, 3> mapped(const Session& session, int chemical, int chemicals, float value,
                            float low, float high) {
    State one(1, 1, chemicals);
    one.plane(chemical)[0] = value;
    const ColourMapRows rows(one, chemical, colormapOn(session.colormap, session), low, high);
    std::array<float, 3> rgb{};
    rows.row(0, rgb.data());
    return rgb;
}

} // namespace

TEST(SurfaceColours, FineTexelsMapTheInterpolatedChemical) {
    const int n = 4;
    const SurfaceTiles tiles = test::cubeSphereTiles(n, 1.0f);
    const Atlas& atlas = *tiles.atlas;
    Session session = loadPreset("turk_leopard");
    // A narrow window, as Witkin-Kass's presets use for sharp-edged cells:
    // the map is far from linear in the chemical, so blending the atlas
    // texels' colours would draw soft steps where mapping draws an edge.
    session.colormap.levels = {0.45f, 0.55f};
    const ReactionModel& model = session.outputModel();
    const int chemicals = int(model.chemicals().size());
    const int chemical = colormapChemical(session.colormap, model);
    State state(atlas.width(), atlas.height(), chemicals);
    const std::vector<float> field = test::fieldOnTexels(
        tiles, [](const Eigen::Vector3f& p) { return std::sin(4.0f * p.x()) + p.y(); });
    std::copy(field.begin(), field.end(), state.plane(chemical));
    float low = 1e9f, high = -1e9f;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            low = std::min(low, field[i]);
            high = std::max(high, field[i]);
        }

    const SurfaceColours c = surfaceColours(state, session, atlas);
    ASSERT_TRUE(c.displayAtlas);
    const DisplayAtlas& d = *c.displayAtlas;
    const int s = d.scale();
    ASSERT_EQ(s, 4);
    ASSERT_EQ(c.display.size(), d.texelCount());
    double worst = 0, worstBlend = 0;
    int checked = 0;
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int v = 0; v < n * s; ++v)
            for (int u = 0; u < n * s; ++u) {
                const double x = (u + 0.5) / s - 0.5, y = (v + 0.5) / s - 0.5;
                const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
                if (x0 < 0 || y0 < 0 || x0 + 1 >= n || y0 + 1 >= n)
                    continue; // the footprint crosses an edge: the gutter's business
                const double fx = x - x0, fy = y - y0;
                const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
                double value = 0;
                std::array<double, 3> blend{};
                for (int k = 0; k < 4; ++k) {
                    const std::uint32_t cell = atlas.tileCell(t, x0 + (k & 1), y0 + (k >> 1));
                    value += w[k] * field[cell];
                    for (int ch = 0; ch < 3; ++ch)
                        blend[std::size_t(ch)] += w[k] * c.colours[cell][std::size_t(ch)];
                }
                const std::array<float, 3> want =
                    mapped(session, chemical, chemicals, float(value), low, high);
                const std::array<int, 2> xy = d.texel(t, u, v);
                const auto& got = c.display[std::size_t(xy[1]) * d.width() + xy[0]];
                ASSERT_EQ(got[3], 255);
                for (int ch = 0; ch < 3; ++ch) {
                    worst = std::max(
                        worst, std::abs(got[std::size_t(ch)] - 255.0 * want[std::size_t(ch)]));
                    worstBlend = std::max(worstBlend,
                                          std::abs(got[std::size_t(ch)] - blend[std::size_t(ch)]));
                }
                ++checked;
            }
    EXPECT_GT(checked, atlas.tileCount() * (n - 1) * (n - 1) * s * s / 2);
    // 8-bit rounding of both, and float sums of the interpolation.
    EXPECT_LE(worst, 1.01);
    // Blending the atlas texels' colours instead differs at the window's
    // edges (the check can fail).
    EXPECT_GT(worstBlend, 8.0);

    // At scale 1 nothing is mapped twice: the cell colours are padded.
    SurfaceLook atlasTexels;
    atlasTexels.scale = 1;
    const SurfaceColours plain = surfaceColours(state, session, atlas, {}, atlasTexels);
    EXPECT_FALSE(plain.displayAtlas);
    EXPECT_TRUE(plain.display.empty());
    EXPECT_EQ(plain.colours, c.colours);
}
