// Parameter maps on a mesh (param_map.hpp: evaluateSurfaceParamMap, and the
// engine's per-cell planes of a session on a surface): fields in space, not in
// the atlas texture's x and y.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/session/param_map.hpp"
#include "core/session/session.hpp"
#include "core/sim/simulator.hpp"
#include "core/surface/surface_setup.hpp"

using namespace morphogen;

namespace {

// A line of points along x from -1 to 1 (y = 2x, z = 0), the last one unused.
struct Points {
    std::vector<std::array<float, 3>> positions;
    std::vector<bool> used;
};
Points line(int n) {
    Points p;
    for (int i = 0; i < n; ++i) {
        const float x = -1.0f + 2.0f * float(i) / float(n - 1);
        p.positions.push_back({x, 2.0f * x, 0.0f});
        p.used.push_back(true);
    }
    p.positions.push_back({50.0f, 50.0f, 50.0f});
    p.used.push_back(false);
    return p;
}

ParamMapSpec spec(ParamMapSpec::Field field, float min, float max) {
    ParamMapSpec s;
    s.field = field;
    s.min = min;
    s.max = max;
    return s;
}

} // namespace

TEST(SurfaceParamMap, LinearFieldsRunAcrossTheUsedPointsBox) {
    const Points p = line(11);
    for (auto field : {ParamMapSpec::Field::LinearX, ParamMapSpec::Field::LinearY}) {
        const std::vector<float> v =
            evaluateSurfaceParamMap(spec(field, 0.2f, 0.7f), "k", p.positions, p.used, 1.0, 1);
        ASSERT_EQ(v.size(), p.positions.size());
        for (int i = 0; i < 11; ++i)
            EXPECT_NEAR(v[std::size_t(i)], 0.2f + 0.05f * float(i), 1e-6f) << i;
        // The unused point (far outside) neither stretches the box nor gets a value of its own.
        EXPECT_EQ(v.back(), 0.2f);
    }
}

TEST(SurfaceParamMap, RadialRunsFromTheBoxPointOverHalfItsDiagonal) {
    const Points p = line(11);
    ParamMapSpec radial = spec(ParamMapSpec::Field::Radial, 0.0f, 1.0f);
    radial.centreX = radial.centreY = 0.5f; // the box centre: the middle point
    const std::vector<float> v = evaluateSurfaceParamMap(radial, "k", p.positions, p.used, 1.0, 1);
    EXPECT_NEAR(v[5], 0.0f, 1e-6f);
    // The line's ends are the box's corners: half its diagonal away.
    EXPECT_NEAR(v[0], 1.0f, 1e-6f);
    EXPECT_NEAR(v[10], 1.0f, 1e-6f);
    EXPECT_NEAR(v[8], 0.6f, 1e-6f);
}

// Noise is laid out in model units: the same field at twice the model units
// per mesh unit is the same noise at half the scale; it stays within the range,
// varies, and depends on the seed.
TEST(SurfaceParamMap, NoiseIsLaidOutInModelUnits) {
    Points p;
    for (int i = 0; i < 400; ++i) {
        p.positions.push_back({0.05f * float(i), 0.013f * float(i), -0.02f * float(i)});
        p.used.push_back(true);
    }
    ParamMapSpec noise = spec(ParamMapSpec::Field::Noise, 1.0f, 3.0f);
    noise.scale = 8;
    const std::vector<float> a = evaluateSurfaceParamMap(noise, "k", p.positions, p.used, 10.0, 5);
    float lo = 3, hi = 1;
    for (float x : a) {
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
    EXPECT_GE(lo, 1.0f);
    EXPECT_LE(hi, 3.0f);
    EXPECT_GT(hi - lo, 0.5f) << "the noise hardly varies";
    noise.scale = 4;
    const std::vector<float> b = evaluateSurfaceParamMap(noise, "k", p.positions, p.used, 5.0, 5);
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_NEAR(a[i], b[i], 1e-5f) << i;
    const std::vector<float> c = evaluateSurfaceParamMap(noise, "k", p.positions, p.used, 5.0, 6);
    EXPECT_NE(b, c);
}

TEST(SurfaceParamMap, AnImageFieldIsRefusedNamingTheParameter) {
    const Points p = line(3);
    ParamMapSpec image = spec(ParamMapSpec::Field::Image, 0.0f, 1.0f);
    image.image = "ramp.png";
    try {
        evaluateSurfaceParamMap(image, "F", p.positions, p.used, 1.0, 1);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("param_maps.F: an image field cannot vary a "
                                             "parameter over a mesh"),
                  std::string::npos)
            << e.what();
    }
}

// A session on the sample sphere with a map of k along the model's y: the
// engine's per-cell plane follows the texels' heights on the mesh.
TEST(SurfaceParamMap, TheEnginesPlaneFollowsTheMesh) {
    Session s = loadPreset("gs_coral");
    s.length = 60;
    s.surface.mesh = "sample:sphere";
    s.surface.tiles = 120;
    s.surface.tileSize = 4;
    s.paramMaps["k"] = spec(ParamMapSpec::Field::LinearY, 0.05f, 0.06f);
    (void)setUpSurface(s);
    ASSERT_TRUE(s.atlasPositions);
    const StepConstants k = StepConstants::fromSession(s);
    ASSERT_EQ(k.mappedParams.size(), 1u);
    const float* plane = k.paramMaps.plane(0);
    int used = 0;
    for (std::uint32_t i = 0; i < s.atlas->cellCount(); ++i) {
        if (!s.atlas->used(i))
            continue;
        ++used;
        // The sphere's used texel centres span y in about [-1, 1].
        const float expected = 0.055f + 0.005f * (*s.atlasPositions)[i][1];
        ASSERT_NEAR(plane[i], expected, 0.0005f) << i;
    }
    EXPECT_GT(used, 1000);
}
