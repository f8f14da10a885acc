// The GLSL backend against the CPU reference: same step semantics, for every
// model, both edge modes and both stencils.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/analysis/pattern_stats.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

struct Case {
    const char* preset;
    // Absolute tolerance after 50 steps. Not zero: the GPU may fuse
    // multiply-adds and order sums differently, and RD amplifies differences
    // (values: Gray-Scott ~[0, 1], Turk and McGraw ~[0, 30]).
    float tolerance;
};

State initial(const Session& s) {
    return makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
}

} // namespace

TEST(GpuCpuAgreement, EveryModelEdgeModeAndStencilAfter50Steps) {
    test::glContext();
    const Case cases[] = {
        {"gs_coral", 1e-4f}, {"turk_small_spots", 1e-3f}, {"mcgraw_turing", 1e-3f}};
    for (const Case& c : cases)
        for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped})
            for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint}) {
                Session s = test::smallSession(c.preset, 40, 50);
                s.width = 48; // non-square catches swapped axes
                s.edges = edges;
                s.diffusion.stencil = stencil;
                SCOPED_TRACE(std::string(c.preset) + " " + toString(edges) + " " +
                             toString(stencil));
                const State start = initial(s);
                CpuSimulator cpu(s);
                cpu.setState(start);
                cpu.run(50);
                gl::GpuSimulator gpu(s);
                gpu.setState(start);
                gpu.run(50);
                const State a = cpu.state(), b = gpu.state();
                std::printf("%s %s %s: moved %.3g, gpu-cpu %.3g\n", c.preset,
                            toString(edges).c_str(), toString(stencil).c_str(),
                            test::maxAbsDifference(a, start), test::maxAbsDifference(a, b));
                // The runs must have moved, or agreement would prove nothing.
                EXPECT_GT(test::maxAbsDifference(a, start), 100 * c.tolerance);
                EXPECT_LT(test::maxAbsDifference(a, b), c.tolerance);
            }
}

TEST(GpuCpuAgreement, EveryDiffusionOperatorAndIntegrator) {
    test::glContext();
    struct OperatorCase {
        const char* what;
        Session session;
        float tolerance; // see Case::tolerance; values stay within ~[-2, 2] here
    };
    std::vector<OperatorCase> cases;
    auto wk = [] {
        Session s = test::smallSession("gs_coral", 40, 50);
        s.model = "witkin_kass";
        s.params = {{"k", 1.0f}, {"b", 1.0f}, {"Dp", 1.0f}, {"Dm", 1.0f}};
        s.init = s.reactionModel().defaultInit();
        s.dt = 0.02f;
        s.diffusion.type = DiffusionType::Anisotropic;
        s.diffusion.anisotropic["p"] = {30.0f, 2.0f, 1.0f};
        s.diffusion.anisotropic["m"] = {30.0f, 2.0f, 1.5f};
        return s;
    };
    cases.push_back({"anisotropic 3x3", wk(), 1e-3f});
    Session mapped = wk();
    mapped.diffusion.map = DiffusionMapSpec{};
    mapped.diffusion.map->orientation.type = OrientationField::Type::Spiral;
    mapped.diffusion.map->orientation.angle = 30.0f;
    cases.push_back({"diffusion map", mapped, 1e-3f});
    // Two state textures (MRT): the map and the 5x5 kernels indexed per texture.
    Session mappedMrt = mapped;
    mappedMrt.model = "witkin_kass_md3";
    mappedMrt.params.clear();
    for (const ParamSpec& p : mappedMrt.reactionModel().params())
        mappedMrt.params[p.name] = p.defaultValue;
    mappedMrt.init = mappedMrt.reactionModel().defaultInit();
    mappedMrt.diffusion.anisotropic = mappedMrt.reactionModel().defaultDiffusion().anisotropic;
    cases.push_back({"diffusion map, 6 chemicals", mappedMrt, 1e-3f});
    Session generalizedMrt = test::smallSession("meinhardt_random_stripes", 40, 50);
    generalizedMrt.diffusion.type = DiffusionType::Generalized;
    generalizedMrt.diffusion.generalized = {{"g1", "c"}, {"g2", "c"}, {"s1", "a"}, {"s2", "a"}};
    generalizedMrt.init.noise = {{"g1", 0.3f}, {"g2", 0.3f}}; // off the steady state, so it moves
    cases.push_back({"generalized, 6 chemicals", generalizedMrt, 1e-4f});
    for (const char* set : {"c", "d"}) {
        Session g = test::smallSession("gs_coral", 40, 50);
        g.diffusion.type = DiffusionType::Generalized;
        g.diffusion.generalized = {{"u", set}, {"v", set}};
        g.dt = 0.15f;
        cases.push_back({set[0] == 'c' ? "generalized (c)" : "generalized (d)", g, 1e-4f});
    }
    Session semi = test::smallSession("gs_coral", 40, 20);
    semi.integrator = Integrator::SemiImplicit;
    semi.dt = 3.0f;
    cases.push_back({"semi-implicit 5-point", semi, 1e-4f});
    Session semiGeneralized = std::find_if(cases.begin(), cases.end(), [](const OperatorCase& c) {
                                  return std::string(c.what) == "generalized (d)";
                              })->session;
    semiGeneralized.integrator = Integrator::SemiImplicit;
    semiGeneralized.dt = 1.0f;
    semiGeneralized.steps = 20;
    cases.push_back({"semi-implicit generalized (d)", semiGeneralized, 1e-4f});

    for (OperatorCase& c : cases)
        for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped}) {
            Session& s = c.session;
            s.edges = edges;
            s.width = 48;
            SCOPED_TRACE(std::string(c.what) + " " + toString(edges));
            const State start = initial(s);
            CpuSimulator cpu(s);
            cpu.setState(start);
            cpu.run(s.steps);
            gl::GpuSimulator gpu(s);
            gpu.setState(start);
            gpu.run(s.steps);
            const State a = cpu.state(), b = gpu.state();
            std::printf("%s %s: moved %.3g, gpu-cpu %.3g\n", c.what, toString(edges).c_str(),
                        test::maxAbsDifference(a, start), test::maxAbsDifference(a, b));
            EXPECT_GT(test::maxAbsDifference(a, start), 100 * c.tolerance);
            EXPECT_LT(test::maxAbsDifference(a, b), c.tolerance);
        }
}

