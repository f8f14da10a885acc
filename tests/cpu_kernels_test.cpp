// The CPU backend's 3x3 and 5x5 kernel sums: which kernels are folded into
// pair sums, that both paths (fused and generic) compute the convolution,
// and that they agree with each other bit for bit; and the fused kernels'
// model dispatch.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/models/gray_scott.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

struct DiffusionCase {
    const char* what;
    DiffusionSpec spec;
    bool folded;     // expected: every kernel centrally symmetric
    bool fiveByFive; // Kernel5, else Kernel3
};

DiffusionSpec generalized(const std::string& sequence) {
    DiffusionSpec spec;
    spec.type = DiffusionType::Generalized;
    spec.generalized = {{"u", sequence}, {"v", sequence}};
    return spec;
}

std::vector<DiffusionCase> diffusionCases() {
    DiffusionSpec anisotropic;
    anisotropic.type = DiffusionType::Anisotropic;
    anisotropic.anisotropic = {{"u", {30.0f, 2.0f, 1.0f}}, {"v", {-70.0f, 1.5f, 0.5f}}};
    DiffusionSpec mixed = generalized("e");
    mixed.generalized["u"] = "c"; // one chemical that cannot fold: neither is folded
    return {
        {"set (a)", generalized("a"), true, false},    {"set (c)", generalized("c"), false, true},
        {"set (d)", generalized("d"), true, true},     {"set (e)", generalized("e"), true, true},
        {"set (f)", generalized("f"), true, true},     {"u (c), v (e)", mixed, false, true},
        {"anisotropic 3x3", anisotropic, true, false},
    };
}

// Gray-Scott at F = k = 0 with v = 0 is pure diffusion of u: one step is
// u' = u + dt A u exactly (v stays 0), so the kernel sum can be checked alone.
Session pureDiffusion(const DiffusionSpec& spec, EdgeMode edges) {
    Session s = test::smallSession("gs_coral", 9, 1);
    s.width = 13; // non-square catches swapped axes
    s.params["F"] = 0.0f;
    s.params["k"] = 0.0f;
    s.dt = 0.1f;
    s.edges = edges;
    s.diffusion = spec;
    return s;
}

// A constant map of F to its own value sends a step down the generic path.
Session generic(Session s) {
    s.paramMaps["F"] = {ParamMapSpec::Field::LinearX, s.params.at("F"), s.params.at("F")};
    return s;
}

State randomU(const Session& s) {
    State state(s.width, s.height, 2);
    std::uint32_t bits = 12345;
    for (std::size_t i = 0; i < state.cellCount(); ++i) {
        bits = bits * 1664525u + 1013904223u;
        state.plane(0)[i] = float(bits >> 8) / float(1u << 24);
    }
    return state;
}

} // namespace

TEST(CpuKernels, EvenKernelsFoldAndOthersDoNot) {
    for (const DiffusionCase& c : diffusionCases()) {
        SCOPED_TRACE(c.what);
        const StepConstants k =
            StepConstants::fromSession(pureDiffusion(c.spec, EdgeMode::Periodic));
        ASSERT_EQ(k.op.form, c.fiveByFive ? DiffusionOperator::Form::Kernel5
                                          : DiffusionOperator::Form::Kernel3);
        EXPECT_EQ(foldsKernels(k.op), c.folded);
        // Folded: the centre and one tap per mirror pair; else every tap.
        const int side = c.fiveByFive ? 5 : 3;
        const KernelTaps taps = kernelTaps(k.op, 0);
        EXPECT_EQ(taps.folded, c.folded);
        EXPECT_EQ(taps.radius, c.fiveByFive ? 2 : 1);
        EXPECT_EQ(taps.count, c.folded ? (side * side + 1) / 2 : side * side);
        EXPECT_EQ(taps.taps[0].dx, 0);
        EXPECT_EQ(taps.taps[0].dy, 0);
    }
    // One weight off its mirror by the last bit in float is enough to refuse.
    DiffusionOperator op;
    op.form = DiffusionOperator::Form::Kernel5;
    op.chemicals = 1;
    op.kernels[0].at(-2, 1) = op.kernels[0].at(2, -1) = 0.25;
    op.kernels[0].at(0, 0) = -0.5;
    EXPECT_TRUE(foldsKernels(op));
    op.kernels[0].at(2, -1) = std::nextafter(0.25f, 1.0f);
    EXPECT_FALSE(foldsKernels(op));
    op.form = DiffusionOperator::Form::Laplacian5;
    EXPECT_FALSE(foldsKernels(op));
}

