// The watercolour model on the GLSL backend: water (on the paper + gone)
// and each pigment (moving + deposited) are conserved, as on the CPU
// (watercolour_test.cpp); the GPU display paints as the image writer does.
// The GLSL/C++ agreement of the step itself is
// gpu_cpu_agreement_gltest's (every registered model).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/models/initial_condition.hpp"
#include "core/models/watercolour.hpp"
#include "core/output/colormap.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/segments.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/display.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;
using M = WatercolourModel;

TEST(WatercolourGl, ConservesWaterAndPigment) {
    test::glContext();
    for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped}) {
        SCOPED_TRACE(toString(edges));
        Session s = sessionFromJson(nlohmann::json{{"model", "watercolour"}}, "conservation");
        s.width = 48;
        s.height = 40;
        s.edges = edges;
        s.init.inside["p2"] = 0.3f;
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
        gl::GpuSimulator gpu(s);
        gpu.setState(start);
        gpu.run(150); // mid-wash, as on the CPU
        const State end = gpu.state();
        const double water0 = test::planeSum(start, M::W) + test::planeSum(start, M::G);
        const double water1 = test::planeSum(end, M::W) + test::planeSum(end, M::G);
        // As on the CPU: float rounding only (the GPU may fuse multiply-adds,
        // which changes rounding, not totals), 1e-5 relative over 150 steps.
        EXPECT_NEAR(water1 / water0, 1.0, 1e-5);
        for (int k = 0; k < 2; ++k) {
            const double p0 = test::planeSum(start, M::P1 + k) + test::planeSum(start, M::D1 + k);
            const double p1 = test::planeSum(end, M::P1 + k) + test::planeSum(end, M::D1 + k);
            EXPECT_NEAR(p1 / p0, 1.0, 1e-5) << "pigment " << k + 1;
        }
        EXPECT_GT(test::planeSum(end, M::G), 0.3 * water0);
        std::printf("gpu %s: water %.9f -> %.9f\n", toString(edges).c_str(), water0, water1);
    }
}

// Drops on a tilted canvas (gravity.hpp): the GLSL step runs the 3x3 kernels
// with the downhill drift as the CPU does, and the drops have moved.
TEST(WatercolourGl, DropsRunDownhillAsOnTheCpu) {
    test::glContext();
    nlohmann::json j = {{"model", "watercolour"},
                        {"size", 48},
                        {"length", 48},
                        {"coarse_to_fine", false},
                        {"edges", "clamped"},
                        {"dt", 0.5},
                        {"gravity", {{"angle", 290}, {"strength", 0.4}}}};
    Session s = sessionFromJson(j, "drops");
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
    gl::GpuSimulator gpu(s);
    CpuSimulator cpu(s);
    gpu.setState(start);
    cpu.setState(start);
    gpu.run(120);
    cpu.run(120);
    const State a = gpu.state(), b = cpu.state();
    float worst = 0, moved = 0;
    for (int c = 0; c < a.channels(); ++c)
        for (std::size_t i = 0; i < a.cellCount(); ++i) {
            worst = std::max(worst, std::fabs(a.plane(c)[i] - b.plane(c)[i]));
            moved = std::max(moved, std::fabs(b.plane(c)[i] - start.plane(c)[i]));
        }
    std::printf("drops: gpu vs cpu %.3g, largest change %.3g\n", worst, moved);
    // Float rounding of 120 steps (the GPU may fuse multiply-adds); a missing
    // or mirrored drift differs by the drops' whole height (~1).
    EXPECT_LT(worst, 1e-4f);
    EXPECT_GT(moved, 0.5f);
}

