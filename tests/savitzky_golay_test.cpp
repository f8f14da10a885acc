#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/numerics/savitzky_golay.hpp"

using namespace morphogen;

namespace {

double factorial(int n) {
    return n <= 1 ? 1.0 : n * factorial(n - 1);
}

struct Poly {
    // coefficient of x^i y^j at [i * 5 + j]
    std::vector<double> a = std::vector<double>(25, 0.0);
    double operator()(double x, double y) const {
        double v = 0;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 5; ++j)
                v += a[std::size_t(i * 5 + j)] * std::pow(x, i) * std::pow(y, j);
        return v;
    }
};

// A random polynomial using every monomial of the basis (and nothing else).
Poly randomPoly(const SavitzkyGolay& sg, std::mt19937& rng) {
    std::uniform_real_distribution<double> coef(-3.0, 3.0);
    Poly p;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            if (sg.hasDerivative(i, j))
                p.a[std::size_t(i * 5 + j)] = coef(rng);
    return p;
}

// The kernel applied at the origin to samples of p.
double apply(const Kernel5& k, const Poly& p) {
    double v = 0;
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            v += k.at(dx, dy) * p(dx, dy);
    return v;
}

const SgOptions kBases[] = {
    {2, 4, SgBasis::TotalDegree}, {2, 4, SgBasis::TensorProduct}, {2, 3, SgBasis::TotalDegree},
    {1, 2, SgBasis::TotalDegree}, {1, 2, SgBasis::TensorProduct},
};

} // namespace

TEST(SavitzkyGolay, ExactOnEveryPolynomialTheFitRepresents) {
    std::mt19937 rng(1234);
    for (const SgOptions& o : kBases) {
        SCOPED_TRACE(describe(o));
        const SavitzkyGolay sg(o);
        int checked = 0;
        for (int p = 0; p <= 4; ++p)
            for (int q = 0; p + q <= 4; ++q) {
                if (!sg.hasDerivative(p, q))
                    continue;
                const Kernel5 k = sg.derivative(p, q);
                for (int trial = 0; trial < 20; ++trial) {
                    const Poly poly = randomPoly(sg, rng);
                    const double expected =
                        factorial(p) * factorial(q) * poly.a[std::size_t(p * 5 + q)];
                    EXPECT_NEAR(apply(k, poly), expected, 1e-10 * (1 + std::abs(expected)))
                        << "d^" << p + q << "/dx^" << p << "dy^" << q;
                }
                ++checked;
            }
        EXPECT_GE(checked, 5);
    }
}

TEST(SavitzkyGolay, KernelsHaveTheSymmetryOfTheirDerivative) {
    for (const SgOptions& o : kBases) {
        SCOPED_TRACE(describe(o));
        const SavitzkyGolay sg(o);
        for (int p = 0; p <= 4; ++p)
            for (int q = 0; p + q <= 4; ++q) {
                if (!sg.hasDerivative(p, q))
                    continue;
                const Kernel5 k = sg.derivative(p, q);
                const Kernel5 t = sg.derivative(q, p);
                const double sx = p % 2 ? -1 : 1, sy = q % 2 ? -1 : 1;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        EXPECT_NEAR(k.at(-dx, dy), sx * k.at(dx, dy), 1e-12) << p << q;
                        EXPECT_NEAR(k.at(dx, -dy), sy * k.at(dx, dy), 1e-12) << p << q;
                        // Swapping the axes swaps the derivative's orders.
                        EXPECT_NEAR(t.at(dy, dx), k.at(dx, dy), 1e-12) << p << q;
                    }
            }
    }
}

TEST(SavitzkyGolay, OrientationIsPlusXRightPlusYDown) {
    const SavitzkyGolay sg;
    // c(x, y) = y: d/dy is +1, so the weights on larger row indices are positive.
    const Kernel5 dy = sg.derivative(0, 1);
    EXPECT_GT(dy.at(0, 1), 0.0);
    EXPECT_LT(dy.at(0, -1), 0.0);
    const Kernel5 dx = sg.derivative(1, 0);
    EXPECT_GT(dx.at(1, 0), 0.0);
}

TEST(SavitzkyGolay, ClassicThreeByThreeGradient) {
    // Total degree 2 on 3x3: d/dx is the Prewitt-like [-1 0 1] / 6 on every row.
    const Kernel5 k = SavitzkyGolay({1, 2, SgBasis::TotalDegree}).derivative(1, 0);
    for (int dy = -1; dy <= 1; ++dy) {
        EXPECT_NEAR(k.at(-1, dy), -1.0 / 6, 1e-14);
        EXPECT_NEAR(k.at(0, dy), 0.0, 1e-14);
        EXPECT_NEAR(k.at(1, dy), 1.0 / 6, 1e-14);
    }
    EXPECT_EQ(k.radius(), 1);
}

TEST(SavitzkyGolay, TensorProductInterpolatesIntoOneDimensionalDifferences) {
    // The interpolating fit's d^4/dx^4 is the 5-point 4th difference on the centre row.
    const Kernel5 k = SavitzkyGolay({2, 4, SgBasis::TensorProduct}).derivative(4, 0);
    const double row[5] = {1, -4, 6, -4, 1};
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
            EXPECT_NEAR(k.at(dx, dy), dy == 0 ? row[dx + 2] : 0.0, 1e-12);
}

TEST(SavitzkyGolay, RankDeficientBasesAreRejected) {
    // x^5 agrees with 5x^3 - 4x on -2..2.
    EXPECT_THROW(SavitzkyGolay({2, 5, SgBasis::TotalDegree}), InputError);
    EXPECT_THROW(SavitzkyGolay({2, 5, SgBasis::TensorProduct}), InputError);
    // x^3 agrees with x on -1..1.
    EXPECT_THROW(SavitzkyGolay({1, 3, SgBasis::TotalDegree}), InputError);
    EXPECT_THROW(SavitzkyGolay({3, 4, SgBasis::TotalDegree}), InputError);
    EXPECT_THROW(SavitzkyGolay({2, 0, SgBasis::TotalDegree}), InputError);
    try {
        SavitzkyGolay({2, 5, SgBasis::TotalDegree});
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("rank-deficient"), std::string::npos) << e.what();
    }
}

TEST(SavitzkyGolay, DerivativeOutsideTheBasisIsAnError) {
    const SavitzkyGolay sg({1, 2, SgBasis::TotalDegree});
    EXPECT_FALSE(sg.hasDerivative(3, 0));
    EXPECT_THROW(sg.derivative(3, 0), InputError);
}
