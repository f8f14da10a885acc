#include <cmath>

#include <gtest/gtest.h>

#include "core/operators/stability.hpp"
#include "core/sim/stability_check.hpp"
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

// A GPU read-back scans bands of rows; bands top to bottom must name the cell
// the whole-grid scan names: the lowest chemical with a problem, its first
// cell, even when a higher chemical's problem comes in an earlier band.
TEST(Stability, ScanningBandsOfRowsFindsWhatTheWholeGridScanFinds) {
    const ReactionModel& gs = *findModel("gray_scott");
    State st(6, 9, 2);
    st.at(1, 2, 1) = NAN;   // v in the first band
    st.at(0, 4, 7) = 50.0f; // u in the last band: u is scanned first, so it is the answer
    st.at(0, 5, 8) = NAN;   // a later u cell
    const std::optional<std::string> whole = findInsaneValue(st, gs);
    ASSERT_TRUE(whole);
    EXPECT_NE(whole->find("chemical u = 50 at (4, 7)"), std::string::npos) << *whole;
    for (int rows : {1, 2, 4, 9}) {
        InsaneValueScan scan(gs);
        for (int y0 = 0; y0 < st.height(); y0 += rows) {
            const int n = std::min(rows, st.height() - y0);
            State band(st.width(), n, st.channels());
            for (int c = 0; c < st.channels(); ++c)
                for (int y = 0; y < n; ++y)
                    for (int x = 0; x < st.width(); ++x)
                        band.at(c, x, y) = st.at(c, x, y0 + y);
            scan.scanRows(band, y0);
        }
        EXPECT_EQ(scan.result(), whole) << rows << " rows per band";
    }
    InsaneValueScan sane(gs);
    sane.scanRows(State(6, 9, 2), 0);
    EXPECT_FALSE(sane.result());
}

// The engine's session check (the CLI prints its notes; the designer shows them).
TEST(SessionStability, EachCascadeStageIsCheckedAndCappedWithItsOwnDt) {
    Session s = test::smallSession("gs_coral", 16, 40);
    s.stages.resize(2);
    s.stages[0].steps = 20;
    s.stages[1].steps = 20;
    s.stages[1].dt = 5.0f;
    const StabilityReport report = checkSessionStability(s, true);
    EXPECT_FALSE(report.refused);
    EXPECT_TRUE(report.capped);
    ASSERT_EQ(report.notes.size(), 2u);
    EXPECT_FALSE(report.notes[0].warning);
    EXPECT_EQ(report.notes[0].text.rfind("stage 1: explicit step: spectral radius", 0), 0u)
        << report.notes[0].text;
    EXPECT_TRUE(report.notes[1].warning);
    EXPECT_EQ(report.notes[1].text.rfind("stage 2: dt 5 exceeds the explicit stability limit", 0),
              0u)
        << report.notes[1].text;
    ASSERT_TRUE(s.stages[1].dt);
    EXPECT_LT(*s.stages[1].dt, 5.0f);
    EXPECT_FALSE(s.stages[0].dt);
    // The capped session passes.
    Session again = s;
    const StabilityReport second = checkSessionStability(again, false);
    EXPECT_FALSE(second.capped);
    EXPECT_TRUE(second.notes.empty());
    EXPECT_EQ(*again.stages[1].dt, *s.stages[1].dt);
}

TEST(SessionStability, AnOperatorGrowingForEveryDtIsRefused) {
    Session s = test::smallSession("gs_coral", 16, 10);
    s.diffusion.type = DiffusionType::Generalized;
    s.diffusion.generalized = {{"u", "d"}, {"v", "d"}};
    s.diffusion.stabilize = false;
    const StabilityReport report = checkSessionStability(s, false);
    ASSERT_TRUE(report.refused);
    EXPECT_NE(report.refused->find("grow for every explicit time step"), std::string::npos);
    s.diffusion.stabilize = true;
    EXPECT_FALSE(checkSessionStability(s, false).refused);
}

// A param map of a diffusion rate: the step must be stable where the map is
// fastest. Before, the check used the session's own rate and a Du map up to 3
// (the session's 0.21) blew up at the session's dt.
TEST(SessionStability, MappedDiffusionRatesAreCheckedAtTheirLargest) {
    Session s = test::smallSession("gs_coral", 32, 200);
    s.paramMaps["Du"] = {ParamMapSpec::Field::LinearX, 0.2f, 3.0f};
    const float before = s.dt;
    const StabilityReport report = checkSessionStability(s, true);
    EXPECT_FALSE(report.refused);
    EXPECT_TRUE(report.capped);
    EXPECT_LT(s.dt, before);
    // 5-point diffusion at rate 3 on unit cells: dt <= 2 / (8 * 3).
    EXPECT_LE(s.dt, 2.0f / 24.0f);
    bool named = false;
    for (const StabilityNote& note : report.notes)
        named = named || note.text.find("Du 3") != std::string::npos;
    EXPECT_TRUE(named);
    const State end = test::runCpu(s);
    for (int c = 0; c < end.channels(); ++c)
        for (std::size_t i = 0; i < end.cellCount(); ++i)
            ASSERT_TRUE(std::isfinite(end.plane(c)[i]));
    // A map that stays at or below the session's rate changes nothing.
    Session slow = test::smallSession("gs_coral", 32, 200);
    slow.paramMaps["Du"] = {ParamMapSpec::Field::LinearX, 0.05f, 0.2f};
    EXPECT_FALSE(checkSessionStability(slow, false).capped);
}
