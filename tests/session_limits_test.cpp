// The limits of core/base/limits.hpp: sessions with every field at its
// minimum and at its maximum are written and read back unchanged; the JSON
// text checks (depth, size, wording) and the image header checks refuse what
// they must before any parsing or decoding; seed spots of any radius mark the
// cells a cell-by-cell test marks, without its cost.

#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/json_input.hpp"
#include "core/base/limits.hpp"
#include "core/base/names.hpp"
#include "core/base/random.hpp"
#include "core/io/image_io.hpp"
#include "core/models/initial_condition.hpp"
#include "core/models/reaction_model.hpp"
#include "core/session/session.hpp"
#include "core/sim/segments.hpp"
#include "test_support.hpp"

namespace morphogen {
namespace {

using nlohmann::json;

template <class F> std::string errorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// Reads `j`, writes it with saveSessionFile, reads the file back: the second
// reading must give the same session (as JSON) as the first.
void expectRoundTrip(const json& j, const std::string& name) {
    SCOPED_TRACE(name);
    Session s;
    ASSERT_NO_THROW(s = sessionFromJson(j, name)) << errorOf([&] { sessionFromJson(j, name); });
    ASSERT_NO_THROW(validateSession(s, name)) << errorOf([&] { validateSession(s, name); });
    const std::string path = (test::scratchDir("session_limits_test") / (name + ".json")).string();
    saveSessionFile(s, path);
    Session back;
    ASSERT_NO_THROW(back = loadSessionFile(path)) << errorOf([&] { loadSessionFile(path); });
    EXPECT_EQ(sessionToJson(back), sessionToJson(s));
    EXPECT_EQ(back.width, s.width);
    EXPECT_EQ(back.steps, s.steps);
    EXPECT_EQ(back.seed, s.seed);
    EXPECT_EQ(back.dt, s.dt);
}

// Every parameter of `model` at its minimum (or maximum).
json paramsAt(const ReactionModel& model, bool maximum) {
    json params = json::object();
    for (const ParamSpec& p : model.params())
        params[p.name] = maximum ? p.max : p.min;
    return params;
}

json chemicalsAt(const ReactionModel& model, double value) {
    json values = json::object();
    for (const ChemicalSpec& c : model.chemicals())
        values[c.name] = value;
    return values;
}

TEST(SessionLimits, EveryModelRoundTripsAtItsMinimumAndMaximum) {
    for (const std::string& name : splitNameList(modelNames())) {
        const ReactionModel& model = *findModel(name);
        const json minimum = {
            {"model", name},
            {"size", 1},
            {"length", kMinLength},
            {"dt", kMinDt},
            {"steps", 0},
            {"seed", 0},
            {"integrator", "semi_implicit"},
            {"relaxation_passes", 1},
            {"edges", "clamped"},
            {"coarse_to_fine", false},
            {"params", paramsAt(model, false)},
            {"init",
             {{"type", "seed_spots"},
              {"count", 0},
              {"radius", 0},
              {"base", chemicalsAt(model, -1e6)},
              {"noise", chemicalsAt(model, -1e6)},
              {"inside", chemicalsAt(model, -1e6)}}},
            {"colormap", {{"name", "grey"}, {"low", {0, 0, 0}}, {"levels", {0, 1e-6}}}},
            {"height", {{"range", {-1e30, -1e29}}, {"normal_strength", 0}, {"mask_threshold", 0}}}};
        expectRoundTrip(minimum, name + "_minimum");

        json colours = json::array();
        for (int i = 0; i < 16; ++i)
            colours.push_back(i % 2 ? "#ffffff" : "#000000");
        const json maximum = {
            {"model", name},
            {"size", {kMaxGridSide, kMaxGridSide}},
            {"length", kMaxLength},
            {"dt", kMaxDt},
            {"steps", kMaxSteps},
            {"seed", kMaxSeed},
            {"integrator", "semi_implicit"},
            {"relaxation_passes", kMaxRelaxationPasses},
            {"params", paramsAt(model, true)},
            {"init",
             {{"type", "jittered_grid"},
              {"spacing", 1e5},
              {"jitter", 1},
              {"radius", 1e4},
              {"base", chemicalsAt(model, 1e6)},
              {"noise", chemicalsAt(model, 1e6)},
              {"inside", chemicalsAt(model, 1e6)}}},
            {"colormap",
             {{"name", "custom"},
              {"colours", colours},
              {"high", {1, 1, 1}},
              {"levels", {0.999, 1}}}},
            {"height", {{"range", {1e29, 1e30}}, {"normal_strength", 100}, {"mask_threshold", 1}}}};
        expectRoundTrip(maximum, name + "_maximum");
    }
}

TEST(SessionLimits, CascadesAndSchedulesRoundTripAtTheirLimits) {
    // kMaxStages stages adding up to kMaxSteps, each with a freeze rule at
    // its default (+-1e30, which a float does not hold exactly) and resets.
    json stages = json::array();
    for (int i = 0; i < kMaxStages; ++i) {
        json stage = {{"steps", kMaxSteps / kMaxStages}, {"dt", i % 2 ? kMaxDt : kMinDt}};
        if (i % 3 == 1)
            stage["freeze"] = {{"chemical", "u"}};
        if (i % 3 == 1)
            stage["reset"] = {{"u", i % 2 ? 1e6 : -1e6}};
        stages.push_back(stage);
    }
    const json cascade = {{"model", "gray_scott"}, {"size", 16}, {"stages", stages}};
    expectRoundTrip(cascade, "stages_maximum");
    json one = cascade;
    one["stages"] = json::array({{{"steps", 0}}});
    expectRoundTrip(one, "stages_minimum");

    // A model change with the freeze rule's explicit extremes.
    const json change = {{"model", "turing_turk"},
                         {"size", 16},
                         {"stages",
                          {{{"steps", 1}},
                           {{"steps", 1},
                            {"model", "meinhardt_stripes"},
                            {"freeze", {{"chemical", "b"}, {"min", -1e30}, {"max", 1e30}}},
                            {"reset", {{"g1", 1e6}}}}}}};
    expectRoundTrip(change, "model_change");

    json levels = json::array();
    for (int i = 0; i < kMaxScheduleLevels; ++i) {
        const int side = std::min(kMaxGridSide, 1 << std::min(i, 14));
        levels.push_back({{"size", side}, {"steps", kMaxSteps / kMaxScheduleLevels}});
    }
    expectRoundTrip({{"model", "gray_scott"}, {"schedule", levels}}, "schedule_maximum");
    expectRoundTrip({{"model", "gray_scott"}, {"schedule", {{{"size", 1}, {"steps", 0}}}}},
                    "schedule_minimum");
}

TEST(SessionLimits, DiffusionMapsAndTilesRoundTripAtTheirLimits) {
    // A blend nested kMaxBlendDepth deep holding kMaxOrientationFields fields.
    json field = {{"type", "spiral"}, {"angle", 3600}, {"centre", {10, -10}}};
    int fields = 1;
    for (int depth = 0; depth < kMaxBlendDepth; ++depth) {
        json parts = json::array({field});
        ++fields;
        while (depth + 1 == kMaxBlendDepth && fields < kMaxOrientationFields) {
            parts.push_back({{"type", "constant"}, {"angle", -3600}, {"centre", {-10, 10}}});
            ++fields;
        }
        field = {{"type", "blend"}, {"centre", {0.5, 0.5}}, {"parts", parts}};
    }
    const json anisotropic = {{"model", "gray_scott"},
                              {"size", 16},
                              {"diffusion",
                               {{"type", "anisotropic"},
                                {"tensors",
                                 {{"u", {{"theta", -3600}, {"a1", 0}, {"a2", 100}}},
                                  {"v", {{"theta", 3600}, {"a1", 100}, {"a2", 0}}}}},
                                {"map", {{"orientation", field}, {"scale", {0, 100}}}}}}};
    expectRoundTrip(anisotropic, "blend_maximum");
    json tooMany = anisotropic;
    tooMany["diffusion"]["map"]["orientation"] = {
        {"type", "blend"}, {"centre", {0.5, 0.5}}, {"parts", json::array({field})}};
    EXPECT_NE(errorOf([&] { sessionFromJson(tooMany, "deep.json"); }).find("nested up to 4 deep"),
              std::string::npos);

    for (const char* sg : {R"({"window": 3, "degree": 2})", R"({"window": 5, "degree": 6})"}) {
        const json generalized = {
            {"model", "gray_scott"},
            {"size", 16},
            {"diffusion",
             {{"type", "generalized"},
              {"tensors", {{"u", "xx=1000,yy=-1000,xxxx=1000"}, {"v", "xxyy=-1000"}}},
              {"savitzky_golay", json::parse(sg)},
              {"stabilize", true}}}};
        expectRoundTrip(generalized, std::string("generalized_window_") + sg[11]);
    }

    const ReactionModel& gs = *findModel("gray_scott");
    const ParamSpec& f = *gs.param("F");
    const ParamSpec& k = *gs.param("k");
    const json maps = {
        {"model", "gray_scott"},
        {"size", 16},
        {"param_maps",
         {{"F", {{"field", "noise"}, {"range", {f.min, f.max}}, {"scale", 1e5}}},
          {"k", {{"field", "radial"}, {"range", {k.max, k.min}}, {"centre", {-10, 10}}}}}}};
    expectRoundTrip(maps, "param_maps");

    // Tiles: the most per side (each 4 x 4 cells), and the most a sweep writes.
    expectRoundTrip({{"model", "gray_scott"},
                     {"size", kMaxGridSide},
                     {"tiles", {{"grid", {kMaxTilesPerSide, kMaxTilesPerSide}}}}},
                    "tiles_per_side");
    json values = json::array();
    for (int i = 0; i < kMaxSweepTiles; ++i)
        values.push_back(i % 2 ? f.max : f.min);
    expectRoundTrip({{"model", "gray_scott"},
                     {"size", 64 * 8},
                     {"tiles", {{"grid", {64, 64}}, {"params", {{"F", values}}}}}},
                    "tiles_sweep");
}

TEST(SessionLimits, SurfaceBlocksRoundTripAtTheirLimits) {
    for (const bool maximum : {false, true}) {
        const json surface = {
            {"mesh", maximum ? "models/meshes/torus.obj" : "sample:sphere"},
            {"tile_size", maximum ? kMaxSurfaceTileSize : kMinSurfaceTileSize},
            {"tiles", maximum ? kMaxSurfaceTiles : kMinSurfaceTiles},
            {"metric_correction", !maximum},
            {"cross_term", maximum},
            {"scale",
             {{"by", "mean_curvature"}, {"strength", maximum ? kMaxSurfaceScaleStrength : 0.0}}},
            {"view",
             {{"azimuth", maximum ? 360 : -360},
              {"elevation", maximum ? 90 : -90},
              {"distance", maximum ? kMaxViewDistance : kMinViewDistance},
              {"resolution", {maximum ? kMaxViewSide : kMinViewSide, kMinViewSide}},
              {"turntable", maximum ? kMaxTurntableFrames : 0}}}};
        expectRoundTrip({{"model", "gray_scott"}, {"length", 64}, {"surface", surface}},
                        maximum ? "surface_maximum" : "surface_minimum");
    }
    // A direction field of either kind, at the coordinate limit.
    expectRoundTrip({{"model", "witkin_kass"},
                     {"surface",
                      {{"mesh", "sample:torus"},
                       {"direction", {{"along", {kMaxSurfacePoint, 0.0, -kMaxSurfacePoint}}}}}}},
                    "surface_direction_along");
    expectRoundTrip(
        {{"model", "witkin_kass"},
         {"surface",
          {{"mesh", "sample:torus"},
           {"direction",
            {{"around", {0.0, 0.0, 1.0}}, {"through", {-kMaxSurfacePoint, 2.5, 0.0}}}}}}},
        "surface_direction_around");
    // Automatic tile size and budget are written as 0 and read back as automatic.
    expectRoundTrip({{"model", "turing_turk"}, {"surface", {{"mesh", "sample:torus"}}}},
                    "surface_defaults");
}

// What a session may not hold, refused by the reader with the field named.
TEST(SessionLimits, ValuesPastTheLimitsAreRefusedNamingTheField) {
    struct Case {
        json session;
        const char* mustMention;
    };
    json stages = json::array();
    for (int i = 0; i <= kMaxStages; ++i)
        stages.push_back({{"steps", 1}});
    json levels = json::array();
    for (int i = 0; i <= kMaxScheduleLevels; ++i)
        levels.push_back({{"size", 8}, {"steps", 1}});
    const Case cases[] = {
        {{{"steps", kMaxSteps + 1}},
         "field 'steps' is 100000001, accepted range is [0, 100000000]"},
        {{{"seed", kMaxSeed + 1}}, "field 'seed' is 9007199254740993"},
        {json::parse(R"({"steps": 18446744073709551615})"),
         "field 'steps' is 18446744073709551615"},
        {{{"dt", 1e-7}}, "field 'dt' is 1e-07, accepted range is [1e-06, 100]"},
        {{{"length", 1e8}}, "field 'length' is 1e+08"},
        {{{"stages", stages}}, "field 'stages' has 1001 stages; accepted are 1 to 1000"},
        {{{"stages", {{{"steps", kMaxSteps}}, {{"steps", 1}}}}},
         "field 'stages' add up to 100000001 steps"},
        {{{"schedule", levels}}, "field 'schedule' has 33 levels"},
        {{{"schedule", {{{"steps", 10}}, {{"size", 32}, {"steps", 10}}}}},
         "field 'schedule[0].size' is missing"},
        {{{"schedule", {{{"size", 32}}}}}, "field 'schedule[0].steps' is missing"},
        {{{"schedule", {{{"size", 64}, {"steps", 1}}, {{"size", 32}, {"steps", 1}}}}},
         "field 'schedule[1].size' is 32 x 32, smaller than level 0's 64 x 64"},
        {{{"schedule", {{{"size", 8}, {"steps", kMaxSteps}}, {{"size", 16}, {"steps", 1}}}}},
         "levels add up to 100000001 steps"},
        {{{"size", 16}, {"tiles", {{"grid", {32, 32}}}}}, "must split the 16 x 16 grid evenly"},
        {{{"surface", {{"tiles", 10}}}}, "field 'surface.mesh' is missing"},
        {{{"surface", {{"mesh", "a.obj"}, {"tile_size", 2}}}},
         "field 'surface.tile_size' is 2, accepted are 0 (automatic) or 4..64"},
        {{{"surface", {{"mesh", "a.obj"}, {"tiles", kMaxSurfaceTiles + 1}}}},
         "field 'surface.tiles' is 100001, accepted range is [0, 100000]"},
        {{{"surface", {{"mesh", "a.obj"}, {"view", {{"resolution", {8, 8}}}}}}},
         "field 'surface.view.resolution' must be an array [width, height] of integers in "
         "16..8192, got 8"},
        {{{"surface", {{"mesh", "a.obj"}, {"scale", {{"by", "height"}}}}}},
         "field 'surface.scale.by' is 'height', accepted: none, mean_curvature"},
        {{{"surface", {{"mesh", "a.obj"}, {"direction", {{"along", {0, 0, 0}}}}}}},
         "field 'surface.direction.along' is [0, 0, 0]: an axis needs a length"},
        {{{"surface", {{"mesh", "a.obj"}, {"direction", {{"around", {0, 1}}}}}}},
         "field 'surface.direction.around' must be an array [x, y, z] of numbers in "
         "-1e+09..1e+09 (mesh units)"},
        {{{"surface", {{"mesh", "a.obj"}, {"direction", {{"along", {0, 1e10, 0}}}}}}},
         "field 'surface.direction.along' must be an array [x, y, z] of numbers in "
         "-1e+09..1e+09 (mesh units), got [0,10000000000.0,0]"},
        {{{"surface",
           {{"mesh", "a.obj"}, {"direction", {{"along", {0, 1, 0}}, {"around", {0, 1, 0}}}}}}},
         "field 'surface.direction.around' cannot be given with \"along\""},
        {{{"surface", {{"mesh", "a.obj"}, {"direction", json::object()}}}},
         "field 'surface.direction.along' is missing: give one of"},
        {{{"surface",
           {{"mesh", "a.obj"}, {"direction", {{"along", {0, 1, 0}}, {"through", {0, 0, 0}}}}}}},
         "field 'surface.direction.through' applies to \"around\" only"},
        {{{"stages", {{{"steps", 1}, {"reset", {{"u", 1}}}}}}},
         "'stages[0].reset' needs frozen cells"},
        {{{"diffusion", {{"type", "generalized"}, {"tensors", {{"u", "xx=1e308"}, {"v", "a"}}}}}},
         "component 'xx' is 1e308; accepted are values in [-1000, 1000]"},
        {{{"diffusion",
           {{"type", "generalized"},
            {"tensors", {{"u", "a"}, {"v", "a"}}},
            {"savitzky_golay", {{"window", 4}}}}}},
         "'diffusion.savitzky_golay.window' is 4, accepted are 3 (3x3) and 5 (5x5)"},
    };
    for (const Case& c : cases) {
        json j = c.session;
        j["model"] = "gray_scott";
        SCOPED_TRACE(j.dump());
        const std::string message = errorOf([&] {
            Session s = sessionFromJson(j, "bad.json");
            validateSession(s, "bad.json");
        });
        EXPECT_NE(message.find(c.mustMention), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// What the command line can put in a session beyond the reader's checks is
// refused by validateSession, before a run.
TEST(SessionLimits, ValidateSessionRefusesWhatTheReaderWould) {
    const Session base = sessionFromJson({{"model", "gray_scott"}, {"size", 16}}, "x");
    auto refused = [&](auto change, const char* mustMention) {
        Session s = base;
        change(s);
        const std::string message = errorOf([&] { validateSession(s, "x"); });
        EXPECT_NE(message.find(mustMention), std::string::npos) << message;
    };
    refused([](Session& s) { s.seed = std::uint64_t(1) << 60; }, "seed is 1152921504606846976");
    refused([](Session& s) { s.dt = 1e-9f; }, "dt is 1e-09");
    refused([](Session& s) { s.dt = 1000.0f; }, "dt is 1000");
    refused([](Session& s) { s.length = 1e-4; }, "0.0001 model units wide");
    refused([](Session& s) { s.steps = -1; }, "steps is -1");
    refused(
        [](Session& s) {
            s.schedule = {{32, 32, 1}, {16, 16, 1}};
            s.width = s.height = 16;
        },
        "smaller than the level before it");
    refused([](Session& s) { s.tiles.columns = s.tiles.rows = 8; }, "must split the 16 x 16");
    refused(
        [](Session& s) {
            s.stages.resize(2);
            s.stages[1].reset["u"] = 1;
        },
        "stages[1].reset: no stage up to this one has a \"freeze\" rule");
    refused([](Session& s) { s.stages.resize(kMaxStages + 1); }, "1001 cascade stages");
}

TEST(JsonInput, DepthIsCountedOutsideStrings) {
    EXPECT_EQ(jsonNestingDepth("{}", 64), 1);
    EXPECT_EQ(jsonNestingDepth("[[], [[1]], {\"a\": {}}]", 64), 3);
    EXPECT_EQ(jsonNestingDepth("[\"[[[{{{\"]", 64), 1);
    EXPECT_EQ(jsonNestingDepth(R"(["\"[[[", "\\", [1]])", 64), 2);
    std::size_t at = 0;
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    EXPECT_EQ(jsonNestingDepth(deep, 64, &at), 65);
    EXPECT_EQ(at, 64u);

    // kMaxJsonDepth levels parse; one more is refused before parsing.
    const std::string ok = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    EXPECT_NO_THROW(parseJsonText(ok, "ok.json"));
    const std::string message = errorOf([&] { parseJsonText(deep, "deep.json"); });
    EXPECT_NE(message.find("deep.json: arrays and objects nested more than 64 levels deep (at "
                           "line 1, column 65)"),
              std::string::npos)
        << message;
    const std::string session = R"({"model": "gray_scott", "size": )" + deep + "}";
    EXPECT_NE(errorOf([&] { parseJsonText(session, "s.json"); }).find("nested more than 64"),
              std::string::npos);
}

TEST(JsonInput, ParseErrorsAreOneLineInputErrors) {
    const std::string syntax = errorOf([] { parseJsonText("{\n  \"a\": [1,\n\n", "t.json"); });
    EXPECT_NE(syntax.find("t.json: not valid JSON: parse error at line "), std::string::npos)
        << syntax;
    EXPECT_EQ(syntax.find('\n'), std::string::npos);
    EXPECT_EQ(syntax.find("[json.exception"), std::string::npos);
    const std::string overflow = errorOf([] { parseJsonText(R"({"dt": 1e400})", "dt.json"); });
    EXPECT_NE(overflow.find("dt.json: not valid JSON: number overflow parsing '1e400'"),
              std::string::npos)
        << overflow;
    // A long unterminated string is quoted, shortened, on one line.
    const std::string open = "[\"" + std::string(100000, 'a') + "\n";
    const std::string quoted = errorOf([&] { parseJsonText(open, "open.json"); });
    EXPECT_LT(quoted.size(), 600u);
    EXPECT_EQ(quoted.find('\n'), std::string::npos);
}

TEST(JsonInput, FilesAreCheckedBeforeTheyAreRead) {
    const std::filesystem::path dir = test::scratchDir("session_limits_test");
    EXPECT_NE(errorOf([&] { readInputFile(dir.string(), "session file"); }).find("is a folder"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  loadSessionFile(dir.string());
              }).find(dir.string() + ": is a folder, not a session file"),
              std::string::npos);
    EXPECT_NE(errorOf([&] {
                  readInputFile((dir / "none.json").string(), "session file");
              }).find("cannot open session file"),
              std::string::npos);
    const std::string big = (dir / "big.json").string();
    {
        std::ofstream out(big, std::ios::binary);
        const std::string spaces(1 << 20, ' ');
        for (int i = 0; i < 16; ++i)
            out << spaces;
        out << "{}";
    }
    const std::string message = errorOf([&] { loadSessionFile(big); });
    EXPECT_NE(message.find("the session file is 16777218 bytes; accepted are up to 16777216"),
              std::string::npos)
        << message;
    std::filesystem::remove(big);
}

TEST(JsonInput, OneLineJoinsAndShortens) {
    EXPECT_EQ(oneLine("libpng error:\n  IDAT: CRC error\r\n"), "libpng error: IDAT: CRC error");
    EXPECT_EQ(oneLine(std::string(50, 'x'), 10), "xxxxxxx...");
}

// A PNG of only a header (and a token IDAT) declaring width x height.
void writePngHeader(const std::string& path, std::uint32_t width, std::uint32_t height) {
    auto crc32 = [](const std::string& bytes) {
        std::uint32_t c = 0xffffffffu;
        for (unsigned char b : bytes) {
            c ^= b;
            for (int k = 0; k < 8; ++k)
                c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
        }
        return c ^ 0xffffffffu;
    };
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(std::uint32_t(data.size())) + type + data + be32(crc32(type + data));
    };
    const std::string ihdr = be32(width) + be32(height) + std::string{8, 2, 0, 0, 0};
    std::ofstream out(path, std::ios::binary);
    out << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("IHDR", ihdr)
        << chunk("IDAT", std::string{0x78, 0x01}) << chunk("IEND", "");
}

TEST(ImageLimits, HugeHeadersAreRefusedBeforeDecoding) {
    const std::filesystem::path dir = test::scratchDir("session_limits_test");
    for (const std::uint32_t side : {1000000u, 20000u}) {
        const std::string path = (dir / ("huge_" + std::to_string(side) + ".png")).string();
        writePngHeader(path, side, side);
        const auto start = std::chrono::steady_clock::now();
        const std::string message = errorOf([&] { loadLuminance(path, 8, 8); });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string declared = std::to_string(side) + " x " + std::to_string(side);
        EXPECT_NE(message.find(path + ": the image is " + declared +
                               " pixels; accepted are up to 16384 pixels per side"),
                  std::string::npos)
            << message;
        EXPECT_LT(seconds, 1.0) << "the pixels were decoded before the refusal";
        EXPECT_NE(errorOf([&] { readRawImage(path); }).find(declared + " pixels"),
                  std::string::npos);
    }
    // A side within the limit but too many pixels in all, in 64 bits.
    EXPECT_NE(errorOf([] { checkImageSize("a.exr", 16384, 16385, 1, 1); }).find("16384 x 16385"),
              std::string::npos);
    EXPECT_NO_THROW(checkImageSize("a.exr", kMaxImageSide, kMaxImageSide, 1, 4));
    EXPECT_NE(errorOf([] { checkImageSize("a.exr", 8, 8, 1, 65); }).find("65 channels"),
              std::string::npos);
    EXPECT_NE(errorOf([] { checkImageSize("a.exr", 8, 8, 3, 1); }).find("volume"),
              std::string::npos);
    EXPECT_NE(errorOf([] { checkImageSize("a.png", 0, 8, 1, 1); }).find("empty"),
              std::string::npos);

    // A real image within the limits still loads.
    const std::string small = (dir / "small.png").string();
    std::vector<float> grey(16 * 8, 0.5f);
    writeGreyImage(small, grey, 16, 8, 8);
    const std::vector<float> lum = loadLuminance(small, 4, 4);
    ASSERT_EQ(lum.size(), 16u);
    EXPECT_NEAR(lum[5], 128.0f / 255.0f, 1e-3f);
}

// An OpenEXR attribute that declares more bytes than the file holds is refused
// by our own check (its message names the attribute), before OpenEXR
// allocates them (image_fuzzer found a 1.7 GB "string" costing
// 10 s under the sanitizers; fuzz/regressions/image_fuzzer keeps it).
TEST(ImageLimits, ExrAttributesLargerThanTheFileAreRefused) {
    const std::filesystem::path dir = test::scratchDir("session_limits_test");
    const std::string path = (dir / "big_attribute.exr").string();
    {
        std::ofstream out(path, std::ios::binary);
        out << std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) << "capDate"
            << std::string(1, '\0') << "string" << std::string(1, '\0')
            << std::string("\xff\xff\xff\x6f", 4) << "2026";
    }
    const std::string message = errorOf([&] { readRawImage(path); });
    EXPECT_NE(message.find(path + ": a corrupt OpenEXR header (attribute 'capDate' of type "
                                  "'string' declares 1879048191 bytes, and the file has 4 left)"),
              std::string::npos)
        << message;
    EXPECT_NE(errorOf([&] { loadLuminance(path, 8, 8); }).find("attribute 'capDate'"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { checkImageFile(path); }).find("attribute 'capDate'"),
              std::string::npos);
}

// The cells a disc of radius r (cells) marks, tested cell by cell as the
// reader's spots were before: the reference for markDiscs.
std::vector<unsigned char> referenceDiscs(int width, int height,
                                          const std::vector<std::pair<double, double>>& centres,
                                          float r) {
    std::vector<unsigned char> marked(std::size_t(width) * height, 0);
    const int reach = int(std::ceil(r));
    for (const auto& [fx, fy] : centres) {
        const int cx = int(std::floor(fx)), cy = int(std::floor(fy));
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx) {
                if (float(dx * dx + dy * dy) > r * r)
                    continue;
                const int x = ((cx + dx) % width + width) % width;
                const int y = ((cy + dy) % height + height) % height;
                marked[std::size_t(y) * width + x] = 1;
            }
    }
    return marked;
}

// Which cells the initial state marks (their `u` is the inside value).
std::vector<unsigned char> markedCells(const InitialCondition& init, int width, int height,
                                       std::uint64_t seed) {
    const ReactionModel& model = *findModel("gray_scott");
    const State state = makeInitialState(init, model, {}, width, height, seed);
    std::vector<unsigned char> marked(state.cellCount());
    for (std::size_t i = 0; i < marked.size(); ++i)
        marked[i] = state.plane(0)[i] == 1.0f;
    return marked;
}

TEST(SeedSpots, AnyRadiusMarksTheCellsACellByCellTestMarks) {
    InitialCondition init;
    init.type = InitialCondition::Type::SeedSpots;
    init.base = {{"u", 0.0f}};
    init.inside = {{"u", 1.0f}};
    const std::pair<int, int> sizes[] = {{32, 32}, {13, 7}, {5, 40}, {1, 1}, {64, 3}};
    const float radii[] = {0.0f, 0.5f, 1.0f, 1.5f, 2.3f, 3.0f, 6.2f, 16.0f, 20.5f, 45.0f, 1e4f};
    for (const auto& [w, h] : sizes)
        for (const float r : radii)
            for (const int count : {1, 3, 17}) {
                SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " r " +
                             std::to_string(r) + " count " + std::to_string(count));
                init.spotCount = count;
                init.spotRadius = r;
                const std::uint64_t seed = 7;
                std::vector<std::pair<double, double>> centres;
                for (int s = 0; s < count; ++s)
                    centres.emplace_back(uniform01(seed, 2000, 2 * s) * w,
                                         uniform01(seed, 2000, 2 * s + 1) * h);
                const float cells = r; // one unit per cell
                if (r > 100)
                    EXPECT_EQ(markedCells(init, w, h, seed),
                              std::vector<unsigned char>(std::size_t(w) * h, 1));
                else
                    EXPECT_EQ(markedCells(init, w, h, seed), referenceDiscs(w, h, centres, cells));
            }
}

