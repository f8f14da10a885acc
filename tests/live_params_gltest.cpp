// Live changes on the GLSL backend: parameters and dt changed between steps
// are uniform updates (no program is compiled, nothing is re-uploaded) and
// give the run a simulator built with the new values would give from the same
// state; the CPU backend agrees.

#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/models/initial_condition.hpp"
#include "core/session/param_map.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

State initial(const Session& s) {
    return makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
}

State gpuFrom(const Session& s, const State& start, int steps) {
    gl::GpuSimulator gpu(s);
    gpu.setState(start);
    gpu.run(steps);
    return gpu.state();
}

State cpuFrom(const Session& s, const State& start, int steps) {
    CpuSimulator cpu(s);
    cpu.setState(start);
    cpu.run(steps);
    return cpu.state();
}

// Gray-Scott on each operator form whose constants are uniforms: rates (the
// Laplacian), 3x3 and 5x5 kernel weights, a tensor map's coefficients.
std::vector<std::pair<std::string, Session>> operatorSessions() {
    std::vector<std::pair<std::string, Session>> sessions;
    Session base = test::smallSession("gs_coral", 32, 40);
    sessions.emplace_back("5-point", base);
    Session anisotropic = base;
    anisotropic.diffusion.type = DiffusionType::Anisotropic;
    for (const ChemicalSpec& c : base.reactionModel().chemicals())
        anisotropic.diffusion.anisotropic[c.name] = {30.0f, 1.2f, 0.8f};
    sessions.emplace_back("anisotropic 3x3", anisotropic);
    Session generalized = base;
    generalized.diffusion.type = DiffusionType::Generalized;
    for (const ChemicalSpec& c : base.reactionModel().chemicals())
        generalized.diffusion.generalized[c.name] = "c";
    sessions.emplace_back("generalized 5x5", generalized);
    Session map = test::smallSession("wk_spiral_stripes", 32, 40);
    sessions.emplace_back("tensor map", map);
    return sessions;
}

// Every diffusion rate times 0.8 and, for Gray-Scott, other F and k.
Session changedParams(const Session& s) {
    Session changed = s;
    for (const ChemicalSpec& c : s.reactionModel().chemicals())
        if (!c.diffusionParam.empty())
            changed.params[c.diffusionParam] *= 0.8f;
    if (s.model == "gray_scott") {
        changed.params["F"] = 0.03f;
        changed.params["k"] = 0.055f;
    }
    return changed;
}

} // namespace

TEST(GpuLiveChanges, ParamsChangedMidRunAreUniformsOnly) {
    test::glContext();
    for (const auto& [name, s] : operatorSessions()) {
        SCOPED_TRACE(name);
        const Session changed = changedParams(s);
        gl::GpuSimulator gpu(s);
        gpu.setState(initial(s));
        gpu.run(20);
        const State middle = gpu.state();
        const int builds = gpu.programBuilds();
        gpu.setParams(changed.params);
        gpu.run(20);
        EXPECT_EQ(gpu.programBuilds(), builds); // no shader compile
        const State live = gpu.state();
        const State rebuilt = gpuFrom(changed, middle, 20);
        const State unchanged = gpuFrom(s, middle, 20);
        const State cpu = cpuFrom(changed, middle, 20);
        std::printf("%s: live-rebuilt %.3g, live-unchanged %.3g, live-cpu %.3g\n", name.c_str(),
                    test::maxAbsDifference(live, rebuilt), test::maxAbsDifference(live, unchanged),
                    test::maxAbsDifference(live, cpu));
        const float scale = std::max(1.0f, test::maxAbsValue(middle));
        EXPECT_LT(test::maxAbsDifference(live, rebuilt), 1e-5f * scale);
        EXPECT_LT(test::maxAbsDifference(live, cpu), 1e-4f * scale);
        // The change mattered, far above the tolerances.
        EXPECT_GT(test::maxAbsDifference(live, unchanged), 1e-3f * scale);
    }
}

TEST(GpuLiveChanges, AGeneralizedKernelFromZeroRatesIsLive) {
    test::glContext();
    Session s = test::smallSession("gs_coral", 32, 40);
    s.diffusion.type = DiffusionType::Generalized;
    s.diffusion.generalized = {{"u", "c"}, {"v", "c"}};
    Session still = s;
    // A zero kernel (on the CPU: the generic path; the change re-picks the fused one).
    still.params["Du"] = still.params["Dv"] = 0.0f;
    gl::GpuSimulator gpu(still);
    gpu.setState(initial(still));
    gpu.run(10);
    const State middle = gpu.state();
    const int builds = gpu.programBuilds();
    gpu.setParams(s.params);
    gpu.run(20);
    EXPECT_EQ(gpu.programBuilds(), builds);
    EXPECT_LT(test::maxAbsDifference(gpu.state(), gpuFrom(s, middle, 20)), 1e-5f);
    EXPECT_GT(test::maxAbsDifference(gpu.state(), gpuFrom(still, middle, 20)), 1e-4f);
}

