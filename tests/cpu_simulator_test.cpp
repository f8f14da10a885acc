// The CPU reference backend: determinism, conservation, edge handling.

#include <cmath>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// Gray-Scott with F = k = 0 and v = 0 is pure diffusion of u.
Session pureDiffusion(EdgeMode edges, Stencil stencil) {
    Session s = test::smallSession("gs_coral", 24, 40);
    s.params["F"] = 0.0f;
    s.params["k"] = 0.0f;
    s.params["Du"] = 0.2f;
    s.edges = edges;
    s.diffusion.stencil = stencil;
    return s;
}

State pointSource(const Session& s, int x, int y) {
    State st(s.width, s.height, 2);
    st.at(0, x, y) = 100.0f;
    return st;
}

double total(const State& st, int c) {
    double sum = 0;
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        sum += st.plane(c)[i];
    return sum;
}

} // namespace

TEST(CpuSimulator, SameSessionSameBits) {
    const Session s = test::smallSession("gs_mitosis", 48, 200);
    EXPECT_TRUE(test::runCpu(s) == test::runCpu(s));
}

TEST(CpuSimulator, DiffusionConservesMassOnBothEdgeModesAndStencils) {
    for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped})
        for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint}) {
            SCOPED_TRACE(toString(edges) + " " + toString(stencil));
            const Session s = pureDiffusion(edges, stencil);
            CpuSimulator sim(s);
            // In a corner, so the mass meets the edges.
            sim.setState(pointSource(s, 0, 0));
            sim.run(s.steps);
            EXPECT_NEAR(total(sim.state(), 0), 100.0, 1e-3);
        }
}

TEST(CpuSimulator, PeriodicDiffusionWrapsAroundClampedDoesNot) {
    Session s = pureDiffusion(EdgeMode::Periodic, Stencil::FivePoint);
    CpuSimulator periodic(s);
    periodic.setState(pointSource(s, 0, 0));
    periodic.run(10);
    // Mass crosses the seam to the far column and row.
    EXPECT_GT(periodic.state().at(0, s.width - 1, 0), 1e-3f);
    EXPECT_FLOAT_EQ(periodic.state().at(0, s.width - 1, 0), periodic.state().at(0, 1, 0));

    s.edges = EdgeMode::Clamped;
    CpuSimulator clamped(s);
    clamped.setState(pointSource(s, 0, 0));
    clamped.run(10);
    EXPECT_LT(clamped.state().at(0, s.width - 1, 0), 1e-12f);
}

TEST(CpuSimulator, NinePointSpreadsMoreIsotropically) {
    // After diffusion from a point, the value at distance d along an axis and
    // along a diagonal should match for an isotropic operator.
    auto anisotropy = [](Stencil stencil) {
        Session s = pureDiffusion(EdgeMode::Periodic, stencil);
        s.width = s.height = 64;
        CpuSimulator sim(s);
        sim.setState(pointSource(s, 32, 32));
        sim.run(60);
        const State st = sim.state();
        const float axis = st.at(0, 32 + 7, 32);         // distance 7
        const float diagonal = st.at(0, 32 + 5, 32 + 5); // distance 7.07
        return std::fabs(axis - diagonal) / axis;
    };
    EXPECT_LT(anisotropy(Stencil::NinePoint), anisotropy(Stencil::FivePoint));
}

TEST(CpuSimulator, ClampHoldsTurksBAtZeroOrAbove) {
    const Session s = test::smallSession("turk_irregular_spots", 48, 1500);
    const State st = test::runCpu(s);
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        ASSERT_GE(st.plane(1)[i], 0.0f);
}

TEST(CpuSimulator, BlowUpIsReportedWithStepAndASmallerDt) {
    Session s = test::smallSession("gs_coral", 32, 400);
    s.dt = 5.0f; // 5 * 8 * 0.2097 > 2: diffusion alone is unstable
    CpuSimulator sim(s);
    sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    RunOptions options;
    options.chunk = 50;
    try {
        runSimulation(sim, s, options);
        FAIL() << "expected a blow-up";
    } catch (const BlowUpError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("blew up between step"), std::string::npos) << message;
        EXPECT_NE(message.find("--dt"), std::string::npos) << message;
        EXPECT_LT(e.suggestedDt(), 2.0f / (8.0f * 0.2097f));
        EXPECT_GT(e.step(), 0);
        EXPECT_LE(e.step(), 400);
    }
}

TEST(CpuSimulator, CancelStopsAfterTheCurrentChunk) {
    Session s = test::smallSession("gs_coral", 32, 1000);
    CpuSimulator sim(s);
    sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    std::atomic<bool> cancel{false};
    RunOptions options;
    options.chunk = 100;
    options.cancel = &cancel;
    options.progress = [&](int done, int) { cancel.store(done >= 300); };
    const RunResult r = runSimulation(sim, s, options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(r.stepsDone, 300);
    EXPECT_EQ(r.state.width(), 32);
}

// run(k) on a plain grid takes its k steps in one parallel region with a
// SpinBarrier between them; one step at a time forks a team per step. Both
// must give the same bits, for an odd and an even k, on a grid large enough
// (65,536 cells and more) to run on several threads.
TEST(CpuSimulator, StepsInOneRegionAreTheStepsOneByOneBitForBit) {
    for (const char* preset : {"gs_coral", "turk_cheetah"}) {
        SCOPED_TRACE(preset);
        Session s = test::smallSession(preset, 256, 0);
        s.edges = EdgeMode::Periodic;
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
        for (int k : {7, 8}) {
            CpuSimulator together(s), oneByOne(s);
            together.setState(start);
            oneByOne.setState(start);
            together.run(k);
            for (int i = 0; i < k; ++i)
                oneByOne.run(1);
            const State a = together.state(), b = oneByOne.state();
            ASSERT_EQ(a.cellCount(), b.cellCount());
            int differing = 0;
            for (int c = 0; c < a.channels(); ++c)
                for (std::size_t i = 0; i < a.cellCount(); ++i)
                    differing += a.plane(c)[i] != b.plane(c)[i];
            EXPECT_EQ(differing, 0) << k << " steps";
            // The steps moved the state (a run that did nothing would match).
            int moved = 0;
            for (std::size_t i = 0; i < a.cellCount(); ++i)
                moved += a.plane(1)[i] != start.plane(1)[i];
            EXPECT_GT(moved, 1000);
        }
    }
}