TEST(CpuKernels, OneStepOfBothPathsIsTheConvolution) {
    for (const DiffusionCase& c : diffusionCases())
        for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped})
            for (bool semiImplicit : {false, true})
                for (bool genericPath : {false, true}) {
                    SCOPED_TRACE(std::string(c.what) + " " + toString(edges) +
                                 (semiImplicit ? " semi-implicit" : " explicit") +
                                 (genericPath ? " generic" : " fused"));
                    Session s = pureDiffusion(c.spec, edges);
                    // Any kernel will do for one explicit step, and the
                    // stabilizer's search costs most of the test's time; the
                    // semi-implicit solve needs it.
                    s.diffusion.stabilize = semiImplicit;
                    if (semiImplicit) {
                        // One relaxation pass from x0 = c with rhs = c (no
                        // reaction): c' = c + omega dt A c.
                        s.integrator = Integrator::SemiImplicit;
                        s.relaxationPasses = 1;
                    }
                    if (genericPath)
                        s = generic(s);
                    const StepConstants k = StepConstants::fromSession(s);
                    ASSERT_EQ(fusedExplicitStep(s.reactionModel(), k) == nullptr, genericPath);
                    const float scale = semiImplicit ? k.dt * k.omega[0] : k.dt;
                    const State start = randomU(s);
                    CpuSimulator sim(s);
                    sim.setState(start);
                    sim.run(1);
                    const State end = sim.state();
                    const Kernel5& kernel = k.op.kernels[0];
                    double worst = 0, largest = 0;
                    for (int y = 0; y < s.height; ++y)
                        for (int x = 0; x < s.width; ++x) {
                            double sum = 0;
                            for (int dy = -2; dy <= 2; ++dy)
                                for (int dx = -2; dx <= 2; ++dx)
                                    sum +=
                                        double(float(kernel.at(dx, dy))) *
                                        start.at(0, GridDomain::wrapOrClamp(x + dx, s.width, edges),
                                                 GridDomain::wrapOrClamp(y + dy, s.height, edges));
                            const double expected = start.at(0, x, y) + double(scale) * sum;
                            worst = std::max(worst, std::fabs(end.at(0, x, y) - expected));
                            largest = std::max(largest, std::fabs(double(scale) * sum));
                            ASSERT_EQ(end.at(1, x, y), 0.0f);
                        }
                    // The step changed u by ~largest; float sums of ~25 terms
                    // of size ~1 are good to a few ulps of 1.
                    EXPECT_GT(largest, 0.01);
                    EXPECT_LT(worst, 2e-6);
                }
}

// Both paths sum the same taps in kernelTaps()' order with the same float
// operations, so they agree exactly (GCC does not contract them into fused
// multiply-adds on x86-64; see cpu_kernels.cpp). Many steps of a reacting
// model, so that any difference would grow.
TEST(CpuKernels, FusedAndGenericPathsAgreeBitForBit) {
    for (const DiffusionCase& c : diffusionCases())
        for (EdgeMode edges : {EdgeMode::Periodic, EdgeMode::Clamped}) {
            SCOPED_TRACE(std::string(c.what) + " " + toString(edges));
            Session s = test::smallSession("gs_coral", 20, 150);
            s.width = 24;
            s.edges = edges;
            s.diffusion = c.spec;
            s.dt = 0.1f; // within the anisotropic masks' explicit limit
            const State start =
                makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
            const State fused = test::runCpu(s), slow = test::runCpu(generic(s));
            std::printf("%s %s: moved %.3g, fused-generic %.3g\n", c.what, toString(edges).c_str(),
                        test::maxAbsDifference(fused, start), test::maxAbsDifference(fused, slow));
            EXPECT_GT(test::maxAbsDifference(fused, start), 1e-2f);
#if defined(__x86_64__)
            EXPECT_EQ(test::maxAbsDifference(fused, slow), 0.0f);
#else
            EXPECT_LT(test::maxAbsDifference(fused, slow), 1e-5f);
#endif
        }
}

namespace {
// Not a built-in model, though it is one by inheritance.
class DerivedGrayScott : public GrayScottModel {};
} // namespace

// The fused kernels' model dispatch reads the same list as the registry
// (builtin_models.hpp): every registered model gets a fused reaction pass,
// and a model that is not on the list gets none.
TEST(CpuKernels, EveryRegisteredModelHasItsFusedKernels) {
    for (const ReactionModel* model : allModels()) {
        SCOPED_TRACE(model->name());
        Session s;
        s.model = model->name();
        for (const ParamSpec& p : model->params())
            s.params[p.name] = p.defaultValue;
        s.width = s.height = 8;
        const StepConstants k = StepConstants::fromSession(s);
        EXPECT_NE(fusedRhsPass(*model, k), nullptr);
        EXPECT_EQ(findModel(model->name()), model);
    }
    const DerivedGrayScott derived;
    Session s = test::smallSession("gs_coral", 8, 1);
    const StepConstants k = StepConstants::fromSession(s);
    ASSERT_NE(fusedRhsPass(s.reactionModel(), k), nullptr);
    EXPECT_EQ(fusedRhsPass(derived, k), nullptr);
    EXPECT_EQ(fusedExplicitStep(derived, k), nullptr);
}
