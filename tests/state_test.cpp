// State's RGBA packing: the GPU backend moves chemicals 4t..4t+3 through
// state texture t, so every channel must land in its own texture component
// and come back unchanged.

#include <gtest/gtest.h>

#include "core/base/state.hpp"

using namespace morphogen;

TEST(State, TenChannelsRoundTripThroughThreeRgbaTextures) {
    State state(3, 2, 10);
    for (int c = 0; c < 10; ++c)
        for (std::size_t i = 0; i < state.cellCount(); ++i)
            state.plane(c)[i] = float(c * 100 + int(i));

    State back(3, 2, 10);
    for (int first : {0, 4, 8}) {
        const std::vector<float> rgba = state.toRgba(first);
        ASSERT_EQ(rgba.size(), state.cellCount() * 4);
        for (std::size_t i = 0; i < state.cellCount(); ++i)
            for (int k = 0; k < 4; ++k) {
                // Components past the last channel are zero, not another channel's data.
                const float expected = first + k < 10 ? float((first + k) * 100 + int(i)) : 0.0f;
                EXPECT_EQ(rgba[i * 4 + std::size_t(k)], expected)
                    << "first " << first << " k " << k;
            }
        back.setRgba(rgba, first);
    }
    EXPECT_TRUE(back == state);
}

TEST(State, FromRgbaKeepsOnlyTheChannelsAsked) {
    const std::vector<float> rgba = {1, 2, 3, 4, 5, 6, 7, 8};
    const State two = State::fromRgba(rgba, 2, 1, 2);
    EXPECT_EQ(two.channels(), 2);
    EXPECT_EQ(two.at(0, 1, 0), 5.0f);
    EXPECT_EQ(two.at(1, 1, 0), 6.0f);
}