TEST(SeedSpots, AHugeRadiusCostsNoMoreThanTheGrid) {
    // 100000 spots of radius 10000 on 32 x 32: 4e13 cell tests the old way.
    InitialCondition init;
    init.type = InitialCondition::Type::SeedSpots;
    init.spotCount = 100000;
    init.spotRadius = 1e4f;
    init.base = {{"u", 0.0f}};
    init.inside = {{"u", 1.0f}};
    const auto start = std::chrono::steady_clock::now();
    const std::vector<unsigned char> marked = markedCells(init, 32, 32, 1);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
    EXPECT_EQ(marked, std::vector<unsigned char>(32 * 32, 1));
    // A radius just under the grid: every centre reaches every row.
    init.spotRadius = 30.0f;
    init.spotCount = 2000;
    const auto again = std::chrono::steady_clock::now();
    markedCells(init, 256, 256, 1);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - again).count(), 2.0);
}

TEST(SegmentLimits, SegmentsPastAnIntInAllAreRefused) {
    // Each stage fits, the substeps of a fine grid make the total pass INT_MAX.
    Session s = sessionFromJson({{"model", "gray_scott"},
                                 {"size", 512},
                                 {"length", 64},
                                 {"coarse_to_fine", false},
                                 {"stages", {{{"steps", 20000000}}, {{"steps", 20000000}}}}},
                                "x");
    const std::string message = errorOf([&] { segmentsOf(s); });
    EXPECT_NE(message.find("more than the engine runs in one go"), std::string::npos) << message;
}

