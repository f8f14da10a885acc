// Diffusion operators on the CPU reference backend: anisotropic spreading,
// conservation with a diffusion map, the semi-implicit solve, coarse-to-fine.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/analysis/pattern_stats.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// Witkin-Kass with k = b = 0 is pure diffusion of both morphogens.
Session pureAnisotropic(float theta, float a1, float a2, int size) {
    Session s = test::smallSession("gs_coral", size, 0);
    s.model = "witkin_kass";
    s.params = {{"k", 0.0f}, {"b", 0.0f}, {"Dp", 1.0f}, {"Dm", 1.0f}};
    s.dt = 0.05f;
    s.init = s.reactionModel().defaultInit(); // noise in [-1, 1]
    s.diffusion.type = DiffusionType::Anisotropic;
    s.diffusion.anisotropic["p"] = {theta, a1, a2};
    s.diffusion.anisotropic["m"] = {theta, a1, a2};
    return s;
}

struct Moments {
    double mass = 0, xx = 0, yy = 0, xy = 0; // display coordinates (y up)
};

Moments moments(const State& st, int chemical) {
    Moments m;
    const double cx = st.width() / 2.0, cy = st.height() / 2.0;
    for (int y = 0; y < st.height(); ++y)
        for (int x = 0; x < st.width(); ++x) {
            const double v = st.at(chemical, x, y), dx = x - cx, dy = -(y - cy);
            m.mass += v;
            m.xx += v * dx * dx;
            m.yy += v * dy * dy;
            m.xy += v * dx * dy;
        }
    return m;
}

State pointAtCentre(const Session& s) {
    State st(s.width, s.height, 2);
    st.at(0, s.width / 2, s.height / 2) = 1000.0f;
    return st;
}

} // namespace

TEST(AnisotropicDiffusion, APointSpreadsAlongTheta) {
    for (float theta : {0.0f, 30.0f, 90.0f, 135.0f}) {
        SCOPED_TRACE(theta);
        const Session s = pureAnisotropic(theta, 2.0f, 0.5f, 64);
        CpuSimulator sim(s);
        sim.setState(pointAtCentre(s));
        sim.run(100);
        const Moments m = moments(sim.state(), 0);
        // The covariance's principal axis is the direction of fastest spread.
        const double axis = 0.5 * std::atan2(2 * m.xy, m.xx - m.yy) * 180.0 / 3.14159265358979;
        double error = std::fmod(std::fabs(axis - theta), 180.0);
        error = std::min(error, 180.0 - error);
        EXPECT_LT(error, 1.0) << "principal axis " << axis;
        // Variance along theta grows at 2 * a1^2 * t, across at 2 * a2^2 * t.
        const double t = 100 * s.dt;
        const double c = std::cos(theta * 3.14159265358979 / 180),
                     sn = std::sin(theta * 3.14159265358979 / 180);
        const double along = (m.xx * c * c + 2 * m.xy * c * sn + m.yy * sn * sn) / m.mass;
        const double across = (m.xx * sn * sn - 2 * m.xy * c * sn + m.yy * c * c) / m.mass;
        EXPECT_NEAR(along, 2 * 4.0 * t, 0.05 * 2 * 4.0 * t);
        EXPECT_NEAR(across, 2 * 0.25 * t, 0.25 * 2 * 0.25 * t);
        EXPECT_NEAR(m.mass, 1000.0, 1e-2);
    }
}

TEST(AnisotropicDiffusion, DiffusionMapConservesMassOnAPeriodicGrid) {
    for (OrientationField::Type type :
         {OrientationField::Type::Radial, OrientationField::Type::Spiral,
          OrientationField::Type::Vortex}) {
        SCOPED_TRACE(toString(type));
        Session s = pureAnisotropic(0.0f, 1.5f, 0.5f, 48);
        DiffusionMapSpec map;
        map.orientation.type = type;
        map.orientation.angle = 40.0f;
        map.scaleMin = 0.5f;
        s.diffusion.map = map;
        ASSERT_EQ(compileDiffusion(s).form, DiffusionOperator::Form::TensorMap);
        CpuSimulator sim(s);
        State st = makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 7);
        double before = 0;
        for (std::size_t i = 0; i < st.cellCount(); ++i)
            before += st.plane(0)[i];
        sim.setState(st);
        sim.run(200);
        double after = 0;
        for (std::size_t i = 0; i < st.cellCount(); ++i)
            after += sim.state().plane(0)[i];
        // The field really moved (noise smoothed), and the sum did not.
        EXPECT_LT(spectrumStats(sim.state(), 0).variance, 0.5 * spectrumStats(st, 0).variance);
        std::printf("%s map: sum before %.6f, after %.6f\n", toString(type).c_str(), before, after);
        // Float round-off only: 200 steps of ~10 additions per cell.
        EXPECT_NEAR(after, before, 1e-3);
    }
}

