// Witkin-Kass's competing orientations (section 6.3): the M-D and D-A
// reactions (eq. 14, 15) on hand-made cells, the fused CPU kernels against the
// generic path, the models' default anisotropic diffusion, and the woven
// 2-direction patterns measured on the CPU reference backend.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/analysis/pattern_stats.hpp"
#include "core/models/witkin_kass_multi.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

const char* const kModels[] = {"witkin_kass_md2", "witkin_kass_md3", "witkin_kass_md5",
                               "witkin_kass_da2", "witkin_kass_da3", "witkin_kass_da5"};

// Cells for N pairs whose differences D_i = C+_i - C-_i are `d` (C-_i = m_i,
// C+_i = m_i + d_i with assorted m_i, so only the differences matter). The
// m_i are multiples of 1/4, so dyadic d_i come back exactly and ties are ties.
std::vector<float> cellWithDifferences(const std::vector<float>& d) {
    std::vector<float> c;
    for (std::size_t i = 0; i < d.size(); ++i) {
        const float m = 0.25f * float(i) - 0.5f;
        c.push_back(m + d[i]);
        c.push_back(m);
    }
    return c;
}

// R of a cell (to rounding: it is 0 or k): every chemical's dc/dt is R - b c,
// the same R for all.
template <class Cell> float reactionOf(const Cell& cell, const std::vector<float>& c, float b) {
    std::vector<float> dcdt(c.size());
    cell.react(c.data(), dcdt.data());
    const float r = dcdt[0] + b * c[0];
    for (std::size_t j = 0; j < c.size(); ++j)
        EXPECT_NEAR(dcdt[j], r - b * c[j], 1e-6f) << "chemical " << j;
    return r;
}

template <class Model> void checkMaxOfDifferences() {
    constexpr int n = Model::kPairs;
    SCOPED_TRACE("M-D, " + std::to_string(n) + " pairs");
    const float k = 1.5f, b = 0.7f, threshold = 0.25f, step = 1.0f / 1024.0f;
    const float params[] = {k, b, threshold, 1.0f};
    const typename Model::Cell cell(params);
    // The largest difference sits at every pair in turn, just above, at and
    // just below the threshold; the others are far below (or far above, to
    // show min does not matter).
    for (int at = 0; at < n; ++at)
        for (float top : {threshold + step, threshold, threshold - step, 2.0f, -0.5f}) {
            std::vector<float> d(std::size_t(n), -3.0f);
            d[std::size_t(at)] = top;
            EXPECT_NEAR(reactionOf(cell, cellWithDifferences(d), b), top > threshold ? k : 0.0f,
                        1e-5f)
                << "max D " << top << " at pair " << at;
        }
}

template <class Model> void checkDifferenceOfAbs() {
    constexpr int n = Model::kPairs;
    SCOPED_TRACE("D-A, " + std::to_string(n) + " pairs");
    const float k = 1.5f, b = 0.7f;
    const float params[] = {k, b, 1.0f};
    const typename Model::Cell cell(params);
    // {max, min} pairs: R fires exactly when |max| > |min|.
    const std::pair<float, float> cases[] = {{1.0f, -0.5f},
                                             {0.5f, -1.0f},
                                             {0.5f, -0.5f},
                                             {0.8f, 0.2f},
                                             {-0.2f, -0.8f},
                                             {0.0f, 0.0f},
                                             {2.0f, 1.9f},
                                             {-1.9f, -2.0f},
                                             {0.25f, -0.25f - 1.0f / 1024},
                                             {0.25f + 1.0f / 1024, -0.25f}};
    for (const auto& [hi, lo] : cases)
        for (int at = 0; at < n; ++at) {
            // Max at pair `at`, min at the next; the rest in between.
            std::vector<float> d(std::size_t(n), 0.5f * (hi + lo));
            d[std::size_t(at)] = hi;
            d[std::size_t((at + 1) % n)] = lo;
            EXPECT_NEAR(reactionOf(cell, cellWithDifferences(d), b),
                        std::fabs(hi) > std::fabs(lo) ? k : 0.0f, 1e-5f)
                << "max " << hi << ", min " << lo << ", max at pair " << at;
        }
}

Session modelSession(const std::string& model, int size, int steps) {
    nlohmann::json j = {{"model", model}, {"size", size}, {"steps", steps}};
    return sessionFromJson(j, model);
}