TEST(GpuLiveChanges, RatesThatComeOrGoRebuildTheStillVariant) {
    // A state texture none of whose chemicals diffuses skips its diffusion
    // term (STILL_TEXTURES, the watercolour's deposits): a rate that comes
    // live must bring the term back, one that goes must drop it.
    test::glContext();
    const Session watercolour = test::smallSession("watercolour_wet_in_wet", 32, 40);
    EXPECT_EQ(gl::stillTextures(StepConstants::fromSession(watercolour)), 2); // d1, d2, g
    const Session s = test::smallSession("gs_coral", 32, 40);
    EXPECT_EQ(gl::stillTextures(StepConstants::fromSession(s)), 0);
    Session still = s;
    still.params["Du"] = still.params["Dv"] = 0.0f;
    EXPECT_EQ(gl::stillTextures(StepConstants::fromSession(still)), 1);
    Session half = s;
    half.params["Du"] = 0.0f; // v still diffuses: the texture is not still
    EXPECT_EQ(gl::stillTextures(StepConstants::fromSession(half)), 0);

    gl::GpuSimulator gpu(still);
    gpu.setState(initial(still));
    gpu.run(10);
    const State middle = gpu.state();
    int builds = gpu.programBuilds();
    gpu.setParams(s.params);
    EXPECT_GT(gpu.programBuilds(), builds);
    gpu.run(20);
    const State diffused = gpu.state();
    const float scale = std::max(1.0f, test::maxAbsValue(middle));
    EXPECT_LT(test::maxAbsDifference(diffused, gpuFrom(s, middle, 20)), 1e-5f * scale);
    EXPECT_LT(test::maxAbsDifference(diffused, cpuFrom(s, middle, 20)), 1e-4f * scale);
    EXPECT_GT(test::maxAbsDifference(diffused, gpuFrom(still, middle, 20)), 1e-3f * scale);
    builds = gpu.programBuilds();
    gpu.setParams(still.params);
    EXPECT_GT(gpu.programBuilds(), builds);
    gpu.run(20);
    EXPECT_LT(test::maxAbsDifference(gpu.state(), gpuFrom(still, diffused, 20)), 1e-5f * scale);
    EXPECT_LT(test::maxAbsDifference(gpu.state(), cpuFrom(still, diffused, 20)), 1e-4f * scale);
}

TEST(GpuLiveChanges, DtChangedMidRunIsAUniformAndTheSemiImplicitWeightFollows) {
    test::glContext();
    for (Integrator integrator : {Integrator::ExplicitEuler, Integrator::SemiImplicit}) {
        SCOPED_TRACE(toString(integrator));
        Session s = test::smallSession("gs_coral", 32, 40);
        s.integrator = integrator;
        const float newDt = integrator == Integrator::SemiImplicit ? 3.0f : 0.5f;
        Session changed = s;
        changed.dt = newDt;
        gl::GpuSimulator gpu(s);
        gpu.setState(initial(s));
        gpu.run(15);
        const State middle = gpu.state();
        const int builds = gpu.programBuilds();
        gpu.setDt(newDt);
        gpu.run(15);
        EXPECT_EQ(gpu.programBuilds(), builds);
        const State live = gpu.state();
        EXPECT_LT(test::maxAbsDifference(live, gpuFrom(changed, middle, 15)), 1e-5f);
        EXPECT_LT(test::maxAbsDifference(live, cpuFrom(changed, middle, 15)), 1e-4f);
        EXPECT_GT(test::maxAbsDifference(live, gpuFrom(s, middle, 15)), 1e-4f);
    }
}

TEST(GpuLiveChanges, AMappedParameterKeepsItsMap) {
    test::glContext();
    Session s = loadPreset("gs_coral");
    s.width = 40;
    s.height = 8;
    s.steps = 1;
    s.dt = 0.5f;
    s.params["Du"] = s.params["Dv"] = 0.0f;
    s.init = InitialCondition{}; // u = v = 0: one step gives u = dt F
    s.paramMaps["F"] = {ParamMapSpec::Field::LinearX, 0.01f, 0.09f};
    gl::GpuSimulator gpu(s);
    gpu.setState(initial(s));
    ParamValues p = s.params;
    p["F"] = 0.05f;
    gpu.setParams(p);
    gpu.run(1);
    const State st = gpu.state();
    const std::vector<float> expected = evaluateParamMap(s.paramMaps["F"], 40, 8, s.seed, "");
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        ASSERT_NEAR(st.plane(0)[i] / s.dt, expected[i], 1e-6f) << "cell " << i;
}

TEST(GpuSessionRun, UnevenPiecesOnTheGpuMatchTheCpuAcrossACascade) {
    test::glContext();
    Session s = loadPreset("turk_cheetah");
    s.width = s.height = 32;
    s.stages[0].steps = 30;
    s.stages[1].steps = 20;
    s.steps = 50;
    const SimulatorFactory gpu = [](const Session& x) {
        return std::make_unique<gl::GpuSimulator>(x);
    };
    SessionRun run(s, gpu);
    for (int piece : {7, 1, 29, 13, 200})
        run.advance(piece);
    EXPECT_TRUE(run.finished());
    const SimulatorFactory makeCpu = [](const Session& x) {
        return std::make_unique<CpuSimulator>(x);
    };
    const State cpu = runSession(s, makeCpu, {}).state;
    EXPECT_LT(test::maxAbsDifference(run.result().state, cpu),
              1e-3f * std::max(1.0f, test::maxAbsValue(cpu)));
}