TEST(JsonInput, ADuplicatedKeyIsRefusedWithItsPath) {
    // nlohmann keeps the last of two equal keys; a session that says a thing
    // twice is more likely a slip than a wish.
    const std::string top = errorOf([] { parseJsonText(R"({"dt": 1, "dt": 2})", "d.json"); });
    EXPECT_NE(top.find("d.json: key 'dt' appears twice in one object"), std::string::npos) << top;
    const std::string nested = errorOf([] {
        parseJsonText(R"({"colormap": {"name": "grey"}, "edits": [{"step": 1, "step": 2}]})",
                      "n.json");
    });
    EXPECT_NE(nested.find("key 'edits[].step' appears twice"), std::string::npos) << nested;
    // The same key in two objects, and a key equal to a value, are fine.
    EXPECT_NO_THROW(parseJsonText(R"({"a": {"x": 1}, "b": {"x": 2}, "c": "a"})", "ok.json"));
    EXPECT_NO_THROW(parseJsonText(R"([{"x": 1}, {"x": 2}])", "ok.json"));
    // Through the session reader too.
    const std::string session = errorOf([] {
        sessionFromJson(
            parseJsonText(R"({"model": "gray_scott", "size": 16, "size": 32})", "s.json"),
            "s.json");
    });
    EXPECT_NE(session.find("key 'size' appears twice"), std::string::npos) << session;
}

} // namespace
} // namespace morphogen