// Each pair's difference D_i = C+_i - C-_i (channel i) and max_j D_j, what
// M-D thresholds (channel N).
State differences(const State& s, int pairs) {
    State d(s.width(), s.height(), pairs + 1);
    for (std::size_t x = 0; x < s.cellCount(); ++x) {
        float hi = -INFINITY;
        for (int i = 0; i < pairs; ++i) {
            d.plane(i)[x] = s.plane(2 * i)[x] - s.plane(2 * i + 1)[x];
            hi = std::max(hi, d.plane(i)[x]);
        }
        d.plane(pairs)[x] = hi;
    }
    return d;
}

struct Measured {
    OrientationStats pair1, pair2, combined;
    SpectrumStats spectrum;
};

// A 2-direction preset shrunk to 64 cells, run for its full model time.
Measured measureTwoDirections(const char* preset) {
    const Session s = test::smallSession(preset, 64, loadPreset(preset).steps);
    const State d = differences(test::runCpu(s), 2);
    Measured m;
    m.pair1 = orientationStats(d, 0);
    m.pair2 = orientationStats(d, 1);
    m.combined = orientationStats(d, 2);
    m.spectrum = spectrumStats(d, 2);
    std::printf("%s: pair 1 Re m2 %+.3f, pair 2 Re m2 %+.3f; max D: Re m2 %+.3f, Re m4 %+.3f; "
                "wavelength %.1f, nyquist %.4f, variance %.3g\n",
                preset, m.pair1.re[2], m.pair2.re[2], m.combined.re[2], m.combined.re[4],
                m.spectrum.dominantWavelength, m.spectrum.nyquistFraction, m.spectrum.variance);
    return m;
}

} // namespace

TEST(WitkinKassMulti, SixModelsWithPairedChemicalsAndOneSnippet) {
    for (const char* name : kModels) {
        SCOPED_TRACE(name);
        const ReactionModel* model = findModel(name);
        ASSERT_NE(model, nullptr);
        const int pairs = name[std::string(name).size() - 1] - '0';
        const bool md = std::string(name).find("_md") != std::string::npos;
        ASSERT_EQ(model->chemicals().size(), std::size_t(2 * pairs));
        for (int i = 0; i < pairs; ++i) {
            EXPECT_EQ(model->chemicals()[std::size_t(2 * i)].name, "p" + std::to_string(i + 1));
            EXPECT_EQ(model->chemicals()[std::size_t(2 * i + 1)].name, "m" + std::to_string(i + 1));
        }
        for (const ChemicalSpec& c : model->chemicals())
            EXPECT_EQ(c.diffusionParam, "D");
        EXPECT_EQ(model->param("threshold") != nullptr, md);
        EXPECT_EQ(model->glslPath(), "glsl/models/witkin_kass_multi.glsl");
        const std::vector<std::string> defines = {"WK_PAIRS " + std::to_string(pairs),
                                                  std::string("WK_REACTION ") + (md ? "0" : "1")};
        EXPECT_EQ(model->glslDefines(), defines);
    }
}

TEST(WitkinKassMulti, MaxOfDifferencesFiresExactlyAboveTheThreshold) {
    checkMaxOfDifferences<WitkinKassMd2>();
    checkMaxOfDifferences<WitkinKassMd3>();
    checkMaxOfDifferences<WitkinKassMd5>();
}

TEST(WitkinKassMulti, DifferenceOfAbsFiresExactlyWhenTheMaxOutweighsTheMin) {
    checkDifferenceOfAbs<WitkinKassDa2>();
    checkDifferenceOfAbs<WitkinKassDa3>();
    checkDifferenceOfAbs<WitkinKassDa5>();
}

TEST(WitkinKassMulti, WithoutADiffusionBlockEachPairDiffusesAlongItsOwnDirection) {
    for (const char* name : kModels) {
        SCOPED_TRACE(name);
        const Session s = modelSession(name, 16, 1);
        const int pairs = int(s.reactionModel().chemicals().size()) / 2;
        ASSERT_EQ(s.diffusion.type, DiffusionType::Anisotropic);
        ASSERT_EQ(s.diffusion.anisotropic.size(), std::size_t(2 * pairs));
        for (int i = 0; i < pairs; ++i) {
            const AnisotropicTensor p = s.diffusion.anisotropic.at("p" + std::to_string(i + 1));
            const AnisotropicTensor m = s.diffusion.anisotropic.at("m" + std::to_string(i + 1));
            // Section 6.2: P+ = [theta_i, e s, s], P- = [theta_i, e s, d s], e 2, d 1.5, s 1.
            EXPECT_FLOAT_EQ(p.theta, 180.0f * float(i) / float(pairs));
            EXPECT_FLOAT_EQ(m.theta, p.theta);
            EXPECT_FLOAT_EQ(p.a1, 2.0f);
            EXPECT_FLOAT_EQ(p.a2, 1.0f);
            EXPECT_FLOAT_EQ(m.a1, 2.0f);
            EXPECT_FLOAT_EQ(m.a2, 1.5f);
        }
        // A session's own block replaces the default whole, as "init" does.
        const Session iso =
            sessionFromJson({{"model", name}, {"diffusion", {{"type", "isotropic"}}}}, "iso.json");
        EXPECT_EQ(iso.diffusion.type, DiffusionType::Isotropic);
        // And it survives a round trip through JSON.
        const Session again = sessionFromJson(sessionToJson(s), "again.json");
        EXPECT_EQ(again.diffusion.anisotropic.size(), s.diffusion.anisotropic.size());
    }
    // Other models keep isotropic diffusion.
    EXPECT_EQ(modelSession("witkin_kass", 16, 1).diffusion.type, DiffusionType::Isotropic);
}

