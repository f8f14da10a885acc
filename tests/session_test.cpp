// Presets and session files: every preset loads; broken files give errors that
// name the file, the field and what is accepted.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;
using nlohmann::json;

namespace {

// Parses text as a session and returns the InputError message ("" if it parsed).
std::string errorFor(const std::string& text) {
    try {
        sessionFromJson(json::parse(text), "broken.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(Session, EveryPresetLoadsWithCompleteParameters) {
    const auto presets = allPresets();
    ASSERT_GE(presets.size(), 10u);
    for (const Session& s : presets) {
        SCOPED_TRACE(s.name);
        EXPECT_FALSE(s.description.empty());
        EXPECT_NO_THROW(validateSession(s, s.name));
        EXPECT_EQ(s.params.size(), s.reactionModel().params().size());
    }
}

TEST(Session, TheIssueRegimesArePresent) {
    for (const char* name : {"gs_mitosis", "gs_coral", "gs_worms", "gs_holes", "gs_chaos",
                             "gs_uniform", "turk_large_spots", "turk_small_spots",
                             "turk_irregular_spots", "mcgraw_turing", "mcgraw_steady"})
        EXPECT_NO_THROW(loadPreset(name)) << name;
}

TEST(Session, UnknownPresetListsTheKnownOnes) {
    try {
        loadPreset("gs_nope");
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("gs_nope"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("gs_coral"), std::string::npos);
    }
}

TEST(Session, JsonRoundTripKeepsEverything) {
    for (const Session& s : allPresets()) {
        SCOPED_TRACE(s.name);
        const Session back = sessionFromJson(sessionToJson(s), "roundtrip");
        EXPECT_EQ(sessionToJson(back), sessionToJson(s));
        EXPECT_EQ(back.params, s.params);
        EXPECT_EQ(back.seed, s.seed);
        EXPECT_EQ(back.init.base, s.init.base);
        EXPECT_EQ(back.init.type, s.init.type);
    }
    Session windowed = loadPreset("gs_coral");
    windowed.colormap.levels = {0.25f, 0.75f};
    EXPECT_EQ(sessionFromJson(sessionToJson(windowed), "roundtrip").colormap.levels,
              windowed.colormap.levels);
}

TEST(Session, BrokenFieldsAreNamed) {
    struct Case {
        const char* json;
        const char* mustMention;
    };
    const Case cases[] = {
        {R"({"model": 3})", "'model' must be a string"},
        {R"({"model": "grey_scott"})", "known: gray_scott"},
        {R"({"model": "gray_scott", "params": {"F": "fast"}})", "'params.F' must be a number"},
        {R"({"model": "gray_scott", "params": {"Q": 1}})", "'params.Q' is not a parameter"},
        {R"({"model": "gray_scott", "params": {"F": 5}})", "'params.F' is 5, accepted range"},
        {R"({"model": "gray_scott", "size": 0})", "'size' is 0"},
        {R"({"model": "gray_scott", "size": [64]})", "'size' must be an integer N or an array"},
        {R"({"model": "gray_scott", "size": 99999})", "accepted range"},
        {R"({"model": "gray_scott", "edges": "mirror"})", "accepted: periodic, clamped"},
        {R"({"model": "gray_scott", "diffusion": {"stencil": "7-point"}})",
         "accepted: 5-point, 9-point"},
        {R"({"model": "gray_scott", "diffusion": {"type": "anisotropic"}})",
         "'diffusion.tensors' is required"},
        {R"({"model": "gray_scott", "diffusion": {"type": "generalized", "tensors": {"q": "c"}}})",
         "'diffusion.tensors.q' is not a chemical"},
        {R"({"model": "gray_scott", "dt": -1})", "'dt' is -1"},
        {R"({"model": "gray_scott", "steps": 1.5})", "'steps' must be an integer"},
        {R"({"model": "gray_scott", "init": {"type": "blob"}})", "accepted: noise, centre_square"},
        {R"({"model": "gray_scott", "init": {"base": {"w": 1}}})",
         "'init.base.w' is not a chemical"},
        {R"({"model": "gray_scott", "colormap": {"low": [1, 2]}})", "array of 3 numbers"},
        {R"({"model": "gray_scott", "colormap": {"levels": [0.5, 0.2]}})",
         "'colormap.levels' must be an array [low, high] with 0 <= low < high <= 1"},
        {R"({"model": "gray_scott", "colormap": {"levels": [0, 2]}})", "colormap.levels[1]"},
        {R"({"model": "gray_scott", "colour": 1})", "unknown field 'colour'"},
        {R"([1, 2])", "must be a JSON object"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.json);
        const std::string message = errorFor(c.json);
        EXPECT_NE(message.find("broken.json"), std::string::npos) << message;
        EXPECT_NE(message.find(c.mustMention), std::string::npos) << message;
    }
}

TEST(Session, FilesWithBadJsonOrMissingFilesAreInputErrors) {
    const auto dir = test::scratchDir("morphogen_session_test");
    const std::string bad = (dir / "bad.json").string();
    std::ofstream(bad) << "{\"model\": \"gray_scott\", ";
    try {
        loadSessionFile(bad);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos);
    }
    EXPECT_THROW(loadSessionFile((dir / "missing.json").string()), InputError);
}

TEST(Session, SaveThenLoadReproducesTheSession) {
    const auto dir = test::scratchDir("morphogen_session_test");
    const std::string path = (dir / "saved.json").string();
    Session s = loadPreset("turk_small_spots");
    s.seed = 77;
    s.params["s"] = 0.15f;
    saveSessionFile(s, path);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
    const Session back = loadSessionFile(path);
    EXPECT_EQ(sessionToJson(back), sessionToJson(s));
}

TEST(Session, ParamOverrides) {
    Session s = loadPreset("gs_coral");
    applyParamOverride(s, "F=0.04");
    EXPECT_FLOAT_EQ(s.params.at("F"), 0.04f);
    EXPECT_THROW(applyParamOverride(s, "F"), InputError);
    EXPECT_THROW(applyParamOverride(s, "F=abc"), InputError);
    EXPECT_THROW(applyParamOverride(s, "F=0.04x"), InputError);
    EXPECT_THROW(applyParamOverride(s, "Z=1"), InputError);
    EXPECT_THROW(applyParamOverride(s, "F=3"), InputError);
    EXPECT_THROW(applyParamOverride(s, "F=nan"), InputError);
}

TEST(Session, InitReplacesTheModelDefaultWhole) {
    // mcgraw_steady names base values only: it must not inherit the model's noise.
    const Session s = loadPreset("mcgraw_steady");
    EXPECT_TRUE(s.init.noise.empty());
}

TEST(Session, ModelChangingStagesParseAndRoundTrip) {
    const char* text = R"({"model": "turing_turk", "size": 32,
        "stages": [{"steps": 10},
                   {"steps": 20, "model": "meinhardt_stripes", "dt": 0.5,
                    "init": {"type": "seed_spots", "count": 2, "radius": 0,
                             "base": {"g1": 0.75, "substrate": 1}, "inside": {"substrate": 1.1}},
                    "params": {"Dg": 0.02},
                    "freeze": {"chemical": "b", "min": 0, "max": 4},
                    "reset": {"g1": 1.5, "s2": 0}},
                   {"steps": 5, "params": {"Dg": 0.01}}],
        "colormap": {"chemical": "s1"}})";
    const Session s = sessionFromJson(json::parse(text), "cascade.json");
    ASSERT_EQ(s.stages.size(), 3u);
    EXPECT_EQ(s.steps, 35);
    EXPECT_EQ(s.reactionModel().name(), "turing_turk");
    EXPECT_EQ(s.outputModel().name(), "meinhardt_stripes");
    EXPECT_EQ(stageModel(s.stages, 0, s.reactionModel()).name(), "turing_turk");
    EXPECT_EQ(stageModel(s.stages, 2, s.reactionModel()).name(), "meinhardt_stripes");
    const Stage& change = s.stages[1];
    EXPECT_EQ(change.model, "meinhardt_stripes");
    ASSERT_TRUE(change.dt.has_value());
    EXPECT_EQ(*change.dt, 0.5f);
    ASSERT_TRUE(change.init.has_value());
    EXPECT_EQ(change.init->type, InitialCondition::Type::SeedSpots);
    EXPECT_EQ(change.init->spotCount, 2);
    EXPECT_EQ(change.init->inside.at("substrate"), 1.1f);
    EXPECT_EQ(change.params.at("Dg"), 0.02f);
    EXPECT_EQ(change.freeze->chemical, "b");
    EXPECT_EQ(change.reset.at("g1"), 1.5f);
    EXPECT_TRUE(s.stages[2].model.empty());
    EXPECT_FALSE(s.stages[2].init.has_value());
    EXPECT_NO_THROW(validateSession(s, "cascade.json"));
    // The session reproduces itself.
    const json j = sessionToJson(s);
    EXPECT_EQ(sessionToJson(sessionFromJson(j, "again")), j);
    EXPECT_EQ(j["stages"][1]["model"], "meinhardt_stripes");
    EXPECT_FALSE(j["stages"][2].contains("model"));

