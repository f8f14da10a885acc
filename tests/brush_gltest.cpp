// brush_test's checks on the GPU backend, and the two backends agreeing on a
// run with brush strokes between its steps.

#include <cstdio>

#include <gtest/gtest.h>

#include "brush_checks.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory gpu() {
    test::glContext();
    return [](const Session& s) { return std::make_unique<gl::GpuSimulator>(s); };
}

// The strokes a designer session might make, steps between them.
State brushedRun(Simulator& sim, const Session& s) {
    sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    const Domain grid = s.domain();
    auto stroke = [&](BrushMode mode, float x, float y, float r, int chemical, float value) {
        Brush b;
        b.mode = mode;
        b.region = BrushRegion::disc(grid, x, y, r, 0.4f);
        b.chemical = chemical;
        b.value = value;
        b.seed = 3;
        return b;
    };
    sim.run(10);
    sim.applyBrush(stroke(BrushMode::Add, 5.0f, 6.0f, 4.0f, 1, 0.25f));
    sim.run(10);
    sim.applyBrush(stroke(BrushMode::Hold, 30.0f, 20.0f, 5.0f, 0, 0.0f));
    sim.applyBrush(stroke(BrushMode::Randomise, 0.0f, 0.0f, 6.0f, 0, 0.1f));
    sim.run(10);
    Brush paint = stroke(BrushMode::Paint, 20.0f, 12.0f, 7.0f, 0, 0.03f);
    paint.param = "F";
    sim.applyBrush(paint);
    sim.run(10);
    sim.applyBrush(stroke(BrushMode::Set, 15.0f, 3.0f, 3.0f, 0, 0.4f));
    sim.applyBrush(stroke(BrushMode::Release, 30.0f, 20.0f, 5.0f, 0, 0.0f));
    sim.run(10);
    return sim.state();
}

} // namespace

TEST(GpuBrush, ChemicalWritesChangeExactlyTheRegion) {
    test::checkChemicalBrushes(gpu());
}

TEST(GpuBrush, RandomiseIsReproducibleAndLocal) {
    test::checkRandomiseReproducible(gpu());
}

TEST(GpuBrush, HeldCellsStayFixedWhileTheRestEvolves) {
    test::checkHoldAndRelease(gpu());
}

TEST(GpuBrush, PaintedParametersChangeTheDynamicsOnlyInTheRegion) {
    test::checkPaintedParameters(gpu());
}

TEST(GpuBrush, CellParamsAreTheValuesTheStepUses) {
    test::checkCellParams(gpu());
}

TEST(GpuBrush, BadBrushesAreRefused) {
    test::checkBadBrushes(gpu());
}

TEST(GpuBrush, BackendsAgreeOnABrushedRun) {
    test::glContext();
    Session s = test::smallSession("gs_coral", 24, 50);
    s.width = 36;
    CpuSimulator cpu(s);
    gl::GpuSimulator gpu(s);
    const State a = brushedRun(cpu, s), b = brushedRun(gpu, s);
    CpuSimulator unbrushed(s);
    unbrushed.setState(
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    unbrushed.run(50);
    const float brushEffect = test::maxAbsDifference(a, unbrushed.state());
    const float disagreement = test::maxAbsDifference(a, b);
    std::printf("brush effect %.3g, gpu-cpu %.3g\n", brushEffect, disagreement);
    EXPECT_GT(brushEffect, 0.1f); // the strokes did something
    // As GpuCpuAgreement: Gray-Scott after 50 steps, values in [0, 1].
    EXPECT_LT(disagreement, 1e-4f);
}
