// Measured behaviour of patterns grown on surfaces (issue 11): the metric
// correction evens out spot areas in world units on a strongly non-uniform
// tessellation (Lo et al. section 3, Witkin & Kass eq. 8), and curvature
// scaling makes spots smaller where the surface bends more (Lo et al. 5.2).
// Turk's spots on the CPU simulator, small atlases, one fixed seed.

#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/mesh/mesh_samples.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/surface_features.hpp"
#include "core/surface/surface_weights.hpp"
#include "core/surface/tile_builder.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

// The unit icosphere with its vertices slid along the meridians so that the
// triangles' areas grow exponentially from the south pole to the north pole,
// by `ratio` in all. A sphere's area is uniform in z (Archimedes), so mapping
// s = (z + 1) / 2 to (e^(k s) - 1) / (e^k - 1), k = ln ratio, scales the area
// element by k e^(k s) / (e^k - 1): ratio times more at the top than at the
// bottom. The shape stays the unit sphere; only the tessellation changes.
TriangleMesh crowdedSphere(int level, double ratio) {
    TriangleMesh mesh = icosphere(level);
    const double k = std::log(ratio);
    for (Eigen::Vector3f& p : mesh.positions) {
        const double s = (double(p.z()) + 1.0) / 2.0;
        const double z = -1.0 + 2.0 * std::expm1(k * s) / std::expm1(k);
        const double r = std::hypot(double(p.x()), double(p.y()));
        const double rNew = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double f = r > 1e-9 ? rNew / r : 0.0;
        p = Eigen::Vector3f(float(p.x() * f), float(p.y() * f), float(z));
    }
    return mesh;
}

struct SpotRun {
    SurfaceTiles tiles;
    std::vector<SurfaceFeature> features;
    FeatureAreaStats stats;
};

// Grows `preset` on `tiles` the way setUpSurface does (length: the preset's,
// spread over the surface's area; the metric correction and curvature scale as
// given) and finds its features, each with the mean |H| under it.
SpotRun grow(SurfaceTiles tiles, const std::string& preset, bool metricCorrection,
             double curvatureStrength, int steps) {
    Session s = loadPreset(preset);
    s.steps = steps;
    SurfaceWeightOptions options;
    options.unitsPerWorld = s.length / std::sqrt(tiles.surfaceArea);
    options.metricCorrection = metricCorrection;
    std::vector<float> scale;
    if (curvatureStrength > 0) {
        scale = curvatureScale(tiles, curvatureStrength);
        options.featureScale = &scale;
    }
    const auto weights = std::make_shared<const AtlasWeights>(surfaceWeights(tiles, options));
    useAtlas(s, tiles.atlas, weights);
    const RunResult result = runSession(s, cpu(), {});
    const int chemical = colormapChemical(s.colormap, s.outputModel());
    std::vector<float> absH(tiles.meanCurvature.size());
    for (std::size_t i = 0; i < absH.size(); ++i)
        absH[i] = std::abs(tiles.meanCurvature[i]);
    SpotRun run;
    run.features = findSurfaceFeatures(*tiles.atlas, result.state.plane(chemical), tiles.texelArea,
                                       tiles.texelPositions, absH);
    run.stats = featureAreaStats(run.features);
    run.tiles = std::move(tiles);
    return run;
}

SurfaceTiles build(const TriangleMesh& mesh, int tiles, int tileSize) {
    TileOptions options;
    options.tiles = tiles;
    options.tileSize = tileSize;
    return buildSurfaceTiles(mesh, options);
}

// Mean feature area over the features whose centroid lies below (south) or
// above (north) the equator.
std::pair<double, double> hemisphereMeans(const std::vector<SurfaceFeature>& features) {
    double sum[2] = {0, 0};
    int count[2] = {0, 0};
    for (const SurfaceFeature& f : features) {
        const int k = f.centroid.z() > 0 ? 1 : 0;
        sum[k] += f.area;
        ++count[k];
    }
    return {count[0] ? sum[0] / count[0] : 0.0, count[1] ? sum[1] / count[1] : 0.0};
}

} // namespace