// Every registered model, so a new model's GLSL snippet is checked against
// its C++ Cell as soon as it is registered. Models with more than four
// chemicals run on several state textures written together (MRT); the frozen
// and semi-implicit variants read and write every texture too.
TEST(GpuCpuAgreement, EveryModelOnEveryPassVariant) {
    test::glContext();
    for (const ReactionModel* model : allModels()) {
        Session s;
        s.model = model->name();
        for (const ParamSpec& p : model->params())
            s.params[p.name] = p.defaultValue;
        s.width = 40; // non-square catches swapped axes
        s.height = 32;
        s.dt = model->defaultDt();
        s.init = model->defaultInit();
        // Noise on every chemical, so every reaction term is exercised.
        for (const ChemicalSpec& c : model->chemicals()) {
            const float base = s.init.base.count(c.name) ? s.init.base.at(c.name) : 0.0f;
            s.init.noise[c.name] = std::max(s.init.noise[c.name], 0.05f * std::fabs(base) + 0.01f);
        }
        const State start = initial(s);
        std::vector<std::uint8_t> frozen(start.cellCount(), 0);
        for (std::size_t i = 0; i < frozen.size(); i += 3)
            frozen[i] = 1;
        for (const char* variant : {"explicit", "frozen", "semi-implicit"}) {
            SCOPED_TRACE(model->name() + " " + variant);
            Session v = s;
            if (std::string(variant) == "semi-implicit")
                v.integrator = Integrator::SemiImplicit;
            const bool freeze = std::string(variant) == "frozen";
            CpuSimulator cpu(v);
            gl::GpuSimulator gpu(v);
            cpu.setState(start);
            gpu.setState(start);
            if (freeze) {
                cpu.setFrozen(frozen);
                gpu.setFrozen(frozen);
            }
            cpu.run(30);
            gpu.run(30);
            const State a = cpu.state(), b = gpu.state();
            // Relative to the largest value: models range from ~1 to ~30.
            const float scale = std::max(1.0f, test::maxAbsValue(a));
            const float tolerance = 1e-4f * scale;
            std::printf("%s %s (%d chemicals): moved %.3g, gpu-cpu %.3g\n", model->name().c_str(),
                        variant, a.channels(), test::maxAbsDifference(a, start),
                        test::maxAbsDifference(a, b));
            EXPECT_GT(test::maxAbsDifference(a, start), 100 * tolerance);
            EXPECT_LT(test::maxAbsDifference(a, b), tolerance);
            if (freeze)
                for (int c = 0; c < a.channels(); ++c)
                    for (std::size_t i = 0; i < frozen.size(); i += 3)
                        ASSERT_EQ(b.plane(c)[i], start.plane(c)[i]) << "chemical " << c;
        }
    }
}

