// The sweep classifier on fields built to be one class, then on real runs of
// the presets named for each class (CPU backend).

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/analysis/pattern_classifier.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSize = 128;
constexpr double kWavelength = 16; // divides kSize: lattices tile the periodic grid

State makeField(const std::function<double(int, int)>& value, int size = kSize) {
    State s(size, size, 1);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            s.at(0, x, y) = float(value(x, y));
    return s;
}

// Offset of a coordinate from the nearest lattice line (centres at spacing/2).
double latticeOffset(int c, double spacing) {
    return std::fmod(double(c), spacing) - 0.5 * spacing + 0.5;
}

// Gaussian bumps on a square lattice; sigma 3 against spacing 16 keeps them
// apart, as Turing spots are.
double dot(int x, int y) {
    const double dx = latticeOffset(x, kWavelength), dy = latticeOffset(y, kWavelength);
    return std::exp(-(dx * dx + dy * dy) / (2 * 3.0 * 3.0));
}

// Ridges of the same profile, running along y.
double ridge(int x) {
    const double dx = latticeOffset(x, kWavelength);
    return std::exp(-dx * dx / (2 * 3.0 * 3.0));
}

PatternClass classify(const State& s, const char* name, const ChemicalSpec* sane = nullptr,
                      int chemical = 0) {
    const PatternStats st = measurePattern(s, chemical);
    const PatternClass c = classifyPattern(st, sane);
    std::printf("%-22s mean %.4g var %.3g wl %.2f nyq %.3f orient %.3f features %d minority %.3f "
                "area %.1f largest %.3f elong %.2f elongated %.3f -> %s\n",
                name, st.mean, st.variance, st.dominantWavelength, st.nyquistFraction,
                st.orientationStrength, st.featureCount, st.minorityFraction, st.meanFeatureArea,
                st.largestFeatureShare, st.elongation, st.elongatedShare, toString(c).c_str());
    return c;
}

} // namespace

TEST(PatternClassifier, NamesEveryClass) {
    EXPECT_EQ(toString(PatternClass::Uniform), "uniform");
    EXPECT_EQ(toString(PatternClass::Spots), "spots");
    EXPECT_EQ(toString(PatternClass::Stripes), "stripes/labyrinth");
    EXPECT_EQ(toString(PatternClass::Mixed), "mixed");
    EXPECT_EQ(toString(PatternClass::Unstable), "unstable");
}

TEST(PatternClassifier, FlatFieldsAreUniform) {
    EXPECT_EQ(classify(makeField([](int, int) { return 0.5; }), "flat"), PatternClass::Uniform);
    EXPECT_EQ(classify(makeField([](int, int) { return 0.0; }), "flat zero"),
              PatternClass::Uniform);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-1e-7, 1e-7);
    EXPECT_EQ(classify(makeField([&](int, int) { return 0.5 + noise(rng); }), "flat + 1e-7 noise"),
              PatternClass::Uniform);
}

// A dot lattice far too faint to see: the feature finder still counts its dots (it thresholds
// relative to the plane's own range), but the class is uniform, so the reported stats must not
// list features, a wavelength or an orientation next to "uniform".
TEST(PatternClassifier, UniformStatsListNoStructure) {
    const State faint = makeField([](int x, int y) { return 0.5 + 1e-4 * dot(x, y); });
    const PatternStats measured = measurePattern(faint, 0);
    ASSERT_EQ(classifyPattern(measured), PatternClass::Uniform);
    ASSERT_GT(measured.featureCount, 0); // the contradiction the report must not carry
    const PatternStats reported = statsForClass(measured, PatternClass::Uniform);
    EXPECT_EQ(reported.featureCount, 0);
    EXPECT_EQ(reported.dominantWavelength, 0);
    EXPECT_EQ(reported.orientationStrength, 0);
    EXPECT_EQ(reported.meanFeatureArea, 0);
    EXPECT_EQ(reported.elongation, 0);
    EXPECT_EQ(reported.mean, measured.mean);
    EXPECT_EQ(reported.variance, measured.variance);

    // Other classes keep what was measured.
    const State dots = makeField(dot);
    const PatternStats spots = measurePattern(dots, 0);
    ASSERT_EQ(classifyPattern(spots), PatternClass::Spots);
    EXPECT_EQ(statsForClass(spots, PatternClass::Spots).featureCount, spots.featureCount);
    EXPECT_EQ(statsForClass(spots, PatternClass::Spots).dominantWavelength,
              spots.dominantWavelength);
}