TEST(WitkinKassMulti, FusedKernelsAgreeWithTheGenericPath) {
    for (const char* name : kModels) {
        SCOPED_TRACE(name);
        Session fused = modelSession(name, 24, 40);
        fused.width = 20; // non-square catches swapped axes
        if (fused.reactionModel().param("threshold"))
            fused.params["threshold"] = 0.1f;
        // Every model has a fused kernel, the 10-chemical ones too (cpu_kernels.hpp).
        EXPECT_NE(fusedExplicitStep(fused.reactionModel(), StepConstants::fromSession(fused)),
                  nullptr);
        // A parameter map (here a constant one) sends the step down the
        // generic path: the virtual react() per cell and row buffers.
        Session generic = fused;
        ParamMapSpec constantK;
        constantK.min = constantK.max = fused.params.at("k");
        generic.paramMaps["k"] = constantK;
        ASSERT_EQ(fusedExplicitStep(generic.reactionModel(), StepConstants::fromSession(generic)),
                  nullptr);
        const State start = makeInitialState(fused.init, fused.reactionModel(), fused.params,
                                             fused.width, fused.height, fused.seed);
        const State a = test::runCpu(fused), b = test::runCpu(generic);
        EXPECT_GT(test::maxAbsDifference(a, start), 0.1f); // it moved
        EXPECT_LE(test::maxAbsDifference(a, b), 1e-5f);
        // Semi-implicit runs use the fused reaction pass (rhs = c + dt f(c)) too.
        fused.integrator = generic.integrator = Integrator::SemiImplicit;
        fused.dt = generic.dt = 0.1f;
        fused.steps = generic.steps = 10;
        EXPECT_NE(fusedRhsPass(fused.reactionModel(), StepConstants::fromSession(fused)), nullptr);
        EXPECT_LE(test::maxAbsDifference(test::runCpu(fused), test::runCpu(generic)), 1e-5f);
    }
}

TEST(WitkinKassMulti, TwoDirectionPatternsHaveStructureAlongBothDirections) {
    // Pair 1 diffuses along x (theta 0), pair 2 along y (theta 90). Each
    // pair's difference forms threads along its own direction, so its
    // gradients run across them: pair 1's mostly vertical (Re m2 < 0), pair
    // 2's mostly horizontal (Re m2 > 0). Together (max D) neither direction
    // wins and the gradients sit on both axes (Re m4 > 0).
    for (const char* preset : {"wk_weave", "wk_maze"}) {
        SCOPED_TRACE(preset);
        const Measured m = measureTwoDirections(preset);
        EXPECT_GT(m.spectrum.variance, 1e-3);
        EXPECT_GT(m.spectrum.dominantWavelength, 4.0);
        EXPECT_LT(m.spectrum.nyquistFraction, 0.05); // not an unstable step's checkerboard
        EXPECT_LT(m.pair1.re[2], -0.2);
        EXPECT_GT(m.pair2.re[2], 0.2);
        EXPECT_LT(std::fabs(m.combined.re[2]), 0.35); // each pair alone: ~0.8
        EXPECT_GT(m.combined.re[4], 0.2);
    }
}

TEST(WitkinKassMulti, PresetsLoadAndRunBriefly) {
    for (const char* name :
         {"wk_weave", "wk_maze", "wk_triweave", "wk_coral", "wk_twisty_maze", "wk_radial_weave"}) {
        SCOPED_TRACE(name);
        Session s;
        ASSERT_NO_THROW(s = loadPreset(name));
        EXPECT_FALSE(s.description.empty());
        s.width = s.height = 32;
        s.steps = 20;
        const State state = test::runCpu(s);
        for (int c = 0; c < state.channels(); ++c)
            for (std::size_t i = 0; i < state.cellCount(); ++i)
                ASSERT_TRUE(std::isfinite(state.plane(c)[i]));
    }
}