// Drops on a model (AtlasDrift, the ATLAS_DRIFT variant): a wet dab on the
// sample sphere runs down under gravity on both backends alike, over the whole
// atlas and over a set of active tiles (localized steps), and the GPU keeps the
// area-weighted water (on the surface + gone) constant. With and without a
// carrier (the DRIFT_CARRIER variant: the water's mobility scales the drift).
void dropsRunDownAModelAsOnTheCpu(const std::string& carrier) {
    SCOPED_TRACE(carrier.empty() ? "no carrier" : "carrier " + carrier);
    test::glContext();
    nlohmann::json j = {{"model", "watercolour"},
                        {"length", 40},
                        {"dt", 0.5},
                        {"init", {{"type", "noise"}}},
                        {"params", {{"paper_grain", 0}, {"paper_fibres", 0}}},
                        {"gravity", {{"strength", 0.5}, {"direction", {0.3, -1, 0.2}}}},
                        {"surface", {{"mesh", "sample:sphere"}, {"tiles", 150}, {"tile_size", 4}}}};
    if (!carrier.empty())
        j["gravity"]["carrier"] = carrier;
    Session s = sessionFromJson(j, "drops on a model");
    (void)setUpSurface(s);
    ASSERT_TRUE(s.atlasWeights && s.atlasWeights->drift);
    // The simulators step at the session's dt: the substep a run would take.
    s.dt /= float(atlasSubsteps(s));
    State start = makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 3);
    // A wet dab: water and pigment on the texels of the upper cap.
    const Atlas& atlas = *s.atlas;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i) && (*s.atlasPositions)[i][1] > 0.7f) {
            start.plane(M::W)[i] = 2.0f;
            start.plane(M::P1)[i] = 0.5f;
        }
    const auto water = [&](const State& st) {
        double sum = 0;
        for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
            if (atlas.used(i))
                sum += double(s.atlasWeights->area[i]) * (st.plane(M::W)[i] + st.plane(M::G)[i]);
        return sum;
    };
    const auto run = [&](auto simulator, const std::vector<int>& tiles) {
        simulator.setState(start);
        if (!tiles.empty())
            simulator.setActiveTiles(tiles);
        simulator.run(80);
        return simulator.state();
    };
    std::vector<int> some;
    for (int t = 0; t < atlas.tileCount(); t += 3)
        some.push_back(t);
    for (const std::vector<int>& tiles : {std::vector<int>{}, some}) {
        SCOPED_TRACE(tiles.empty() ? "whole atlas" : "active tiles");
        const State cpu = run(CpuSimulator(s), tiles);
        const State gpu = run(gl::GpuSimulator(s), tiles);
        // Float rounding of 80 steps (the GPU may fuse multiply-adds); a
        // missing or mirrored drift differs by the dab's height (~2).
        EXPECT_LT(test::maxAbsDifference(cpu, gpu), 1e-4f);
        EXPECT_GT(test::maxAbsDifference(cpu, start), 0.5f) << "nothing ran";
        std::printf("water: start %.6g cpu %.6g gpu %.6g, gpu vs cpu %.3g\n", water(start),
                    water(cpu), water(gpu), double(test::maxAbsDifference(cpu, gpu)));
        if (tiles.empty()) {
            // Relative 1e-5: float sums over ~2,400 texels and 80 steps.
            EXPECT_NEAR(water(gpu) / water(start), 1.0, 1e-5);
            // Without gravity the same run differs by far more than rounding.
            Session still = s;
            still.gravity = {};
            (void)setUpSurface(still);
            still.dt = s.dt;
            const State plain = run(gl::GpuSimulator(still), {});
            EXPECT_GT(test::maxAbsDifference(plain, gpu), 0.05f) << "gravity changed nothing";
        }
    }
}

TEST(WatercolourGl, DropsRunDownAModelAsOnTheCpu) {
    dropsRunDownAModelAsOnTheCpu("");
    dropsRunDownAModelAsOnTheCpu("w");
}

// The designer's GPU display of the "watercolour" map against the CPU path
// (what render writes): the same paint within the driver's float-to-unorm8
// rounding (1 of 255 per channel), dark edges included, read across the
// border both ways (the session's edges).
TEST(WatercolourGl, GpuDisplayPaintsAsTheImageWriter) {
    test::glContext();
    for (const EdgeMode edges : {EdgeMode::Clamped, EdgeMode::Periodic}) {
        Session s = sessionFromJson(nlohmann::json{{"model", "watercolour"}}, "display");
        s.width = 64;
        s.height = 48;
        s.edges = edges;
        s.init.inside["p2"] = 0.4f;
        s.colormap.name = "watercolour";
        s.colormap.edgeWidth = 0.06f; // radii 1 and 4 cells at 64
        gl::GpuSimulator gpu(s);
        gpu.setState(
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
        gpu.run(150); // part dry, part wet: deposits and suspended pigment both show
        ColorMapSpec plain = s.colormap;
        plain.edgeDarkening = 0.0f;
        gl::Display onGpu(s.width, s.height), onCpu(s.width, s.height), flat(s.width, s.height);
        onGpu.render(gpu, 0, s.colormap, edges);
        onCpu.upload(gpu.state(), 0, s.colormap, edges);
        flat.render(gpu, 0, plain, edges);
        const std::vector<std::uint8_t> a = onGpu.downloadRgba8(), b = onCpu.downloadRgba8(),
                                        c = flat.downloadRgba8();
        ASSERT_EQ(a.size(), b.size());
        int worst = 0, coloured = 0, darkened = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
            coloured += i % 4 == 0 && b[i] < 200; // red absorbed: blue pigment shows
            darkened += i % 4 == 0 && int(a[i]) + 8 < int(c[i]);
        }
        std::printf("watercolour display (%s edges): gpu-cpu worst %d of 255, %d pigmented "
                    "texels, %d darkened by more than 8 of 255 at the edges\n",
                    edges == EdgeMode::Periodic ? "periodic" : "clamped", worst, coloured,
                    darkened);
        EXPECT_LE(worst, 1);
        EXPECT_GT(coloured, 20);
        EXPECT_GT(darkened, 20) << "the dark edges were not drawn";
    }
}
