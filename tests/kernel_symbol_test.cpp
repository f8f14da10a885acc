#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/numerics/kernel_symbol.hpp"
#include "core/numerics/tensor_sequence.hpp"

using namespace morphogen;

namespace {

constexpr double kPi = 3.14159265358979323846;

Kernel5 fivePoint() {
    return generalizedDiffusionKernel(parseTensorSequence("xx=1,yy=1"));
}

// u <- (I + dt A) u on a periodic n x n grid, A = convolution by k.
std::vector<double> step(const Kernel5& k, const std::vector<double>& u, int n, double dt) {
    std::vector<double> out(u.size());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            double a = 0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx)
                    a += k.at(dx, dy) * u[std::size_t(((y + dy + n) % n) * n + (x + dx + n) % n)];
            out[std::size_t(y * n + x)] = u[std::size_t(y * n + x)] + dt * a;
        }
    return out;
}

// Power iteration: the operator is circulant, hence normal, so the growth of
// the norm per step converges to the spectral radius.
double powerIteration(const Kernel5& k, int n, double dt, int iterations) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> v(std::size_t(n * n));
    for (double& x : v)
        x = u(rng);
    double ratio = 0;
    for (int i = 0; i < iterations; ++i) {
        double before = 0, after = 0;
        for (double x : v)
            before += x * x;
        v = step(k, v, n, dt);
        for (double x : v)
            after += x * x;
        ratio = std::sqrt(after / before);
        for (double& x : v)
            x /= std::sqrt(after);
    }
    return ratio;
}

} // namespace

TEST(KernelSymbol, FivePointSymbol) {
    const Kernel5 k = fivePoint();
    EXPECT_NEAR(std::abs(kernelSymbol(k, 0, 0)), 0.0, 1e-15);
    EXPECT_NEAR(kernelSymbol(k, kPi, 0).real(), -4.0, 1e-12);
    EXPECT_NEAR(kernelSymbol(k, kPi, kPi).real(), -8.0, 1e-12);
    EXPECT_NEAR(kernelSymbol(k, 0.3, 1.1).imag(), 0.0, 1e-12);
}

TEST(KernelSymbol, SpectralRadiusMatchesPowerIteration) {
    struct Case {
        Kernel5 k;
        double dt;
    };
    const Case cases[] = {
        {fivePoint(), 0.3},                                  // isotropic, past its dt limit
        {generalizedDiffusionKernel(tableTwoSet('c')), 0.5}, // rank 3: complex eigenvalues
        {generalizedDiffusionKernel(tableTwoSet('d')), 0.1}, // rank 4: Re(lambda) > 0
        {generalizedDiffusionKernel(tableTwoSet('f')), 0.2},
    };
    for (const Case& c : cases) {
        const double symbolic = analyzeExplicitStep(c.k, 16, 16, c.dt).spectralRadius;
        const double iterated = powerIteration(c.k, 16, c.dt, 3000);
        EXPECT_GT(symbolic, 1.0);
        EXPECT_NEAR(iterated, symbolic, 2e-3 * symbolic) << c.dt;
    }
}

TEST(KernelSymbol, IsotropicLargestStableDtIsQuarterOverD) {
    for (double d : {1.0, 2.0, 0.25}) {
        const ExplicitStepReport r = analyzeExplicitStep(fivePoint().scaled(d), 16, 16, 0.1);
        ASSERT_TRUE(r.maxStableDt);
        EXPECT_NEAR(*r.maxStableDt, 0.25 / d, 1e-12);
        EXPECT_NEAR(r.maxRealPart, 0.0, 1e-12); // the conserved mean
        // Just inside and just outside the limit.
        EXPECT_LE(
            analyzeExplicitStep(fivePoint().scaled(d), 16, 16, 0.999 * 0.25 / d).spectralRadius,
            1.0 + 1e-12);
        EXPECT_GT(
            analyzeExplicitStep(fivePoint().scaled(d), 16, 16, 1.001 * 0.25 / d).spectralRadius,
            1.0);
    }
}

TEST(KernelSymbol, RankFourSetsGrowAndStabilisationStopsIt) {
    for (char l : {'d', 'e', 'f'}) {
        SCOPED_TRACE(std::string(1, l));
        const Kernel5 k = generalizedDiffusionKernel(tableTwoSet(l));
        const ExplicitStepReport raw = analyzeExplicitStep(k, 0.1);
        EXPECT_GT(raw.maxRealPart, 0.1);
        EXPECT_FALSE(raw.maxStableDt);

        const StabilizedKernel s = stabilizeKernel(k);
        EXPECT_GT(s.eta, 0.0);
        for (int n : {16, 37, 64, 100, 256}) {
            const ExplicitStepReport r = analyzeExplicitStep(s.kernel, n, n + 3, 0.1);
            EXPECT_LE(r.maxRealPart, 1e-12) << n;
            ASSERT_TRUE(r.maxStableDt) << n;
            EXPECT_GT(*r.maxStableDt, 0.0);
        }
        // Conservative: the mean is still neither created nor destroyed.
        double sum = 0;
        for (double w : s.kernel.w)
            sum += w;
        EXPECT_NEAR(sum, 0.0, 1e-12);
    }
}

TEST(KernelSymbol, StableKernelsAreLeftAlone) {
    for (char l : {'a', 'b', 'c'}) {
        const Kernel5 k = generalizedDiffusionKernel(tableTwoSet(l));
        const StabilizedKernel s = stabilizeKernel(k);
        EXPECT_EQ(s.eta, 0.0) << l;
        EXPECT_EQ(s.kernel.w, k.w) << l;
    }
}

TEST(KernelSymbol, BiharmonicIsTheLaplacianSquared) {
    const Kernel5 b = biharmonicKernel();
    EXPECT_EQ(b.at(0, 0), 20);
    EXPECT_EQ(b.at(1, 0), -8);
    EXPECT_EQ(b.at(1, 1), 2);
    EXPECT_EQ(b.at(2, 0), 1);
    EXPECT_EQ(b.at(2, 1), 0);
    const double s = 4 * std::sin(0.35) * std::sin(0.35) + 4 * std::sin(0.2) * std::sin(0.2);
    EXPECT_NEAR(kernelSymbol(b, 0.7, 0.4).real(), s * s, 1e-12);
}
