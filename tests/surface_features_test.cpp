// Features on an atlas: regions joined through the connectivity map (a spot
// across a tile edge is one feature), areas and centroids weighted by the
// texels' areas, and the statistics the surface reports use.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/domain/atlas.hpp"
#include "core/surface/surface_features.hpp"

namespace morphogen {
namespace {

// The cube's texel centres in [0, 1]^3 (the face frames of Atlas::cube).
std::vector<Eigen::Vector3f> cubePositions(const Atlas& atlas) {
    // Face t: corner 0 and the directions of u and v, from Atlas::cube's corner lists.
    const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                             {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
    auto vertex = [](int v) {
        return Eigen::Vector3f(float(v & 1), float((v >> 1) & 1), float((v >> 2) & 1));
    };
    const int n = atlas.tileSize();
    std::vector<Eigen::Vector3f> p(atlas.cellCount(), Eigen::Vector3f::Zero());
    for (int t = 0; t < 6; ++t) {
        const Eigen::Vector3f o = vertex(faces[t][0]);
        const Eigen::Vector3f du = vertex(faces[t][1]) - o, dv = vertex(faces[t][3]) - o;
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u)
                p[atlas.tileCell(t, u, v)] = o + du * ((u + 0.5f) / n) + dv * ((v + 0.5f) / n);
    }
    return p;
}

TEST(SurfaceFeatures, ASpotAcrossTileEdgesIsOneFeatureWithItsArea) {
    const Atlas atlas = Atlas::cube(8);
    const auto position = cubePositions(atlas);
    std::vector<float> area(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            area[i] = 1.0f / 64.0f;
    // A disc of radius 0.3 around the cube corner (1, 1, 1): it covers three faces.
    // A second one around the face centre of -x.
    std::vector<float> plane(atlas.cellCount(), 0.0f);
    const Eigen::Vector3f corner(1, 1, 1), face(0, 0.5f, 0.5f);
    std::size_t cornerTexels = 0, faceTexels = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        if ((position[i] - corner).norm() < 0.3f) {
            plane[i] = 1;
            ++cornerTexels;
        } else if ((position[i] - face).norm() < 0.2f) {
            plane[i] = 1;
            ++faceTexels;
        }
    }
    ASSERT_GT(cornerTexels, 9u);
    const auto features = findSurfaceFeatures(atlas, plane.data(), area, position);
    ASSERT_EQ(features.size(), 2u);

    std::size_t total = 0;
    for (const SurfaceFeature& f : features) {
        total += f.texels;
        EXPECT_NEAR(f.area, f.texels / 64.0, 1e-9);
    }
    EXPECT_EQ(total, cornerTexels + faceTexels);
    // The corner spot's centroid lies on the cube's diagonal, the face spot's at the face centre.
    const bool cornerFirst = features[0].centroid.x() > 0.5;
    const SurfaceFeature& c = features[cornerFirst ? 0 : 1];
    const SurfaceFeature& f = features[cornerFirst ? 1 : 0];
    EXPECT_EQ(c.texels, cornerTexels);
    EXPECT_EQ(f.texels, faceTexels);
    EXPECT_NEAR(c.centroid.x(), c.centroid.y(), 1e-6);
    EXPECT_NEAR(c.centroid.y(), c.centroid.z(), 1e-6);
    EXPECT_GT(c.centroid.x(), 0.85);
    EXPECT_NEAR((f.centroid - face.cast<double>()).norm(), 0.0, 1e-6);
}

// A filled ellipse with semi-axes a and b has covariance a^2/4 and b^2/4
// along them, so its elongation is a / b; on a face of 32 x 32 texels the
// discretisation moves it by a few percent. The disc is round; the spot over
// the cube's edge bends, which must not count as elongation.
TEST(SurfaceFeatures, ElongationIsTheRatioOfTheSpotsAxes) {
    const Atlas atlas = Atlas::cube(32);
    const auto position = cubePositions(atlas);
    std::vector<float> area(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            area[i] = 1.0f / 1024.0f;
    std::vector<float> plane(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        const Eigen::Vector3f p = position[i];
        // On the face x = 0: an ellipse 0.3 by 0.1 along z; on the face
        // x = 1: a disc of radius 0.15 round a point 0.1 from the edge with
        // y = 1, so that it folds over onto the face y = 1.
        const bool ellipse =
            p.x() == 0.0f &&
            std::pow((p.z() - 0.5f) / 0.3f, 2.0f) + std::pow((p.y() - 0.5f) / 0.1f, 2.0f) < 1.0f;
        const Eigen::Vector3f centre(1.0f, 0.9f, 0.5f);
        const bool folded = std::abs(p.x() - 1.0f) < 1e-6f || std::abs(p.y() - 1.0f) < 1e-6f;
        const Eigen::Vector3f flat(1.0f, p.y() + (1.0f - p.x()), p.z()); // unfolded onto x = 1
        const bool disc = folded && (flat - centre).norm() < 0.15f;
        plane[i] = ellipse || disc ? 1.0f : 0.0f;
    }
    const auto features = findSurfaceFeatures(atlas, plane.data(), area, position);
    ASSERT_EQ(features.size(), 2u);
    const bool ellipseFirst = features[0].centroid.x() < 0.5;
    const SurfaceFeature& e = features[ellipseFirst ? 0 : 1];
    const SurfaceFeature& d = features[ellipseFirst ? 1 : 0];
    EXPECT_NEAR(e.elongation, 3.0, 0.15);
    EXPECT_GT(std::abs(e.majorAxis.z()), 0.99);
    // Folded over the edge, the disc's extent in 3D is not a flat disc's: a
    // spot a fifth as wide as the face keeps its elongation below 1.2.
    EXPECT_LT(d.elongation, 1.2);
    EXPECT_NEAR(medianElongation(features, 1), std::max(e.elongation, d.elongation), 1e-12);
    EXPECT_EQ(medianElongation(features, 100000), 0.0);
}

TEST(SurfaceFeatures, AreaStatisticsAndCorrelation) {
    std::vector<SurfaceFeature> features(4);
    const double areas[4] = {1, 2, 3, 2};
    for (int i = 0; i < 4; ++i)
        features[i].area = areas[i];
    const FeatureAreaStats s = featureAreaStats(features);
    EXPECT_EQ(s.count, 4u);
    EXPECT_DOUBLE_EQ(s.meanArea, 2.0);
    EXPECT_NEAR(s.coefficientOfVariation, std::sqrt(2.0 / 3.0) / 2.0, 1e-12);
    EXPECT_NEAR(correlation({1, 2, 3, 4}, {2, 4, 6, 8.5}), 0.998, 0.002);
    EXPECT_NEAR(correlation({1, 2, 3, 4}, {4, 3, 2, 1}), -1.0, 1e-12);
    EXPECT_EQ(correlation({1, 1, 1}, {1, 2, 3}), 0.0);
}

} // namespace
} // namespace morphogen
