// How a session in model units reaches its size (core/sim/segments.hpp):
// substeps below one cell per unit, coarse-to-fine refinement for large
// sizes, the written session as the session's own steps, and the pattern's
// scale in units kept across sizes.

#include <cmath>

#include <gtest/gtest.h>

#include "core/analysis/pattern_stats.hpp"
#include "core/base/errors.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/segments.hpp"
#include "core/sim/session_run.hpp"
#include "core/sim/stability_check.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

Session coralAt(int size) {
    Session s = loadPreset("gs_coral"); // 256 units wide
    resizeSession(s, size, size);
    return s;
}

} // namespace

TEST(Segments, AtItsOwnSizeASessionRunsAsWritten) {
    const Session s = coralAt(256);
    const std::vector<Segment> segments = segmentsOf(s);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_EQ(segments[0].substeps, 1);
    EXPECT_DOUBLE_EQ(segments[0].session.gridSpacing, 1.0);
    EXPECT_EQ(segments[0].session.steps, s.steps);
    EXPECT_EQ(segments[0].session.dt, s.dt);
    EXPECT_TRUE(describePlan(s).empty());
}

TEST(Segments, AFinerGridTakesSubstepsOfTheSameSimulatedTime) {
    Session s = coralAt(384); // under twice the length: no refinement
    const std::vector<Segment> segments = segmentsOf(s);
    ASSERT_EQ(segments.size(), 1u);
    const double h = 256.0 / 384.0;
    EXPECT_DOUBLE_EQ(segments[0].session.gridSpacing, h);
    EXPECT_EQ(segments[0].substeps, 3); // ceil(1 / h^2) = ceil(2.25)
    EXPECT_EQ(segments[0].session.steps, 3 * s.steps);
    EXPECT_FLOAT_EQ(segments[0].session.dt, s.dt / 3);
    EXPECT_FLOAT_EQ(segments[0].sessionDt, s.dt);
    // The semi-implicit step keeps its dt: its diffusion is implicit.
    s.integrator = Integrator::SemiImplicit;
    EXPECT_EQ(segmentsOf(s)[0].substeps, 1);
}

TEST(Segments, ALargeSizeRunsItsStepsAtTheBaseAndRefinesEachDoubling) {
    const Session s = coralAt(1024);
    const std::vector<Segment> segments = segmentsOf(s);
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_EQ(segments[0].session.width, 256);
    EXPECT_FALSE(segments[0].refine);
    EXPECT_EQ(segments[0].session.steps, s.steps);
    EXPECT_EQ(segments[1].session.width, 512);
    EXPECT_EQ(segments[2].session.width, 1024);
    for (std::size_t i = 1; i < 3; ++i) {
        EXPECT_TRUE(segments[i].refine);
        EXPECT_EQ(segments[i].session.steps, refineSteps());
    }
    EXPECT_EQ(segments[1].substeps, 4);
    EXPECT_EQ(segments[2].substeps, 16);
    EXPECT_DOUBLE_EQ(segments[2].session.gridSpacing, 0.25);
    EXPECT_NE(describePlan(s).find("coarse-to-fine"), std::string::npos) << describePlan(s);

    Session direct = s;
    direct.coarseToFine = false;
    const std::vector<Segment> one = segmentsOf(direct);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].substeps, 16);
}

TEST(Segments, ACascadeRunsItsStagesAtTheBaseThenRefinesItsLastStage) {
    Session s = loadPreset("turk_giraffe"); // 128 units wide, two stages
    resizeSession(s, 512, 512);
    const std::vector<Segment> segments = segmentsOf(s);
    ASSERT_EQ(segments.size(), 4u);
    EXPECT_EQ(segments[0].session.width, 128);
    EXPECT_EQ(segments[1].session.width, 128);
    EXPECT_EQ(segments[1].session.model, "meinhardt_stripes");
    EXPECT_TRUE(segments[2].refine);
    EXPECT_EQ(segments[3].session.width, 512);
    EXPECT_EQ(segments[3].session.model, "meinhardt_stripes");
    EXPECT_FALSE(segments[3].freeze); // the frozen cells carry over, resampled
}

TEST(Segments, StepsBeyondTheEngineLimitAreRefusedByName) {
    Session s = coralAt(16384);
    s.coarseToFine = false;
    s.steps = 100000000;
    try {
        segmentsOf(s);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("16384 x 16384"), std::string::npos) << e.what();
    }
}

TEST(Segments, TheWrittenSessionHoldsItsOwnStepsAndReproducesTheRun) {
    Session s = loadPreset("gs_coral");
    s.length = 16;
    s.width = s.height = 32; // base 16, refined at 32
    s.steps = 300;
    const RunResult first = runSession(s, cpu(), RunOptions{});
    EXPECT_EQ(first.stepsDone, 300 + refineSteps());
    EXPECT_EQ(first.completed.steps, 300);
    EXPECT_TRUE(first.completed.schedule.empty());
    EXPECT_DOUBLE_EQ(first.completed.length, 16.0);
    const RunResult again = runSession(first.completed, cpu(), RunOptions{});
    EXPECT_EQ(test::maxAbsDifference(first.state, again.state), 0.0f);
}

