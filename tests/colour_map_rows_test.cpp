// ColourMapRows::rowRgba8, the designer's per-frame colours, against row()
// rounded as the image writer rounds it.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/image_io.hpp"
#include "core/models/initial_condition.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

State grown(const Session& s, int steps) {
    CpuSimulator sim(s);
    sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    sim.run(steps);
    return sim.state();
}

// The largest channel difference between rowRgba8 and row() rounded, and how
// many channels differ; alpha must be 255.
std::pair<int, int> compareRows(const ColourMapRows& rows) {
    const std::size_t w = std::size_t(rows.width());
    std::vector<float> rgb(w * 3);
    std::vector<std::uint8_t> rgba(w * 4);
    int worst = 0, differing = 0;
    for (int y = 0; y < rows.height(); ++y) {
        rows.row(y, rgb.data());
        rows.rowRgba8(y, rgba.data());
        for (std::size_t x = 0; x < w; ++x) {
            EXPECT_EQ(rgba[x * 4 + 3], 255);
            for (std::size_t k = 0; k < 3; ++k) {
                const int d = std::abs(int(rgba[x * 4 + k]) - int(toUnorm8(rgb[x * 3 + k])));
                worst = std::max(worst, d);
                differing += d != 0;
            }
        }
    }
    return {worst, differing};
}

} // namespace

TEST(ColourMapRows, ScreenRowsAreWithinOneStepOfTheWritersForEveryMap) {
    Session s = test::smallSession("gs_coral", 40, 0);
    State state = grown(s, 300);
    // Non-finite cells are shown at the low end by both.
    state.at(1, 3, 4) = std::numeric_limits<float>::quiet_NaN();
    state.at(1, 9, 2) = std::numeric_limits<float>::infinity();
    for (const std::string& name : colormapNames()) {
        if (name == "custom" || name == "watercolour")
            continue;
        for (const std::array<float, 2> levels : {std::array<float, 2>{0.0f, 1.0f}, {0.2f, 0.7f}}) {
            SCOPED_TRACE(name + " levels " + std::to_string(levels[0]));
            ColorMapSpec spec;
            spec.name = name;
            spec.levels = levels;
            spec.low = {0.1f, 0.3f, 0.05f};
            const ColourMapRows rows(state, 1, spec);
            const auto [worst, differing] = compareRows(rows);
            EXPECT_LE(worst, 1);
            // The table rounds t, so a few channels may step; most must not.
            EXPECT_LT(differing, int(state.cellCount() * 3 / 20));
        }
    }
}

TEST(ColourMapRows, ScreenRowsOfACustomGradientAndAFlatField) {
    Session s = test::smallSession("gs_coral", 24, 0);
    ColorMapSpec spec;
    spec.name = "custom";
    spec.colours = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    EXPECT_LE(compareRows(ColourMapRows(grown(s, 200), 1, spec)).first, 1);
    State flat(24, 24, 2);
    std::fill(flat.plane(0), flat.plane(0) + flat.cellCount(), 0.75f);
    spec.name = "magma";
    EXPECT_EQ(compareRows(ColourMapRows(flat, 0, spec)).first, 0);
}

TEST(ColourMapRows, WatercolourScreenRowsAreTheWritersExactly) {
    // Made-up amounts in the model's seven planes (water, pigments, paper):
    // smooth waves, so there are washes, their edges and dry paper.
    State state(48, 40, 7);
    for (int c = 0; c < state.channels(); ++c)
        for (int y = 0; y < state.height(); ++y)
            for (int x = 0; x < state.width(); ++x)
                state.at(c, x, y) = std::max(
                    0.0f, std::sin(0.21f * float(x * (c + 1)) + 0.13f * float(y) + float(c)));
    ColorMapSpec spec;
    spec.name = "watercolour";
    const auto [worst, differing] = compareRows(ColourMapRows(state, 0, spec));
    EXPECT_EQ(worst, 0);
    EXPECT_EQ(differing, 0);
}