    // Stage parameters are checked against their stage's model.
    Session bad = s;
    bad.stages[1].params["Dg"] = 100.0f;
    EXPECT_THROW(validateSession(bad, "x"), InputError);
    bad = s;
    bad.stages[2].params["s"] = 0.1f; // turing_turk's, not meinhardt_stripes'
    EXPECT_THROW(validateSession(bad, "x"), InputError);
}

TEST(Session, BrokenModelChangingStagesAreNamed) {
    struct Case {
        const char* stage1; // the second stage of a turing_turk cascade
        const char* extra;  // more top-level fields
        const char* mustMention;
    };
    const Case cases[] = {
        {R"({"model": "zebra"})", "", "'stages[1].model' is 'zebra', not a known model (known: "},
        {R"({"model": 7})", "", "'stages[1].model' must be a string"},
        {R"({"init": {"base": {"a": 1}}})", "",
         "'stages[1].init' is only accepted on a stage that sets 'model'"},
        {R"({"model": "meinhardt_stripes", "params": {"s": 0.1}})", "",
         "'stages[1].params.s' is not a parameter of model 'meinhardt_stripes'"},
        {R"({"model": "meinhardt_stripes", "params": {"Dg": -1}})", "",
         "'stages[1].params.Dg' is -1"},
        {R"({"model": "meinhardt_stripes", "freeze": {"chemical": "g1"}})", "",
         "'stages[1].freeze.chemical' is 'g1', not a chemical of model 'turing_turk' (the "
         "previous stage's model"},
        {R"({"model": "meinhardt_stripes", "freeze": {"chemical": "b"}, "reset": {"a": 4}})", "",
         "'stages[1].reset.a' is not a chemical of model 'meinhardt_stripes'"},
        {R"({"model": "meinhardt_stripes", "reset": {"g1": 4}})", "",
         "'stages[1].reset' needs frozen cells: add a \"freeze\" rule"},
        {R"({"model": "meinhardt_stripes", "init": {"base": {"a": 1}}})", "",
         "'stages[1].init.base.a' is not a chemical of model 'meinhardt_stripes'"},
        {R"({"model": "meinhardt_stripes", "init": {"type": "blob"}})", "",
         "'stages[1].init.type' is 'blob'"},
        {R"({"model": "meinhardt_stripes", "init": {"colour": 1}})", "",
         "unknown field 'stages[1].init.colour'"},
        {R"({"modle": "meinhardt_stripes"})", "", "unknown field 'stages[1].modle'"},
        {R"({"model": "meinhardt_stripes", "dt": -1})", "", "'stages[1].dt' is -1"},
        {R"({"model": "meinhardt_stripes"})", R"(, "colormap": {"chemical": "b"})",
         "'colormap.chemical' is 'b', not a chemical of model 'meinhardt_stripes' (the last "
         "stage's model)"},
        {R"({"model": "meinhardt_stripes"})",
         R"(, "param_maps": {"s": {"field": "linear_x", "range": [0.05, 0.1]}})",
         "'param_maps' cannot be combined with a stage that changes the model"},
    };
    for (const Case& c : cases) {
        const std::string text =
            std::string(R"({"model": "turing_turk", "stages": [{"steps": 1}, )") + c.stage1 + "]" +
            c.extra + "}";
        SCOPED_TRACE(text);
        const std::string message = errorFor(text);
        EXPECT_NE(message.find("broken.json"), std::string::npos) << message;
        EXPECT_NE(message.find(c.mustMention), std::string::npos) << message;
    }
    EXPECT_NE(errorFor(R"({"model": "turing_turk",
                           "stages": [{"steps": 1, "model": "meinhardt_stripes"}]})")
                  .find("'stages[0].model' cannot be set on the first stage"),
              std::string::npos);
}

