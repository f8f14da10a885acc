#include <cmath>

#include <gtest/gtest.h>

#include "core/operators/stability.hpp"
#include "test_support.hpp"

using namespace morphogen;

TEST(Stability, DiffusionLimitFollowsTheStencilSymbol) {
    EXPECT_FLOAT_EQ(stableDiffusionDt(Stencil::FivePoint, 1.0f), 0.25f);
    EXPECT_FLOAT_EQ(stableDiffusionDt(Stencil::NinePoint, 1.0f), 0.375f);
    EXPECT_TRUE(std::isinf(stableDiffusionDt(Stencil::FivePoint, 0.0f)));
}

TEST(Stability, SuggestedDtIsBelowTheFailedOneAndTheLimit) {
    Session s = test::smallSession("mcgraw_turing", 16, 1);
    s.dt = 0.1f;
    const float dt = suggestDt(s);
    EXPECT_LT(dt, 0.1f);
    EXPECT_LE(dt, stableDiffusionDt(s.diffusion.stencil, 8.0f));
}

TEST(Stability, InsaneValuesAreFoundAndNamed) {
    const ReactionModel& gs = *findModel("gray_scott");
    State st(8, 8, 2);
    EXPECT_FALSE(findInsaneValue(st, gs));
    st.at(1, 3, 5) = NAN;
    auto found = findInsaneValue(st, gs);
    ASSERT_TRUE(found);
    EXPECT_NE(found->find("chemical v"), std::string::npos);
    EXPECT_NE(found->find("(3, 5)"), std::string::npos);
    st.at(1, 3, 5) = 0.0f;
    st.at(0, 0, 0) = 50.0f; // u beyond its sane range [-1, 2]
    found = findInsaneValue(st, gs);
    ASSERT_TRUE(found);
    EXPECT_NE(found->find("sane range"), std::string::npos);
}
