// Until settled (core/analysis/settle_detector.hpp).

#include <gtest/gtest.h>

#include "core/analysis/settle_detector.hpp"
#include "core/base/random.hpp"

using namespace morphogen;

namespace {

// Spots: a disc per 16x16 block, of radius r, on a 64x64 grid.
State spots(float radius) {
    State s(64, 64, 1);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float dx = float(x % 16) - 7.5f, dy = float(y % 16) - 7.5f;
            s.at(0, x, y) = dx * dx + dy * dy < radius * radius ? 1.0f : 0.0f;
        }
    return s;
}

} // namespace

TEST(SettleDetector, AStillPatternSettlesAfterTheWindow) {
    SettleDetector d(0, true);
    const State s = spots(4);
    EXPECT_FALSE(d.check(s)); // the first check has nothing to compare with
    EXPECT_FALSE(d.check(s));
    EXPECT_FALSE(d.check(s));
    EXPECT_TRUE(d.check(s)); // three stable checks
    EXPECT_EQ(d.features(), 16);
    EXPECT_EQ(d.change(), 0.0);
}

TEST(SettleDetector, AGrowingPatternDoesNotSettle) {
    SettleDetector d(0, true);
    for (int i = 0; i < 8; ++i)
        EXPECT_FALSE(d.check(spots(2.0f + 0.5f * float(i)))) << i;
    EXPECT_GT(d.change(), d.changeTolerance());
}

TEST(SettleDetector, ChaosNeverSettles) {
    SettleDetector d(0, true);
    for (int i = 0; i < 20; ++i) {
        State s(32, 32, 1);
        for (std::size_t k = 0; k < s.cellCount(); ++k)
            s.plane(0)[k] = float(uniform01(9, std::uint64_t(i), k));
        EXPECT_FALSE(d.check(s));
    }
}

TEST(SettleDetector, AFeatureCountThatStillChangesIsNotSettled) {
    SettleDetector d(0, true);
    State s = spots(4);
    d.check(s);
    // Remove one spot per check: the values barely change, the count does.
    for (int k = 0; k < 6; ++k) {
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                s.at(0, 16 * (k % 4) + x, 16 * (k / 4) + y) = 0.0f;
        EXPECT_FALSE(d.check(s)) << k;
    }
}
