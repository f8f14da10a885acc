// Meinhardt's stripe system (Turk 1991, appendix) on the CPU reference
// backend: substrate noise makes stripes, a homogeneous substrate makes none
// (Turk: "no stripes will form anywhere"), one initiator cell grows a pattern;
// and the fused kernel agrees with the generic path for every built-in model.

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/analysis/pattern_classifier.hpp"
#include "core/models/initial_condition.hpp"
#include "core/models/meinhardt_stripes.hpp"
#include "core/models/reaction_model.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// max - min of one chemical.
float spread(const State& s, int chemical) {
    const float* p = s.plane(chemical);
    const auto [lo, hi] = std::minmax_element(p, p + s.cellCount());
    return *hi - *lo;
}

// The stripe preset on 64 x 64 with the substrate noise given and, when
// `initiators` > 0, that many single cells with the substrate raised 5%.
Session stripeSession(float substrateNoise, int initiators, int steps) {
    Session s = test::smallSession("meinhardt_random_stripes", 64, steps);
    s.init = s.reactionModel().defaultInit();
    s.init.noise["substrate"] = substrateNoise;
    if (initiators > 0) {
        s.init.type = InitialCondition::Type::SeedSpots;
        s.init.spotCount = initiators;
        s.init.spotRadius = 0.0f; // one cell each
        s.init.inside["substrate"] = 1.05f;
    }
    return s;
}

} // namespace

TEST(MeinhardtStripes, TheDefaultStartIsTheHomogeneousSteadyState) {
    const ReactionModel& model = *findModel("meinhardt_stripes");
    ParamValues params;
    for (const ParamSpec& p : model.params())
        params[p.name] = p.defaultValue;
    const std::vector<float> packed = model.packParams(params);
    const MeinhardtStripesModel::Cell cell(packed.data());
    const InitialCondition& init = model.defaultInit();
    float c[6], dcdt[6];
    for (int i = 0; i < 6; ++i)
        c[i] = init.base.at(model.chemicals()[std::size_t(i)].name);
    cell.react(c, dcdt);
    for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(dcdt[i], 0.0f, 1e-6f) << model.chemicals()[std::size_t(i)].name;
    // r = 0 (a careless reset) must not divide by zero.
    c[2] = 0.0f;
    cell.react(c, dcdt);
    for (float d : dcdt)
        EXPECT_TRUE(std::isfinite(d));
}

TEST(MeinhardtStripes, SubstrateNoiseGrowsStripes) {
    const Session s = stripeSession(0.005f, 0, 3000);
    const State st = test::runCpu(s);
    const PatternStats stats = measurePattern(st, 0);
    std::printf("meinhardt stripes: wavelength %.2f, features %d, elongated %.2f, class %s\n",
                stats.dominantWavelength, stats.featureCount, stats.elongatedShare,
                toString(classifyPattern(stats, &s.reactionModel().chemicals()[0])).c_str());
    EXPECT_EQ(classifyPattern(stats, &s.reactionModel().chemicals()[0]), PatternClass::Stripes);
    EXPECT_GT(spread(st, 0), 1.0f); // g1 near 0 in one colour, ~1.5 in the other
    EXPECT_GT(stats.dominantWavelength, 4.0);
}

TEST(MeinhardtStripes, AHomogeneousSubstrateFormsNoStripes) {
    const Session s = stripeSession(0.0f, 0, 3000);
    const State st = test::runCpu(s);
    for (int c = 0; c < st.channels(); ++c)
        EXPECT_LT(spread(st, c), 1e-5f) << s.reactionModel().chemicals()[std::size_t(c)].name;
    EXPECT_NEAR(st.plane(0)[0], 0.75f, 1e-3f); // and it stays at the steady state
    EXPECT_EQ(classifyPattern(measurePattern(st, 0)), PatternClass::Uniform);
}

TEST(MeinhardtStripes, OneInitiatorCellGrowsAPattern) {
    const Session s = stripeSession(0.0f, 1, 3000);
    const State st = test::runCpu(s);
    const PatternStats stats = measurePattern(st, 0);
    EXPECT_GT(spread(st, 0), 1.0f);
    EXPECT_NE(classifyPattern(stats), PatternClass::Uniform);
    EXPECT_NE(classifyPattern(stats), PatternClass::Unstable);
    // The pattern spreads from the initiator over much of the 64 x 64 grid:
    // both colours cover a good share of it.
    EXPECT_GT(stats.minorityFraction, 0.2);
}

TEST(CpuKernels, FusedAndGenericPathsAgreeForEveryModel) {
    // A parameter map sends a run down the generic path (one react() per
    // cell); a map of one parameter to its own value must change nothing.
    for (const ReactionModel* model : allModels()) {
        SCOPED_TRACE(model->name());
        // The model's defaults, with noise on every chemical so each reacts.
        Session fused;
        fused.model = model->name();
        for (const ParamSpec& p : model->params())
            fused.params[p.name] = p.defaultValue;
        fused.dt = model->defaultDt();
        fused.init = model->defaultInit();
        for (const ChemicalSpec& c : model->chemicals())
            fused.init.noise.emplace(c.name, 0.01f);
        fused.width = fused.height = 32;
        fused.steps = 200;
        Session generic = fused;
        const ParamSpec& first = model->params().front();
        const float v = fused.params.at(first.name);
        generic.paramMaps[first.name] = {ParamMapSpec::Field::LinearX, v, v};
        // Every built-in model has its fused kernel (up to 12 chemicals), so
        // the two runs take different code.
        ASSERT_NE(fusedExplicitStep(*model, StepConstants::fromSession(fused)), nullptr);
        ASSERT_EQ(fusedExplicitStep(*model, StepConstants::fromSession(generic)), nullptr);
        const State a = test::runCpu(fused);
        const State b = test::runCpu(generic);
        const State start = makeInitialState(fused.init, *model, fused.params, fused.width,
                                             fused.height, fused.seed);
        std::printf("%s: fused vs generic %.3g, change over the run %.3g\n", model->name().c_str(),
                    test::maxAbsDifference(a, b), test::maxAbsDifference(a, start));
        EXPECT_GT(test::maxAbsDifference(a, start), 1e-3f); // the run did something
        EXPECT_LT(test::maxAbsDifference(a, b), 1e-4f);
    }
}