TEST(SemiImplicit, JacobiResidualShrinksWithSweeps) {
    Session s = test::smallSession("gs_coral", 64, 5);
    s.integrator = Integrator::SemiImplicit;
    s.dt = 3.0f; // ~2.5x the explicit limit
    double previous = 1e30;
    for (int sweeps : {2, 8, 32}) {
        s.relaxationPasses = sweeps;
        CpuSimulator sim(s);
        sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 1));
        sim.run(s.steps);
        const double residual = sim.lastSolveResidual();
        std::printf("semi-implicit dt 3, %d sweeps: residual %.3g\n", sweeps, residual);
        EXPECT_LT(residual, previous);
        previous = residual;
    }
    EXPECT_LT(previous, 1e-5);
}

TEST(SemiImplicit, StepsBeyondTheExplicitLimitMakeTheSamePattern) {
    // Explicit at its default dt vs semi-implicit at 3x the explicit limit,
    // same simulated time: both form the coral labyrinth at the same scale.
    Session explicitRun = test::smallSession("gs_coral", 96, 4000);
    const double limit = *explicitStability(compileDiffusion(explicitRun), 96, 96, 0.9).maxStableDt;
    Session implicitRun = explicitRun;
    implicitRun.integrator = Integrator::SemiImplicit;
    implicitRun.dt = float(3 * limit);
    implicitRun.steps = int(std::lround(4000 * 0.9 / implicitRun.dt));
    const SpectrumStats e = spectrumStats(test::runCpu(explicitRun), 1);
    const SpectrumStats i = spectrumStats(test::runCpu(implicitRun), 1);
    std::printf(
        "explicit: wavelength %.2f var %.3g; semi-implicit dt %.2f: wavelength %.2f var %.3g\n",
        e.dominantWavelength, e.variance, implicitRun.dt, i.dominantWavelength, i.variance);
    EXPECT_GT(i.variance, 0.5 * e.variance);
    EXPECT_NEAR(i.dominantWavelength, e.dominantWavelength, 0.25 * e.dominantWavelength);
    EXPECT_LT(i.nyquistFraction, 0.05);
}

TEST(CoarseToFine, ACoarseLevelGrowsThePatternAtTheFineScale) {
    // Run only the coarse level (the fine level gets 0 steps): the coarse
    // pattern, resampled to the final grid, must already have the flat
    // run's wavelength in final cells, i.e. half of it in coarse cells.
    Session s = test::smallSession("turk_small_spots", 128, 0);
    applySchedule(s, {{64, 64, 0}, {128, 128, 0}});
    s.schedule[0].steps = 2500;
    s.steps = 2500;
    s.params["Da"] = 4.0f; // a wavelength of ~14 cells at 128, ~7 at 64
    s.params["Db"] = 1.0f;
    s.dt = 0.045f;
    const RunResult c2f = runSession(
        s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, RunOptions{});
    Session flat = s;
    flat.schedule.clear();
    flat.steps = 2500;
    const double wc = spectrumStats(c2f.state, 1).dominantWavelength;
    const double wf = spectrumStats(test::runCpu(flat), 1).dominantWavelength;
    std::printf("coarse level only: wavelength %.2f (final cells); flat %.2f\n", wc, wf);
    EXPECT_NEAR(wc, wf, 0.2 * wf);
}

TEST(CoarseToFine, LevelsRunInOrderAndKeepThePatternScale) {
    Session s = test::smallSession("gs_coral", 128, 0);
    s.schedule = {{64, 64, 1500}, {128, 128, 1000}};
    s.steps = 2500;
    std::vector<int> sizes;
    const RunResult r = runSession(
        s,
        [&](const Session& level) -> std::unique_ptr<Simulator> {
            sizes.push_back(level.width);
            EXPECT_DOUBLE_EQ(level.gridSpacing, 128.0 / level.width);
            return std::make_unique<CpuSimulator>(level);
        },
        RunOptions{});
    EXPECT_EQ(sizes, (std::vector<int>{64, 128}));
    EXPECT_EQ(r.stepsDone, 2500);
    ASSERT_EQ(r.state.width(), 128);
    // Flat at 128 for the same steps, for comparison.
    Session flat = test::smallSession("gs_coral", 128, 2500);
    const SpectrumStats c = spectrumStats(r.state, 1), f = spectrumStats(test::runCpu(flat), 1);
    std::printf("coarse-to-fine wavelength %.2f, flat %.2f\n", c.dominantWavelength,
                f.dominantWavelength);
    EXPECT_NEAR(c.dominantWavelength, f.dominantWavelength, 0.3 * f.dominantWavelength);
    EXPECT_LT(c.nyquistFraction, 0.05);
}