TEST(GpuCpuAgreement, UploadThenReadBackIsExact) {
    test::glContext();
    const Session s = test::smallSession("turk_irregular_spots", 17, 0);
    gl::GpuSimulator gpu(s);
    const State start = initial(s);
    gpu.setState(start);
    EXPECT_TRUE(gpu.state() == start);
}

// State transfers go a band of ~256k texels at a time: a grid of several
// bands (the last one short), with two state textures (six chemicals: RGBA32F,
// the second half empty), round-trips exactly, and the blow-up check over the
// bands names the cell the CPU's whole-grid scan names.
TEST(GpuCpuAgreement, BandedTransfersAndChecksMatchTheWholeGrid) {
    test::glContext();
    Session s = test::smallSession("meinhardt_random_stripes", 8, 0);
    s.width = 700;
    s.height = 1000; // 374 rows a band: three bands
    const ReactionModel& model = s.reactionModel();
    ASSERT_GT(model.chemicals().size(), 4u);
    State start = initial(s);
    for (int c = 0; c < start.channels(); ++c)
        for (std::size_t i = 0; i < start.cellCount(); i += 7)
            start.plane(c)[i] += 1e-3f * float(i % 13); // not one value per chemical
    gl::GpuSimulator gpu(s);
    gpu.setState(start);
    EXPECT_TRUE(gpu.state() == start);
    EXPECT_FALSE(gpu.insaneValue(model));

    State broken = start;
    broken.at(4, 5, 990) = NAN;  // in the last band
    broken.at(1, 600, 3) = 1e9f; // an earlier band, a lower chemical: the answer
    gpu.setState(broken);
    const std::optional<std::string> found = gpu.insaneValue(model);
    ASSERT_TRUE(found);
    EXPECT_EQ(found, findInsaneValue(broken, model));
    EXPECT_NE(found->find("at (600, 3)"), std::string::npos) << *found;

    CpuSimulator cpu(s);
    cpu.setState(broken);
    EXPECT_EQ(cpu.insaneValue(model), found);
    // takeState hands the buffer over: the same state, and none left behind.
    cpu.setState(start);
    EXPECT_TRUE(cpu.takeState() == start);
    EXPECT_EQ(cpu.state().cellCount(), 0u);
}

// Every preset through runSession on both backends, with every stage and
// schedule level (stages may freeze cells or change the model).
TEST(GpuPresets, EveryPresetRunsOnBothBackendsAndTheyAgree) {
    test::glContext();
    const SimulatorFactory gpu = [](const Session& level) {
        return std::make_unique<gl::GpuSimulator>(level);
    };
    const SimulatorFactory cpu = [](const Session& level) {
        return std::make_unique<CpuSimulator>(level);
    };
    for (const Session& preset : allPresets()) {
        SCOPED_TRACE(preset.name);
        // Strokes on a model need the model: drops on a model are
        // watercolour_gltest's (DropsRunDownAModelAsOnTheCpu).
        if (editsNeedTheModel(preset.edits))
            continue;
        const Session s = test::shrunk(preset, 32, 15);
        // runSession throws if a value leaves the model's sane range.
        const State a = runSession(s, cpu, {}).state, b = runSession(s, gpu, {}).state;
        ASSERT_EQ(a.channels(), b.channels());
        const float scale = std::max(1.0f, test::maxAbsValue(a));
        // See Case::tolerance; relative, as values range from ~1 to ~30.
        EXPECT_LT(test::maxAbsDifference(a, b), 1e-3f * scale);
    }
}

TEST(GpuPresets, GpuLongRunMatchesCpuByStatistics) {
    // Pixels diverge over thousands of steps; the pattern's scale must not.
    test::glContext();
    const Session s = test::smallSession("turk_small_spots", 64, 2500);
    gl::GpuSimulator gpu(s);
    gpu.setState(initial(s));
    gpu.run(s.steps);
    const State g = gpu.state(), c = test::runCpu(s);
    EXPECT_FALSE(findInsaneValue(g, s.reactionModel()));
    const double wg = spectrumStats(g, 1).dominantWavelength;
    const double wc = spectrumStats(c, 1).dominantWavelength;
    EXPECT_NEAR(wg, wc, 0.2 * wc);
}
