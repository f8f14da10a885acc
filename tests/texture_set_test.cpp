#include <cmath>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/output/texture_set.hpp"
#include "test_support.hpp"

namespace morphogen {
namespace {

// The expected encoded normal of z = strength * h with slopes gx (along +x)
// and gyUp (along +Y, up the image).
std::array<float, 3> encoded(float gx, float gyUp) {
    const float nx = -gx, ny = -gyUp;
    const float inv = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
    return {nx * inv * 0.5f + 0.5f, ny * inv * 0.5f + 0.5f, inv * 0.5f + 0.5f};
}

void expectNormal(const std::vector<float>& rgb, int width, int x, int y,
                  const std::array<float, 3>& want) {
    const float* p = &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(p[c], want[std::size_t(c)], 1e-6f) << "x " << x << " y " << y << " c " << c;
}

TEST(TextureSet, RampInXGivesTheAnalyticNormalInsideAndAHalfSlopeOnClampedEdges) {
    const int w = 9, h = 5;
    const float a = 0.1f, strength = 3.0f;
    std::vector<float> height(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[std::size_t(y * w + x)] = a * float(x);
    const std::vector<float> n =
        normalMap(height, w, h, EdgeMode::Clamped, strength, NormalFormat::OpenGl);
    for (int y = 0; y < h; ++y) {
        for (int x = 1; x < w - 1; ++x)
            expectNormal(n, w, x, y, encoded(strength * a, 0.0f));
        // The edge texel is repeated: the difference spans one step, not two.
        expectNormal(n, w, 0, y, encoded(strength * a * 0.5f, 0.0f));
        expectNormal(n, w, w - 1, y, encoded(strength * a * 0.5f, 0.0f));
    }
    // A rising ramp tilts the normal towards -x: red below the midpoint.
    EXPECT_LT(n[3 * 4], 0.5f);
}

TEST(TextureSet, PeriodicRampWrapsAtTheSeam) {
    // A sawtooth: x / w rises across the image and drops back where it wraps.
    const int w = 8, h = 4;
    std::vector<float> height(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[std::size_t(y * w + x)] = float(x) / float(w);
    const float s = 2.0f;
    const std::vector<float> n =
        normalMap(height, w, h, EdgeMode::Periodic, s, NormalFormat::OpenGl);
    const float slope = 1.0f / float(w);
    // The seam's differences read across the wrap: (h[1] - h[w-1]) / 2 at x = 0,
    // (h[0] - h[w-2]) / 2 at x = w - 1.
    const float seam0 = 0.5f * (1.0f / float(w) - float(w - 1) / float(w));
    const float seamLast = 0.5f * (0.0f - float(w - 2) / float(w));
    for (int y = 0; y < h; ++y) {
        for (int x = 1; x < w - 1; ++x)
            expectNormal(n, w, x, y, encoded(s * slope, 0.0f));
        expectNormal(n, w, 0, y, encoded(s * seam0, 0.0f));
        expectNormal(n, w, w - 1, y, encoded(s * seamLast, 0.0f));
    }
}

TEST(TextureSet, RampInYPointsGreenUpForOpenGlAndDirectXFlipsGreenOnly) {
    const int w = 6, h = 7;
    const float a = 0.05f;
    std::vector<float> height(std::size_t(w * h));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[std::size_t(y * w + x)] = a * float(y); // rises down the image
    const std::vector<float> gl =
        normalMap(height, w, h, EdgeMode::Clamped, 1, NormalFormat::OpenGl);
    for (int y = 1; y < h - 1; ++y)
        for (int x = 0; x < w; ++x)
            expectNormal(gl, w, x, y, encoded(0.0f, -a)); // downhill going up the image
    EXPECT_GT(gl[(std::size_t(3 * w + 2)) * 3 + 1], 0.5f);

    // On any field DirectX is the OpenGL map with green mirrored about 0.5.
    for (float& v : height)
        v = u(rng);
    const std::vector<float> g =
        normalMap(height, w, h, EdgeMode::Periodic, 4, NormalFormat::OpenGl);
    const std::vector<float> d =
        normalMap(height, w, h, EdgeMode::Periodic, 4, NormalFormat::DirectX);
    bool greenDiffers = false;
    for (std::size_t i = 0; i < g.size(); i += 3) {
        EXPECT_EQ(g[i], d[i]);
        EXPECT_EQ(g[i + 2], d[i + 2]);
        EXPECT_NEAR(g[i + 1] + d[i + 1], 1.0f, 1e-6f);
        greenDiffers = greenDiffers || std::abs(g[i + 1] - d[i + 1]) > 0.01f;
    }
    EXPECT_TRUE(greenDiffers);
}

TEST(TextureSet, NormalMapOfAPeriodicFieldTiles) {
    const int w = 16, h = 12;
    std::vector<float> height(std::size_t(w * h));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (float& v : height)
        v = u(rng);
    const std::vector<float> n =
        normalMap(height, w, h, EdgeMode::Periodic, 2, NormalFormat::OpenGl);
    // Shift the field so that its old wrap-around columns and rows are in the
    // middle: each texel's normal must move with it, seams included.
    const int sx = 5, sy = 7;
    std::vector<float> shifted(height.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            shifted[std::size_t(((y + sy) % h) * w + (x + sx) % w)] =
                height[std::size_t(y * w + x)];
    const std::vector<float> m =
        normalMap(shifted, w, h, EdgeMode::Periodic, 2, NormalFormat::OpenGl);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(n[std::size_t(y * w + x) * 3 + std::size_t(c)],
                          m[std::size_t(((y + sy) % h) * w + (x + sx) % w) * 3 + std::size_t(c)])
                    << x << "," << y;

    // A smooth periodic field: the jump across the seam (last column to the
    // first) is no larger than between interior neighbours.
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            height[std::size_t(y * w + x)] = 0.5f + 0.5f *
                                                        std::sin(6.2831853f * float(x) / float(w)) *
                                                        std::cos(6.2831853f * float(y) / float(h));
    const std::vector<float> smooth =
        normalMap(height, w, h, EdgeMode::Periodic, 4, NormalFormat::OpenGl);
    const auto jump = [&](int x0, int y0, int x1, int y1) {
        float j = 0;
        for (int c = 0; c < 3; ++c)
            j = std::max(j, std::abs(smooth[std::size_t(y0 * w + x0) * 3 + std::size_t(c)] -
                                     smooth[std::size_t(y1 * w + x1) * 3 + std::size_t(c)]));
        return j;
    };
    float interior = 0, seam = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x + 1 < w; ++x)
            interior = std::max(interior, jump(x, y, x + 1, y));
        seam = std::max(seam, jump(w - 1, y, 0, y));
    }
    for (int x = 0; x < w; ++x) {
        for (int y = 0; y + 1 < h; ++y)
            interior = std::max(interior, jump(x, y, x, y + 1));
        seam = std::max(seam, jump(x, h - 1, x, 0));
    }
    EXPECT_GT(interior, 0.0f);
    EXPECT_LE(seam, interior + 1e-6f);
}

TEST(TextureSet, FixedLevelsMapTheSameValueToTheSameHeight) {
    // Two states with different minima and maxima share the value 0.2.
    State a(3, 1, 2), b(3, 1, 2);
    const float av[] = {0.1f, 0.2f, 0.3f}, bv[] = {0.0f, 0.2f, 0.45f};
    for (int x = 0; x < 3; ++x) {
        a.at(1, x, 0) = av[x];
        b.at(1, x, 0) = bv[x];
    }
    Session session = test::smallSession("gs_coral", 8, 1);
    const HeightLevels levels = heightLevels(session, 1);
    EXPECT_EQ(levels.low, 0.0f);
    EXPECT_EQ(levels.high, 0.5f); // Gray-Scott v's display range
    const std::vector<float> ha = heightField(a, 1, levels), hb = heightField(b, 1, levels);
    EXPECT_FLOAT_EQ(ha[1], 0.4f);
    EXPECT_FLOAT_EQ(hb[1], 0.4f);
    EXPECT_FLOAT_EQ(hb[2], 0.9f); // linear, not stretched to each state's max

    session.heightMaps.range = std::array<float, 2>{0.1f, 0.3f};
    const HeightLevels fromSession = heightLevels(session, 1);
    EXPECT_EQ(fromSession.source, "session");
    const std::vector<float> hs = heightField(a, 1, fromSession);
    EXPECT_NEAR(hs[0], 0.0f, 1e-6f);
    EXPECT_NEAR(hs[1], 0.5f, 1e-6f);
    EXPECT_NEAR(hs[2], 1.0f, 1e-6f);
}

TEST(TextureSet, MaskIsAboveTheThreshold) {
    const std::vector<float> m = heightMask({0.2f, 0.5f, 0.51f, 1.3f}, 0.5f);
    EXPECT_EQ(m, (std::vector<float>{0, 0, 1, 1}));
}

TEST(TextureSet, HeightBlockRoundTripsAndRefusesBadValues) {
    Session s = test::smallSession("gs_coral", 8, 1);
    s.heightMaps.range = std::array<float, 2>{-1.0f, 2.0f};
    s.heightMaps.normalStrength = 5.0f;
    s.heightMaps.normalFormat = NormalFormat::DirectX;
    s.heightMaps.maskThreshold = 0.25f;
    const Session back = sessionFromJson(sessionToJson(s), "round trip");
    EXPECT_TRUE(back.heightMaps == s.heightMaps);
    // A session without the block writes none (old sessions stay as they were).
    EXPECT_FALSE(sessionToJson(test::smallSession("gs_coral", 8, 1)).contains("height"));

    const auto refuses = [&](const nlohmann::json& block, const std::string& needle) {
        nlohmann::json j = sessionToJson(test::smallSession("gs_coral", 8, 1));
        j["height"] = block;
        try {
            sessionFromJson(j, "bad.json");
            ADD_FAILURE() << "accepted " << block.dump();
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        }
    };
    refuses({{"range", {2, 1}}}, "height.range");
    refuses({{"normal_format", "vulkan"}}, "opengl, directx");
    refuses({{"normal_strength", -1}}, "height.normal_strength");
    refuses({{"mask_threshold", 2}}, "height.mask_threshold");
    refuses({{"colour", 1}}, "unknown field 'height.colour'");
}

TEST(TextureSet, WritesEveryFileAndAManifestThatNamesThem) {
    const Session session = test::smallSession("gs_coral", 16, 20);
    const State state = test::runCpu(session);
    const std::filesystem::path dir = test::scratchDir("texture_set") / "set";
    std::filesystem::remove_all(dir);
    writeTextureSet(dir.string(), state, session);
    for (const std::string& f : textureSetFiles())
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / f)) << f;
    std::ifstream in(dir / "texture_set.json");
    const nlohmann::json m = nlohmann::json::parse(in);
    EXPECT_EQ(m["chemical"], "v");
    EXPECT_EQ(m["height"]["low"], 0.0);
    EXPECT_EQ(m["height"]["high"], 0.5);
    EXPECT_EQ(m["normal"]["format"], "opengl");
    EXPECT_EQ(m["session"], "session.json");
    std::size_t named = 0;
    for (const nlohmann::json& f : m["files"]) {
        ++named;
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / f["file"].get<std::string>()));
        const std::string space = f["colour_space"];
        if (f["file"] == "albedo.png")
            EXPECT_EQ(space, "sRGB");
        else if (f["file"] != "session.json")
            EXPECT_EQ(space, "linear");
    }
    EXPECT_EQ(named + 1, textureSetFiles().size()); // every file but the manifest itself
    // The written session reproduces the set's state.
    const Session again = loadSessionFile((dir / "session.json").string());
    EXPECT_EQ(test::runCpu(again), state);
}

} // namespace
} // namespace morphogen
