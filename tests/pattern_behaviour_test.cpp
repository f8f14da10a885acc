// Behaviour, measured on the CPU reference backend: the patterns each preset
// is for, by statistics rather than pixels.

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/analysis/pattern_stats.hpp"
#include "test_support.hpp"

using namespace morphogen;

TEST(PatternBehaviour, TurkLargeSpotsHaveAClearlyLongerWavelengthThanSmallSpots) {
    const State large = test::runCpu(test::smallSession("turk_large_spots", 128, 6000));
    const State small = test::runCpu(test::smallSession("turk_small_spots", 128, 3000));
    const SpectrumStats l = spectrumStats(large, 1), s = spectrumStats(small, 1);
    std::printf("turk wavelength: large %.2f, small %.2f cells; nyquist %.4f, %.4f\n",
                l.dominantWavelength, s.dominantWavelength, l.nyquistFraction, s.nyquistFraction);
    // Measured 14.2 and 7.1 cells when the presets were tuned.
    EXPECT_GT(l.dominantWavelength, 1.6 * s.dominantWavelength)
        << l.dominantWavelength << " vs " << s.dominantWavelength;
    // Both are real patterns, not the 2-cell checkerboard of an unstable step.
    EXPECT_GT(s.dominantWavelength, 4.5);
    EXPECT_GT(l.variance, 1.0);
    EXPECT_GT(s.variance, 1.0);
    EXPECT_LT(l.nyquistFraction, 0.05);
    EXPECT_LT(s.nyquistFraction, 0.05);
}

TEST(PatternBehaviour, NyquistMeasureFlagsACheckerboard) {
    // The statistic the other tests rely on must see a checkerboard.
    State board(32, 32, 1);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            board.at(0, x, y) = float((x + y) % 2);
    const SpectrumStats st = spectrumStats(board, 0);
    EXPECT_GT(st.nyquistFraction, 0.9);
    EXPECT_LT(st.dominantWavelength, 2.1);
}

TEST(PatternBehaviour, GrayScottUniformDecaysWhileMitosisKeepsStructure) {
    const State uniform = test::runCpu(test::smallSession("gs_uniform", 96, 4000));
    const State mitosis = test::runCpu(test::smallSession("gs_mitosis", 96, 4000));
    const SpectrumStats u = spectrumStats(uniform, 1), m = spectrumStats(mitosis, 1);
    std::printf("gray-scott variance: uniform %.3g, mitosis %.3g\n", u.variance, m.variance);
    EXPECT_LT(u.variance, 1e-10);
    EXPECT_GT(m.variance, 1e-3);
    EXPECT_LT(m.nyquistFraction, 0.05);
}

TEST(PatternBehaviour, McGrawSteadyStateStaysPutAndBeta15Patterns) {
    const State steady = test::runCpu(test::smallSession("mcgraw_steady", 32, 500));
    for (std::size_t i = 0; i < steady.cellCount(); ++i) {
        ASSERT_FLOAT_EQ(steady.plane(0)[i], 4.0f);
        ASSERT_FLOAT_EQ(steady.plane(1)[i], 4.0f);
    }
    const State pattern = test::runCpu(test::smallSession("mcgraw_turing", 64, 6000));
    const SpectrumStats p = spectrumStats(pattern, 0);
    std::printf("mcgraw: wavelength %.2f, variance %.3g\n", p.dominantWavelength, p.variance);
    EXPECT_GT(p.variance, 1.0);
    EXPECT_GT(p.dominantWavelength, 5.0);
    EXPECT_LT(p.nyquistFraction, 0.05);
}

TEST(PatternBehaviour, PeriodicOutputTilesSeamlessly) {
    // Across the wrap seam (last column -> first column) the field changes no
    // more than between ordinary neighbours; with clamped edges the seam is a
    // cut and its jump is much larger.
    auto seamRatio = [](EdgeMode edges) {
        Session s = test::smallSession("gs_coral", 96, 4000);
        s.edges = edges;
        const State st = test::runCpu(s);
        double seam = 0, interior = 0;
        for (int y = 0; y < st.height(); ++y) {
            seam += std::fabs(st.at(1, st.width() - 1, y) - st.at(1, 0, y));
            for (int x = 0; x + 1 < st.width(); ++x)
                interior += std::fabs(st.at(1, x + 1, y) - st.at(1, x, y));
        }
        for (int x = 0; x < st.width(); ++x)
            seam += std::fabs(st.at(1, x, st.height() - 1) - st.at(1, x, 0));
        interior /= double(st.width() - 1) * st.height();
        seam /= double(st.width() + st.height());
        return seam / interior;
    };
    const double periodic = seamRatio(EdgeMode::Periodic);
    const double clamped = seamRatio(EdgeMode::Clamped);
    std::printf("seam/interior jump: periodic %.3f, clamped %.3f\n", periodic, clamped);
    EXPECT_LT(periodic, 1.5);
    EXPECT_GT(periodic, 0.5);
    EXPECT_GT(clamped, 2.0 * periodic);
}

TEST(PatternBehaviour, FeatureCountCountsSpotsAcrossThePeriodicSeam) {
    State st(20, 20, 1);
    auto disc = [&](int cx, int cy) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                st.at(0, (cx + dx + 20) % 20, (cy + dy + 20) % 20) = 1.0f;
    };
    disc(5, 5);
    disc(12, 14);
    disc(0, 10); // straddles the left/right seam: one spot, not two
    EXPECT_EQ(featureCount(st, 0, true), 3);
    EXPECT_EQ(featureCount(st, 0, false), 4);
    st.at(0, 17, 2) = 1.0f; // a single cell is noise
    EXPECT_EQ(featureCount(st, 0, true), 3);
}