// Turk's large spots on the unit sphere tessellated 8x denser (in triangle
// area) at the south pole than at the north (960 tiles of 5x5, not simplified).
// Uncorrected, a spot covers about as many texels everywhere, so its area in
// world units follows the texels' (and neighbouring spots merge where texels
// are large); corrected, spots have one size on the surface. Measured with
// seed 1: corrected 79 spots, CV 0.18, mean area south/north 1.04 (82, 0.22
// and 1.03 with the 5-point weights, before the cross term); uncorrected 76
// spots, CV 0.69, south/north 0.37 (CV 0.26 against 1.78 with 6x6 tiles, with
// the 5-point weights). Asserted with margin: the CV drops by at least 2x
// (measured 3.9x) and the hemispheres' mean areas are within 1.5x corrected.
TEST(SurfaceMeasure, MetricCorrectionEvensOutSpotAreas) {
    const TriangleMesh mesh = crowdedSphere(2, 8.0);
    const SurfaceTiles tiles = build(mesh, 3 * int(mesh.triangles.size()), 5);
    ASSERT_EQ(tiles.simplified.triangles.size(), mesh.triangles.size()); // not simplified
    const SpotRun corrected = grow(tiles, "turk_large_spots", true, 0.0, 6000);
    const SpotRun plain = grow(tiles, "turk_large_spots", false, 0.0, 6000);
    const auto [cSouth, cNorth] = hemisphereMeans(corrected.features);
    const auto [pSouth, pNorth] = hemisphereMeans(plain.features);
    std::printf("corrected: %zu spots, mean area %.4g, CV %.3f, south/north %.3f\n",
                corrected.stats.count, corrected.stats.meanArea,
                corrected.stats.coefficientOfVariation, cSouth / cNorth);
    std::printf("uncorrected: %zu spots, mean area %.4g, CV %.3f, south/north %.3f\n",
                plain.stats.count, plain.stats.meanArea, plain.stats.coefficientOfVariation,
                pSouth / pNorth);
    // Turk's large spots on 128 x 128 units give some 80-100 spots; the sphere
    // has the same area in model units.
    EXPECT_GT(corrected.stats.count, 40u);
    EXPECT_LT(corrected.stats.count, 160u);
    EXPECT_LT(corrected.stats.coefficientOfVariation, plain.stats.coefficientOfVariation / 2.0);
    EXPECT_LT(corrected.stats.coefficientOfVariation, 0.5);
    // Spots are as large where the tessellation is dense as where it is coarse.
    EXPECT_GT(cSouth / cNorth, 0.67);
    EXPECT_LT(cSouth / cNorth, 1.5);
    EXPECT_LT(pSouth / pNorth, 0.67 * cSouth / cNorth);
}

// Turk's large spots on an ellipsoid four times as long as it is wide (the
// unit icosphere stretched along x; its triangles are 4:1 and so are the
// tiles built on them; automatic budget, 1,998 tiles of 4x4). Metric-corrected
// diffusion is isotropic on the surface, so the spots must be round there,
// not drawn out along the stretch (issue #34: within 1.2:1). Measured (seed
// 1, 6000 steps): corrected 78 spots, median elongation 1.166, mean |cos| of
// their long axis with x 0.62 (2 / pi = 0.64 for axes at random); uncorrected
// 85 spots, 1.300 and 0.74 (drawn along the stretch), area CV 0.17 against
// 0.52. A render of the same preset on a 4:1 UV sphere (48 x 24 quads) looks
// alike: round spots. The uncorrected run shows that the measure sees a
// stretch.
TEST(SurfaceMeasure, SpotsStayRoundOnAStretchedSurface) {
    TriangleMesh mesh = icosphere(3);
    for (Eigen::Vector3f& p : mesh.positions)
        p.x() *= 4.0f;
    const SurfaceTiles tiles = build(mesh, 0, 4);
    const auto shape = [&](bool metric) {
        const SpotRun run = grow(tiles, "turk_large_spots", metric, 0.0, 6000);
        double along = 0;
        std::size_t counted = 0;
        for (const SurfaceFeature& f : run.features)
            if (f.texels >= 12) {
                along += std::abs(f.majorAxis.x());
                ++counted;
            }
        const double elongation = medianElongation(run.features, 12);
        const double meanAlong = counted ? along / double(counted) : 0.0;
        std::printf("%s: %zu tiles of %dx%d, %zu spots (%zu of 12+ texels), median "
                    "elongation %.3f, mean |major axis . x| %.3f, area CV %.3f\n",
                    metric ? "corrected" : "uncorrected", std::size_t(tiles.atlas->tileCount()),
                    tiles.atlas->tileSize(), tiles.atlas->tileSize(), run.stats.count, counted,
                    elongation, meanAlong, run.stats.coefficientOfVariation);
        return std::pair{elongation, meanAlong};
    };
    const auto [corrected, correctedAlong] = shape(true);
    const auto [plain, plainAlong] = shape(false);
    EXPECT_LT(corrected, 1.2);
    EXPECT_LT(correctedAlong, 0.7);
    EXPECT_GT(plain, 1.25);
    EXPECT_GT(plainAlong, correctedAlong + 0.05);
}

// Curvature-scaled spots on the holes model (automatic budget, 4x4 tiles):
// the correlation between a spot's area and the mean |H| under it, at
// strengths 0, 1 and 2. Measured (seed 1): -0.16 (100 spots), -0.45 (413),
// -0.16 (512, many merged into a labyrinth: CV 2.7), with the shrink-only
// curvatureScale. Too slow for the suite (6 minutes and
// more on 2 cores: the smallest texels set the substeps, tens per step) and
// not monotonic in the strength, so it is disabled; run it with
// --gtest_also_run_disabled_tests to print the numbers.
TEST(SurfaceMeasure, DISABLED_CurvatureScalingShrinksSpotsWhereCurved) {
    const TriangleMesh mesh = sampleMesh("holes", 0);
    const SurfaceTiles tiles = build(mesh, 0, 4);
    for (double strength : {0.0, 1.0, 2.0}) {
        const SpotRun run = grow(tiles, "turk_large_spots", true, strength, 6000);
        std::vector<double> area, curvature;
        for (const SurfaceFeature& f : run.features) {
            area.push_back(f.area);
            curvature.push_back(f.meanValue);
        }
        std::printf("strength %.1f: %zu spots, mean area %.4g, CV %.3f, corr(area, |H|) %.3f\n",
                    strength, run.stats.count, run.stats.meanArea, run.stats.coefficientOfVariation,
                    correlation(area, curvature));
    }
}
