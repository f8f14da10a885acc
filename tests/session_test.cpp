// Presets and session files: every preset loads; broken files give errors that
// name the file, the field and what is accepted.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/session.hpp"
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
