#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/numerics/propagator.hpp"

using namespace morphogen;

namespace {

std::vector<double> peaksOf(const TensorSequence& s) {
    return findAngularPeaks(sampleAngular(Propagator(s, 0.1), 1.0));
}

void expectPeaks(const std::vector<double>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i)
        EXPECT_NEAR(got[i], want[i], 0.5) << i;
}

} // namespace

TEST(Propagator, IsotropicHasNoPreferredDirection) {
    EXPECT_TRUE(peaksOf(tableTwoSet('a')).empty());
}

TEST(Propagator, AnisotropicGaussianPeaksAlongTheLargerDiffusivity) {
    expectPeaks(peaksOf(tableTwoSet('b')), {90, 270});
}

TEST(Propagator, RankFourSetsAreAxisAlignedOrDiagonal) {
    expectPeaks(peaksOf(tableTwoSet('d')), {0, 90, 180, 270});
    expectPeaks(peaksOf(tableTwoSet('e')), {45, 135, 225, 315});
}

TEST(Propagator, RankThreeSetIsThreeFold) {
    // D3 : r^3 = cos 3t - sin 3t = sqrt 2 cos(3t + 45 deg), entering with a
    // minus sign: three lobes 120 degrees apart, i.e. three orientations
    // (mod 180) 60 degrees apart: 45, 105, 165.
    expectPeaks(peaksOf(tableTwoSet('c')), {45, 165, 285});
}

TEST(Propagator, IsotropicRankFourDampingKeepsThePeaks) {
    // The stabilisation's Laplacian^2 term is the isotropic rank-4 tensor.
    for (char l : {'d', 'e', 'f'}) {
        TensorSequence s = tableTwoSet(l);
        const std::vector<double> before = peaksOf(s);
        const double eta = 0.5;
        s.set("xxxx", s.get("xxxx") - eta);
        s.set("xxyy", s.get("xxyy") - eta / 3);
        s.set("yyyy", s.get("yyyy") - eta);
        expectPeaks(peaksOf(s), before);
    }
}

TEST(Propagator, NeedsAPositiveDefiniteRankTwoTensor) {
    EXPECT_THROW(Propagator(parseTensorSequence("xxxx=1")), InputError);
    EXPECT_THROW(Propagator(parseTensorSequence("xx=1,yy=1,xy=2")), InputError);
    EXPECT_THROW(Propagator(tableTwoSet('a'), 0.0), InputError);
}

TEST(Propagator, PeakFinderWrapsAround) {
    std::vector<double> f(360);
    for (int i = 0; i < 360; ++i)
        f[std::size_t(i)] = std::cos((i - 359.6) * 3.14159265358979 / 180);
    expectPeaks(findAngularPeaks(f), {359.6});
}

TEST(Propagator, PlotIsDrawn) {
    const std::vector<float> rgb =
        renderPolarPlot(sampleAngular(Propagator(tableTwoSet('d')), 1), 128);
    ASSERT_EQ(rgb.size(), std::size_t(128 * 128 * 3));
    int red = 0;
    for (std::size_t i = 0; i < rgb.size(); i += 3)
        red += rgb[i] > 0.6f && rgb[i + 1] < 0.4f;
    EXPECT_GT(red, 200);
}

TEST(Propagator, AnEmptyPlotIsNotIsotropic) {
    // At a radius far out in the tails the density underflows to 0 everywhere:
    // nothing to plot, and no direction to read (not "isotropic").
    const Propagator p(tableTwoSet('c'), 0.1);
    EXPECT_EQ(angularShape(sampleAngular(p, 100.0)), AngularShape::Empty);
    EXPECT_EQ(angularShape(std::vector<double>(360, -1e-3)), AngularShape::Empty);
    std::vector<double> withNan(360, 1.0);
    withNan[7] = std::nan("");
    EXPECT_EQ(angularShape(withNan), AngularShape::Empty);
    EXPECT_EQ(angularShape(sampleAngular(Propagator(tableTwoSet('a'), 0.1), 1.0)),
              AngularShape::Isotropic);
    EXPECT_EQ(angularShape(sampleAngular(p, 1.0)), AngularShape::Directional);
    // The width the message suggests radii from: sqrt(2 tau D2) for D2 = I.
    EXPECT_NEAR(Propagator(tableTwoSet('a'), 0.1).width(), std::sqrt(0.2), 1e-12);
}