TEST(Segments, ASettleCheckEndsTheLastOwnSegmentAndTheRefinementStillRuns) {
    Session s = loadPreset("gs_coral");
    s.length = 16;
    s.width = s.height = 32;
    s.steps = 1000;
    int asked = 0;
    RunOptions options;
    options.settleEvery = 50;
    options.settleAfter = 200;
    options.settled = [&](const State& state) {
        EXPECT_EQ(state.width(), 16); // checked at the base, not while refining
        return ++asked == 3;
    };
    const RunResult r = runSession(s, cpu(), options);
    EXPECT_TRUE(r.settled);
    EXPECT_EQ(r.completed.steps, 300); // checks at 200, 250, 300
    EXPECT_EQ(r.stepsDone, 300 + refineSteps());
    EXPECT_EQ(r.state.width(), 32);
}

// The pattern's scale is in model units: Turing spots on an image 64 units
// across keep their wavelength in units and their count whether the grid has
// one cell per unit, two refined from one, or two run directly with
// substeps. The steps let the spots settle: at 3000 steps the direct run,
// whose finer operator grows the pattern a little slower, still had 5 of 6
// spots forming (measured).
TEST(Segments, TheWavelengthInUnitsIsTheSameAtEverySize) {
    Session s = loadPreset("turk_large_spots");
    s.length = 64;
    s.width = s.height = 64;
    s.steps = 8000;
    const int chemical = s.reactionModel().displayChemical();
    struct Measure {
        double wavelength; // units
        int features;
    };
    auto measure = [&](const Session& run) {
        const State state = runSession(run, cpu(), RunOptions{}).state;
        return Measure{spectrumStats(state, chemical).dominantWavelength * run.cellSize(),
                       featureCount(state, chemical)};
    };
    const Measure own = measure(s);
    Session refined = s;
    resizeSession(refined, 128, 128);
    Session direct = refined;
    direct.coarseToFine = false;
    const Measure r = measure(refined), d = measure(direct);
    std::printf("wavelength in units (features): 64 cells %.2f (%d), 128 refined %.2f (%d), 128 "
                "direct %.2f (%d)\n",
                own.wavelength, own.features, r.wavelength, r.features, d.wavelength, d.features);
    EXPECT_GT(own.features, 10); // a pattern, not noise
    EXPECT_NEAR(r.wavelength, own.wavelength, 0.05 * own.wavelength);
    EXPECT_NEAR(d.wavelength, own.wavelength, 0.05 * own.wavelength);
    EXPECT_NEAR(r.features, own.features, 0.1 * own.features);
    EXPECT_NEAR(d.features, own.features, 0.1 * own.features);
}

// McGraw's rank-4 set (d) grows as 1/h^4 on finer grids: each level takes the
// substeps its own explicit limit needs, so the session's dt is not capped
// for the whole run (it was: a 1024 render of gs_generalized_d ran at 1/64 of
// its dt, its base simulated 1/64 of the time and the maze never grew). The
// base of a large render is then the preset's own run, step for step.
TEST(Segments, AHigherOrderOperatorTakesTheSubstepsItsLevelNeeds) {
    for (int size : {192, 256, 1024}) {
        SCOPED_TRACE(size);
        Session s = loadPreset("gs_generalized_d"); // 128 units wide, dt 0.15
        const Session native = s;
        resizeSession(s, size, size);
        Session checked = s;
        const StabilityReport report = checkSessionStability(checked, false);
        EXPECT_FALSE(report.capped);
        EXPECT_FALSE(report.refused.has_value());
        EXPECT_FLOAT_EQ(checked.dt, native.dt);
        const std::vector<Segment> segments = segmentsOf(s);
        // The session's simulated time at its base: steps x dt unchanged.
        EXPECT_EQ(segments.front().session.steps, segments.front().substeps * native.steps);
        for (const Segment& segment : segments) {
            const double h = segment.session.gridSpacing;
            const Session& level = segment.session;
            const std::optional<double> limit =
                explicitStability(compileDiffusion(level), level.domain(), level.dt).maxStableDt;
            ASSERT_TRUE(limit.has_value());
            EXPECT_LE(level.dt, *limit) << "at h " << h;
            if (h < 1.0) // more than the 1/h^2 of a second-order operator
                EXPECT_GT(segment.substeps, int(std::ceil(1.0 / (h * h))));
            EXPECT_FLOAT_EQ(segment.sessionDt, native.dt);
        }
        if (size == 256)
            EXPECT_EQ(segments.front().session.width, 128); // the base: the preset's own run
    }
    // A second-order set keeps 1/h^2: (a) is the isotropic reference.
    Session a = loadPreset("gs_generalized_a");
    resizeSession(a, 4 * a.width, 4 * a.height);
    const std::vector<Segment> segments = segmentsOf(a);
    ASSERT_EQ(segments.size(), 3u);
    EXPECT_EQ(segments[1].substeps, 4);
    EXPECT_EQ(segments[2].substeps, 16);
}
