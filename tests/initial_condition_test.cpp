#include <gtest/gtest.h>

#include "core/models/initial_condition.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {
State initialOf(const Session& s) {
    return makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
}
} // namespace

TEST(InitialCondition, SameSeedSameStateOtherSeedOtherState) {
    Session s = test::smallSession("mcgraw_turing", 32, 0);
    const State a = initialOf(s), b = initialOf(s);
    EXPECT_TRUE(a == b);
    s.seed += 1;
    EXPECT_FALSE(a == initialOf(s));
}

TEST(InitialCondition, NoiseStaysInItsRange) {
    const Session s = test::smallSession("mcgraw_turing", 64, 0);
    const State st = initialOf(s);
    float lo = 1e9f, hi = -1e9f;
    for (std::size_t i = 0; i < st.cellCount(); ++i) {
        lo = std::min(lo, st.plane(0)[i]);
        hi = std::max(hi, st.plane(0)[i]);
    }
    // u = 4 + U(-2, 2): the extremes of 4096 draws come close to both ends.
    EXPECT_GE(lo, 2.0f);
    EXPECT_LT(hi, 6.0f);
    EXPECT_LT(lo, 2.1f);
    EXPECT_GT(hi, 5.9f);
}

TEST(InitialCondition, CentreSquareMarksTheCentreOnly) {
    Session s = test::smallSession("gs_mcgraw_square", 40, 0);
    s.init.noise.clear();
    s.init.squareFraction = 0.25f; // a 10x10 square at 15..24
    const State st = initialOf(s);
    EXPECT_FLOAT_EQ(st.at(0, 20, 20), 0.5f);
    EXPECT_FLOAT_EQ(st.at(1, 15, 15), 0.25f);
    EXPECT_FLOAT_EQ(st.at(1, 24, 24), 0.25f);
    EXPECT_FLOAT_EQ(st.at(0, 14, 20), 1.0f);
    EXPECT_FLOAT_EQ(st.at(1, 25, 20), 0.0f);
}

TEST(InitialCondition, SeedSpotsCoverRoughlyTheExpectedArea) {
    Session s = test::smallSession("gs_coral", 128, 0);
    s.init.noise.clear();
    s.init.spotCount = 5;
    s.init.spotRadius = 3.0f;
    const State st = initialOf(s);
    int marked = 0;
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        marked += st.plane(1)[i] == 0.25f;
    // 5 discs of radius 3 hold 29 cells each; overlaps can only reduce it.
    EXPECT_GT(marked, 29);
    EXPECT_LE(marked, 5 * 29);
}

TEST(InitialCondition, TurkBetaIsMeanPlusMinusNoise) {
    Session s = test::smallSession("turk_irregular_spots", 64, 0);
    const State st = initialOf(s);
    const float mean = s.params.at("beta_mean"), noise = s.params.at("beta_noise");
    double sum = 0;
    for (std::size_t i = 0; i < st.cellCount(); ++i) {
        const float b = st.plane(2)[i];
        EXPECT_GE(b, mean - noise);
        EXPECT_LE(b, mean + noise);
        sum += b;
    }
    EXPECT_NEAR(sum / double(st.cellCount()), mean, 0.1);
}

TEST(InitialCondition, JitteredGridPlacesOneDiscPerDiamondLatticePoint) {
    Session s = test::smallSession("gs_coral", 64, 0);
    s.init = InitialCondition{};
    s.init.type = InitialCondition::Type::JitteredGrid;
    s.init.base = {{"u", 0.0f}};
    s.init.inside = {{"u", 1.0f}};
    s.init.spacing = 16.0f;
    s.init.spotRadius = 1.0f; // a plus sign of 5 cells
    s.init.jitter = 0.0f;
    const State lattice = initialOf(s);
    // 4 columns x 8 rows (rows spacing / 2 apart): 32 discs of 5 cells.
    double marked = 0;
    for (std::size_t i = 0; i < lattice.cellCount(); ++i)
        marked += lattice.plane(0)[i];
    EXPECT_EQ(marked, 32 * 5);
    // Every other row is shifted by half a spacing: a diamond lattice.
    EXPECT_EQ(lattice.at(0, 0, 4), 1.0f);
    EXPECT_EQ(lattice.at(0, 8, 12), 1.0f);
    EXPECT_EQ(lattice.at(0, 8, 4), 0.0f);
    s.init.jitter = 0.3f;
    const State jittered = initialOf(s);
    EXPECT_FALSE(jittered == lattice);
    EXPECT_TRUE(jittered == initialOf(s)); // same seed, same jitter
}
