#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/numerics/tensor_sequence.hpp"

using namespace morphogen;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseTensorSequence(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

} // namespace

TEST(TensorSequence, ComponentsAndMultiplicities) {
    const auto& c = tensorComponents();
    int sum[5] = {};
    for (const TensorComponent& t : c) {
        EXPECT_EQ(t.nx + t.ny, t.rank);
        sum[t.rank] += t.multiplicity;
    }
    // Multiplicities count all 2^rank index tuples.
    EXPECT_EQ(sum[2], 4);
    EXPECT_EQ(sum[3], 8);
    EXPECT_EQ(sum[4], 16);
    EXPECT_EQ(c[9].multiplicity, 6); // xxyy
}

TEST(TensorSequence, ParserAccepts) {
    const TensorSequence s = parseTensorSequence("xx=1, yy = 2 ,xxxx=-1,yx=0.5,yxy=3e-1");
    EXPECT_EQ(s.get("xx"), 1);
    EXPECT_EQ(s.get("yy"), 2);
    EXPECT_EQ(s.get("xxxx"), -1);
    EXPECT_EQ(s.get("xy"), 0.5); // indices in any order: the tensors are symmetric
    EXPECT_EQ(s.get("xyy"), 0.3);
    EXPECT_EQ(s.get("yyyy"), 0);
    EXPECT_EQ(parseTensorSequence(toString(s)).values, s.values);
    EXPECT_EQ(parseTensorSequence("e").values, tableTwoSet('e').values);
}

TEST(TensorSequence, ParserRejectsNamingTheTokenAndTheAcceptedNames) {
    const std::string unknown = errorOf("xx=1,zz=1");
    EXPECT_NE(unknown.find("'zz'"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("xxyy"), std::string::npos) << unknown;
    EXPECT_NE(errorOf("xx=abc").find("'abc'"), std::string::npos);
    EXPECT_NE(errorOf("xx=1,yy").find("'yy'"), std::string::npos);
    EXPECT_NE(errorOf("xx=1,xx=2").find("twice"), std::string::npos);
    EXPECT_NE(errorOf("xxxxx=1").find("'xxxxx'"), std::string::npos);
    EXPECT_FALSE(errorOf("").empty());
    EXPECT_FALSE(errorOf("g").empty());
    EXPECT_FALSE(errorOf("xx=nan").empty());
    EXPECT_FALSE(errorOf("xx=1,,yy=1").empty());
}

TEST(TensorSequence, TableTwoSetsLoad) {
    for (char l = 'a'; l <= 'f'; ++l) {
        const TensorSequence s = tableTwoSet(l);
        EXPECT_EQ(s.get("xx"), 1) << l;
        EXPECT_EQ(s.get("xy"), 0) << l;
        EXPECT_EQ(s.get("yy"), (l == 'b' || l == 'f') ? 2 : 1) << l;
        EXPECT_EQ(s.hasRank(3), l == 'c') << l;
        EXPECT_EQ(s.hasRank(4), l >= 'd') << l;
    }
    const TensorSequence c = tableTwoSet('c');
    EXPECT_EQ(c.get("xxx"), 1);
    EXPECT_EQ(c.get("xxy"), -1);
    EXPECT_EQ(c.get("xyy"), -1);
    EXPECT_EQ(c.get("yyy"), 1);
    const TensorSequence d = tableTwoSet('d'), e = tableTwoSet('e');
    EXPECT_EQ(d.get("xxxx"), 1);
    EXPECT_EQ(d.get("xxyy"), -1);
    EXPECT_EQ(d.get("yyyy"), 1);
    EXPECT_EQ(e.get("xxxx"), -1);
    EXPECT_EQ(e.get("xxyy"), 1);
    EXPECT_EQ(e.get("yyyy"), -1);
    EXPECT_EQ(tableTwoSet('F').values,
              parseTensorSequence("xx=1,yy=2,xxxx=-1,xxyy=1,yyyy=-1").values);
    EXPECT_THROW(tableTwoSet('g'), InputError);
}

TEST(TensorSequence, RankTwoIsotropicIsTheFivePointLaplacian) {
    const Kernel5 k = generalizedDiffusionKernel(parseTensorSequence("xx=1,yy=1"));
    Kernel5 expected;
    expected.at(0, 0) = -4;
    expected.at(1, 0) = expected.at(-1, 0) = expected.at(0, 1) = expected.at(0, -1) = 1;
    EXPECT_EQ(k.w, expected.w);
    EXPECT_EQ(k.radius(), 1);
}

TEST(TensorSequence, MixedSecondDerivativeIsTheCornerStencil) {
    // 2 D_xy d_xy with the corners / 4: Witkin-Kass eq. 29's off-diagonal entries.
    const Kernel5 k = generalizedDiffusionKernel(parseTensorSequence("xy=1"));
    EXPECT_EQ(k.at(1, 1), 0.5);
    EXPECT_EQ(k.at(-1, -1), 0.5);
    EXPECT_EQ(k.at(1, -1), -0.5);
    EXPECT_EQ(k.at(-1, 1), -0.5);
    EXPECT_EQ(k.at(0, 0), 0.0);
}

TEST(TensorSequence, FittedOperatorIsExactOnQuartics) {
    // With SG kernels for every rank, the assembled kernel applied to any
    // quartic equals eq. 21 applied analytically: checks multiplicities and signs.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-2, 2);
    GeneralizedOperatorOptions o;
    o.centralSecondDerivatives = false;
    for (int trial = 0; trial < 10; ++trial) {
        TensorSequence s;
        for (double& v : s.values)
            v = u(rng);
        double a[5][5] = {}; // c(x, y) = sum a[i][j] x^i y^j, total degree <= 4
        for (int i = 0; i <= 4; ++i)
            for (int j = 0; i + j <= 4; ++j)
                a[i][j] = u(rng);
        const Kernel5 k = generalizedDiffusionKernel(s, o);
        double applied = 0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                double c = 0;
                for (int i = 0; i <= 4; ++i)
                    for (int j = 0; i + j <= 4; ++j)
                        c += a[i][j] * std::pow(dx, i) * std::pow(dy, j);
                applied += k.at(dx, dy) * c;
            }
        // d^(nx+ny) c / dx^nx dy^ny at 0 is nx! ny! a[nx][ny].
        const double f[5] = {1, 1, 2, 6, 24};
        double expected = 0;
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            const TensorComponent& t = tensorComponents()[i];
            expected += t.multiplicity * s.values[i] * f[t.nx] * f[t.ny] * a[t.nx][t.ny];
        }
        EXPECT_NEAR(applied, expected, 1e-9 * (1 + std::abs(expected)));
    }
}

TEST(TensorSequence, ThreeByThreeWindowCannotGiveHigherRanks) {
    GeneralizedOperatorOptions o;
    o.sg = {1, 2, SgBasis::TotalDegree};
    EXPECT_NO_THROW(generalizedDiffusionKernel(tableTwoSet('b'), o));
    EXPECT_THROW(generalizedDiffusionKernel(tableTwoSet('d'), o), InputError);
}