TEST(PatternClassifier, DotLatticeIsSpotsEitherWayUp) {
    EXPECT_EQ(classify(makeField(dot), "light dots"), PatternClass::Spots);
    EXPECT_EQ(classify(makeField([](int x, int y) { return 1.0 - dot(x, y); }), "dark dots"),
              PatternClass::Spots);
    // Off the lattice and at another scale: spacing 16 does not divide 120.
    EXPECT_EQ(classify(makeField(dot, 120), "dots, 120 grid"), PatternClass::Spots);
}

TEST(PatternClassifier, SinusoidalStripesAreStripesAtAnyAngle) {
    for (double degrees : {0.0, 30.0, 45.0, 90.0}) {
        const double a = degrees * kPi / 180, k = 2 * kPi / kWavelength;
        const State s = makeField(
            [&](int x, int y) { return std::cos(k * (x * std::cos(a) + y * std::sin(a))); });
        const std::string name = "stripes " + std::to_string(int(degrees)) + " deg";
        EXPECT_EQ(classify(s, name.c_str()), PatternClass::Stripes) << degrees;
    }
}

TEST(PatternClassifier, LabyrinthIsStripes) {
    // The sign of a sum of random-phase plane waves of one wavelength is a
    // maze. Integer wave vectors of length sqrt(65) (wavelength 15.9) keep
    // it periodic.
    const int waves[8][2] = {{8, 1}, {1, 8}, {7, 4}, {4, 7}, {-8, 1}, {-1, 8}, {-7, 4}, {-4, 7}};
    for (unsigned seed = 1; seed <= 6; ++seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> phase(0, 2 * kPi);
        double phases[8];
        for (double& p : phases)
            p = phase(rng);
        const State s = makeField([&](int x, int y) {
            double sum = 0;
            for (int i = 0; i < 8; ++i)
                sum += std::cos(2 * kPi * (waves[i][0] * x + waves[i][1] * y) / kSize + phases[i]);
            return std::tanh(4 * sum);
        });
        const std::string name = "labyrinth seed " + std::to_string(seed);
        EXPECT_EQ(classify(s, name.c_str()), PatternClass::Stripes) << seed;
    }
}

TEST(PatternClassifier, NonFiniteOutOfRangeAndCheckerboardAreUnstable) {
    State nan = makeField(dot);
    nan.at(0, 40, 50) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(classify(nan, "dots + one NaN"), PatternClass::Unstable);
    State inf = makeField(dot);
    inf.at(0, 3, 4) = std::numeric_limits<float>::infinity();
    EXPECT_EQ(classify(inf, "dots + one Inf"), PatternClass::Unstable);

    ChemicalSpec sane;
    sane.saneMin = -1.0f;
    sane.saneMax = 2.0f;
    EXPECT_EQ(classify(makeField(dot), "dots in [-1, 2]", &sane), PatternClass::Spots);
    EXPECT_EQ(classify(makeField([](int x, int y) { return 3 * dot(x, y); }), "dots x3 in [-1, 2]",
                       &sane),
              PatternClass::Unstable);

    EXPECT_EQ(classify(makeField([](int x, int y) { return double((x + y) % 2); }), "checkerboard"),
              PatternClass::Unstable);
    // A checkerboard growing on top of a pattern, as a too-long step leaves it.
    EXPECT_EQ(classify(makeField([](int x, int y) { return dot(x, y) + ((x + y) % 2 ? 0.8 : 0); }),
                       "dots + checkerboard"),
              PatternClass::Unstable);
}

TEST(PatternClassifier, HalfDotsHalfStripesIsMixed) {
    // Comparable areas of each: six columns of dots, two ridges.
    const State s = makeField([](int x, int y) { return x < 96 ? dot(x, y) : ridge(x); });
    EXPECT_EQ(classify(s, "dots | ridges"), PatternClass::Mixed);
}

TEST(PatternClassifier, PresetsClassifyAsTheirNames) {
    struct Case {
        const char* preset;
        int size, steps, chemical;
        PatternClass expected;
    };
    const Case cases[] = {
        {"turk_small_spots", 96, 1500, 1, PatternClass::Spots},
        {"gs_mitosis", 96, 4000, 1, PatternClass::Spots},
        {"gs_coral", 96, 3000, 1, PatternClass::Stripes},
        {"gs_worms", 96, 4000, 1, PatternClass::Stripes},
        {"gs_uniform", 96, 4000, 1, PatternClass::Uniform},
    };
    for (const Case& c : cases) {
        const Session session = test::smallSession(c.preset, c.size, c.steps);
        const State st = test::runCpu(session);
        const ChemicalSpec& sane = session.reactionModel().chemicals()[std::size_t(c.chemical)];
        EXPECT_EQ(classify(st, c.preset, &sane, c.chemical), c.expected) << c.preset;
    }
}