// Common spellings in a session file read as the canonical names, which are
// what the session writes back; near misses name the intended key or value.
TEST(Session, AliasesAreWrittenCanonicallyAndTyposSuggested) {
    const Session s =
        sessionFromJson(json::parse(R"({"model": "Gray-Scott", "size": 16, "edges": "wrap",
                        "integrator": "semi-implicit",
                        "init": {"type": "center_square"}})"),
                        "aliases.json");
    const json written = sessionToJson(s);
    EXPECT_EQ(written["model"], "gray_scott");
    EXPECT_EQ(written["edges"], "periodic");
    EXPECT_EQ(written["integrator"], "semi_implicit");
    EXPECT_EQ(written["init"]["type"], "centre_square");

    EXPECT_NE(errorFor(R"({"model": "gray_scot"})").find("(did you mean 'gray_scott'?)"),
              std::string::npos);
    EXPECT_NE(
        errorFor(R"({"model": "gray_scott", "edgse": "periodic"})").find("(did you mean 'edges'?)"),
        std::string::npos);
    EXPECT_NE(
        errorFor(R"({"model": "gray_scott", "params": {"Dw": 0.1}})").find("(did you mean 'Du'?)"),
        std::string::npos);
    const std::string far = errorFor(R"({"model": "gray_scott", "edges": "spherical"})");
    EXPECT_NE(far.find("accepted: periodic, clamped"), std::string::npos);
    EXPECT_EQ(far.find("did you mean"), std::string::npos);
}
