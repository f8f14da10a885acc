// Custom gradients: hex parsing, stop lists, palette files, sessions and the colour map.

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/session/gradient.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;
using Rgb = std::array<float, 3>;

namespace {

// The InputError message of f(), or "" when it does not throw.
template <class F> std::string errorOf(F f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

std::string writeTemp(const std::string& name, const std::string& text) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

} // namespace

TEST(Gradient, HexColoursLongAndShort) {
    EXPECT_EQ(parseHexColour("#1b1b1b"), (Rgb{27 / 255.0f, 27 / 255.0f, 27 / 255.0f}));
    EXPECT_EQ(parseHexColour("#D9A441"), (Rgb{217 / 255.0f, 164 / 255.0f, 65 / 255.0f}));
    EXPECT_EQ(parseHexColour("#f80"), parseHexColour("#ff8800"));
    for (const char* bad : {"", "#", "1b1b1b", "#1b1b1", "#1b1b1b1", "#ggg", "#12345z", " #123"})
        EXPECT_FALSE(parseHexColour(bad)) << bad;
}

TEST(Gradient, HexRoundTrip) {
    for (const char* hex : {"#000000", "#ffffff", "#1b1b1b", "#d9a441", "#f4e8c1", "#0a7f80"})
        EXPECT_EQ(hexColour(*parseHexColour(hex)), hex);
}

TEST(Gradient, ListsOfTwoToSixteenStops) {
    const auto stops = parseGradient("#1b1b1b, #d9a441,#f4e8c1", "--colours");
    ASSERT_EQ(stops.size(), 3u);
    EXPECT_EQ(stops[1], *parseHexColour("#d9a441"));
    std::string sixteen = "#000", seventeen;
    for (int i = 1; i < 16; ++i)
        sixteen += ",#fff";
    EXPECT_EQ(parseGradient(sixteen, "--colours").size(), 16u);
    seventeen = sixteen + ",#123";
    EXPECT_NE(errorOf([&] { parseGradient(seventeen, "--colours"); }).find("17 colours given"),
              std::string::npos);
    EXPECT_NE(errorOf([] { parseGradient("#123456", "--colours"); }).find("1 colour given"),
              std::string::npos);
    const std::string bad = errorOf([] { parseGradient("#000,red", "--colours"); });
    EXPECT_NE(bad.find("--colours: 'red' is not a colour"), std::string::npos) << bad;
    EXPECT_NE(bad.find("#rgb or #rrggbb"), std::string::npos) << bad;
    EXPECT_NE(errorOf([] { parseGradient("#000,,#fff", "--colours"); }).find("'' is not"),
              std::string::npos);
}

TEST(Gradient, PaletteFilesTextAndJson) {
    const std::string text =
        writeTemp("palette.txt", "// dusk\n#1b1b1b\n#d9a441, #f4e8c1\n\n#fff\n");
    const auto t = loadPaletteFile(text);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[3], (Rgb{1, 1, 1}));
    const auto a = loadPaletteFile(writeTemp("palette_a.json", R"(["#000", "#808080"])"));
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[1], *parseHexColour("#808080"));
    EXPECT_EQ(
        loadPaletteFile(writeTemp("palette_o.json", R"({"colours": ["#000", "#111", "#222"]})"))
            .size(),
        3u);

    const std::string missing = errorOf([] { loadPaletteFile("/nonexistent/p.txt"); });
    EXPECT_NE(missing.find("/nonexistent/p.txt: cannot open palette file"), std::string::npos);
    const std::string one = writeTemp("palette_one.txt", "#123\n");
    EXPECT_NE(errorOf([&] { loadPaletteFile(one); }).find("1 colour given"), std::string::npos);
    const std::string number = writeTemp("palette_num.json", R"(["#000", 7])");
    EXPECT_NE(errorOf([&] { loadPaletteFile(number); }).find("7 is not a string"),
              std::string::npos);
    const std::string broken = writeTemp("palette_broken.json", R"(["#000", )");
    EXPECT_NE(errorOf([&] { loadPaletteFile(broken); }).find("not valid JSON"), std::string::npos);
}

TEST(Gradient, CustomMapSamplesItsStopsEvenlySpaced) {
    ColorMapSpec spec;
    spec.name = "custom";
    spec.colours = parseGradient("#000000,#ff0000,#ffffff", "test");
    EXPECT_EQ(colormapAnchors(spec), spec.colours);
    // A ramp 0, 1/4, 1/2, 3/4, 1: the middle cell is the middle stop, the
    // quarter cells half-way between stops.
    State ramp(5, 1, 1);
    for (int x = 0; x < 5; ++x)
        ramp.at(0, x, 0) = float(x);
    const std::vector<float> rgb = applyColormap(ramp, 0, spec);
    EXPECT_EQ((Rgb{rgb[6], rgb[7], rgb[8]}), (Rgb{1, 0, 0}));
    EXPECT_FLOAT_EQ(rgb[3], 0.5f);
    EXPECT_FLOAT_EQ(rgb[4], 0.0f);
    EXPECT_FLOAT_EQ(rgb[10], 0.5f);
    EXPECT_EQ((Rgb{rgb[12], rgb[13], rgb[14]}), (Rgb{1, 1, 1}));

    ColorMapSpec empty;
    empty.name = "custom";
    EXPECT_NE(errorOf([&] { colormapAnchors(empty); }).find("needs its colours"),
              std::string::npos);
    // Another map ignores the stops, and a session with it does not write them.
    ColorMapSpec other = spec;
    other.name = "viridis";
    other.levels = {0.2f, 0.8f};
    ColorMapSpec plain;
    plain.name = "viridis";
    plain.levels = other.levels;
    EXPECT_EQ(applyColormap(ramp, 0, other), applyColormap(ramp, 0, plain));
    Session s = loadPreset("gs_coral");
    s.colormap = other;
    EXPECT_FALSE(sessionToJson(s)["colormap"].contains("colours"));
    EXPECT_EQ(canonicalColormapName("Custom"), "custom");
}

TEST(Gradient, SessionRoundTripAndErrors) {
    Session s = loadPreset("gs_coral");
    nlohmann::json j = sessionToJson(s);
    j["colormap"] = {{"name", "custom"}, {"colours", {"#1b1b1b", "#d9a441", "#f4e8c1"}}};
    const Session custom = sessionFromJson(j, "test.json");
    EXPECT_EQ(custom.colormap.name, "custom");
    ASSERT_EQ(custom.colormap.colours.size(), 3u);
    const nlohmann::json back = sessionToJson(custom);
    EXPECT_EQ(back["colormap"]["colours"], nlohmann::json({"#1b1b1b", "#d9a441", "#f4e8c1"}));
    EXPECT_EQ(sessionFromJson(back, "back.json").colormap.colours, custom.colormap.colours);
    // A built-in map writes no stops.
    EXPECT_FALSE(sessionToJson(s)["colormap"].contains("colours"));

    // Stops without a name are a custom map.
    j["colormap"] = {{"colours", {"#000", "#fff"}}};
    EXPECT_EQ(sessionFromJson(j, "test.json").colormap.name, "custom");

    auto fails = [&](const nlohmann::json& cm, const std::string& needle) {
        j["colormap"] = cm;
        const std::string e = errorOf([&] { sessionFromJson(j, "test.json"); });
        EXPECT_NE(e.find(needle), std::string::npos) << cm.dump() << ": " << e;
    };
    fails({{"name", "custom"}}, "needs \"colours\"");
    fails({{"name", "viridis"}, {"colours", {"#000", "#fff"}}}, "apply only to the map");
    fails({{"colours", {"#000"}}}, "has 1 colours");
    fails({{"colours", {"#000", "#12"}}}, "colours[1]");
    fails({{"colours", "#000,#fff"}}, "must be an array");
}
