// Checks on a finished state (core/analysis/result_checks.hpp): what counts
// as flat, and how NaN or infinite cells are described.

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/analysis/result_checks.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"

using namespace morphogen;

namespace {

State filled(int w, int h, int channels, float value) {
    State s(w, h, channels);
    for (int c = 0; c < channels; ++c)
        std::fill(s.plane(c), s.plane(c) + s.cellCount(), value);
    return s;
}

} // namespace

TEST(ResultChecks, PlaneRangeSkipsAndCountsNonFiniteCells) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float values[] = {0.5f, nan, -2.0f, inf, 3.0f};
    const PlaneRange r = planeRange(values, 5);
    EXPECT_EQ(r.min, -2.0f);
    EXPECT_EQ(r.max, 3.0f);
    EXPECT_EQ(r.nonFinite, 2u);
    EXPECT_EQ(r.firstNonFinite, 1u);
    const float none[] = {nan, nan};
    EXPECT_EQ(planeRange(none, 2).nonFinite, 2u);
    EXPECT_EQ(planeRange(none, 2).min, 0.0f);
}

TEST(ResultChecks, FlatMeansRoundOffNotSmallValues) {
    EXPECT_TRUE(isFlatRange(0.25f, 0.25f));
    EXPECT_TRUE(isFlatRange(0.25f, std::nextafter(std::nextafter(0.25f, 1.0f), 1.0f)));
    EXPECT_TRUE(isFlatRange(1000.0f, 1000.001f)); // relative to the magnitude
    EXPECT_FALSE(isFlatRange(0.0f, 1e-3f));       // a faint pattern is still one
    EXPECT_FALSE(isFlatRange(1000.0f, 1000.1f));
}

TEST(ResultChecks, DescribesAFlatChannelOnly) {
    State s = filled(8, 8, 2, 0.25f);
    s.plane(0)[5] = 0.9f; // u varies, v is flat
    EXPECT_FALSE(describeFlatChannel(s, 0, "u"));
    const auto v = describeFlatChannel(s, 1, "v");
    ASSERT_TRUE(v);
    EXPECT_EQ(*v, "chemical v = 0.25 everywhere");
    EXPECT_FALSE(allChannelsFlat(s));
    EXPECT_TRUE(allChannelsFlat(filled(4, 4, 3, 1.0f)));
    // NaN is not "flat": it is reported as NaN.
    s.plane(1)[3] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(describeFlatChannel(s, 1, "v"));
}

TEST(ResultChecks, DescribesNonFiniteCellsByCountChemicalAndPlace) {
    State s = filled(8, 4, 2, 0.5f);
    EXPECT_FALSE(describeNonFinite(s, {"u", "v"}));
    s.plane(1)[8 * 2 + 3] = std::numeric_limits<float>::quiet_NaN();
    s.plane(1)[31] = -std::numeric_limits<float>::infinity();
    const auto bad = describeNonFinite(s, {"u", "v"});
    ASSERT_TRUE(bad);
    EXPECT_EQ(*bad, "2 of 32 cells of chemical v are NaN or infinite (the first at (3, 2))");
    EXPECT_NE(describeNonFinite(s, {})->find("channel 1"), std::string::npos);
}

TEST(ResultChecks, TheColourMapPaintsWhatIsFlatInOneColour) {
    // The warning and the image agree: a field flat by isFlatRange is one colour.
    State s = filled(4, 1, 1, 0.3f);
    s.plane(0)[2] = std::nextafter(0.3f, 1.0f);
    ColorMapSpec spec;
    spec.name = "viridis";
    const std::vector<float> rgb = applyColormap(s, 0, spec);
    for (std::size_t i = 3; i < rgb.size(); ++i)
        EXPECT_EQ(rgb[i], rgb[i % 3]) << i;
}
