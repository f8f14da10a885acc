// render's knob flags (--theta, --orientation, --anisotropy, --param-map, --init
// and its values): each flag must give the session its JSON twin gives, and
// refuse what the JSON reader refuses, naming the flag.

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/knob_flags.hpp"
#include "core/base/errors.hpp"
#include "core/session/session.hpp"

using namespace morphogen;
using morphogen::cli::applyKnobFlags;
using morphogen::cli::KnobFlags;
using nlohmann::json;

namespace {

// The InputError message of applying `flags` to the preset ("" when accepted).
std::string errorFor(const std::string& preset, const KnobFlags& flags) {
    Session s = loadPreset(preset);
    try {
        applyKnobFlags(flags, s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The preset with `patch` merged into its JSON, read by the session reader:
// what a user editing the JSON gets.
Session presetWithJson(const std::string& preset, const json& patch) {
    json j = sessionToJson(loadPreset(preset));
    j.merge_patch(patch);
    return sessionFromJson(j, "patched " + preset);
}

std::string errorForJson(const std::string& preset, const json& patch) {
    try {
        presetWithJson(preset, patch);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(KnobFlags, OrientationTextBecomesItsJsonField) {
    using morphogen::cli::orientationFlagJson;
    EXPECT_EQ(orientationFlagJson("concentric:0.3,0.7"),
              json::parse(R"({"type": "concentric", "centre": [0.3, 0.7]})"));
    EXPECT_EQ(orientationFlagJson("radial"), json::parse(R"({"type": "radial"})"));
    EXPECT_EQ(orientationFlagJson("constant:-30"),
              json::parse(R"({"type": "constant", "angle": -30})"));
    // The angle and centre of a spiral come in either order.
    const json spiral = json::parse(R"({"type": "spiral", "angle": 30, "centre": [0.2, 0.4]})");
    EXPECT_EQ(orientationFlagJson("spiral:30:0.2,0.4"), spiral);
    EXPECT_EQ(orientationFlagJson("Spiral:0.2,0.4:30"), spiral);
    EXPECT_EQ(orientationFlagJson("vortex:90.5"),
              json::parse(R"({"type": "vortex", "angle": 90.5})"));
    // "image" is short for the JSON's image_gradient; the file keeps its colons.
    EXPECT_EQ(orientationFlagJson("image:dir/a:b.png"),
              json::parse(R"({"type": "image_gradient", "image": "dir/a:b.png"})"));

    auto message = [](const std::string& text) {
        try {
            orientationFlagJson(text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_TRUE(contains(message("spiral"), "spiral needs its twist")) << message("spiral");
    EXPECT_TRUE(contains(message("radial:45"), "radial takes only a centre"));
    EXPECT_TRUE(contains(message("concentrc:0.5,0.5"), "(did you mean 'concentric'?)"));
    EXPECT_TRUE(contains(message("radial:0.5,x"), "'x' is not a number"));
    EXPECT_TRUE(contains(message("radial:0.5"), "--orientation 'radial:0.5'"));
    EXPECT_TRUE(contains(message("blend"), "once per field"));
    EXPECT_TRUE(contains(message("image"), "needs the image"));
}

TEST(KnobFlags, ParamMapTextBecomesItsJsonMap) {
    using morphogen::cli::paramMapFlagJson;
    EXPECT_EQ(paramMapFlagJson("k=linear_x:0.05:0.07"),
              std::make_pair(std::string("k"),
                             json::parse(R"({"field": "linear_x", "range": [0.05, 0.07]})")));
    EXPECT_EQ(paramMapFlagJson("F=radial:0.02:0.06:0.25,0.75").second,
              json::parse(R"({"field": "radial", "range": [0.02, 0.06], "centre": [0.25, 0.75]})"));
    EXPECT_EQ(paramMapFlagJson("F=noise:0.02:0.06:24").second,
              json::parse(R"({"field": "noise", "range": [0.02, 0.06], "scale": 24})"));
    EXPECT_EQ(
        paramMapFlagJson("k=image:masks/a:b.png:0.06:0.05").second,
        json::parse(R"({"field": "image", "image": "masks/a:b.png", "range": [0.06, 0.05]})"));
    EXPECT_TRUE(paramMapFlagJson("Dp=none").second.is_null());

    auto message = [](const std::string& text) {
        try {
            paramMapFlagJson(text);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_TRUE(contains(message("k=linear_x:0.05"), "expected k=linear_x:LOW:HIGH"));
    EXPECT_TRUE(contains(message("k=linear_x:0.05:0.06:3"), "expected k=linear_x:LOW:HIGH"));
    EXPECT_TRUE(contains(message("k=image:0.05:0.06"), "expected k=image:FILE:LOW:HIGH"));
    EXPECT_TRUE(contains(message("k=linearx:0.05:0.06"), "(did you mean 'linear_x'?)"));
    EXPECT_TRUE(contains(message("linear_x:0.05:0.06"), "expected NAME=FIELD:LOW:HIGH"));
}

TEST(KnobFlags, ThetaTurnsTheTensorsAsTheJsonDoes) {
    KnobFlags f;
    f.theta = "45";
    Session s = loadPreset("wk_zebra");
    EXPECT_TRUE(applyKnobFlags(f, s).empty());
    const Session twin = presetWithJson("wk_zebra", json::parse(R"({"diffusion": {"tensors": {
        "p": {"theta": 45}, "m": {"theta": 45}}}})"));
    EXPECT_EQ(diffusionToJson(s.diffusion), diffusionToJson(twin.diffusion));
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("p").theta, 45.0f);
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("p").a1, 2.0f); // the rates stay
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("m").a2, 1.5f);
}

TEST(KnobFlags, ThetaKeepsTheAnglesBetweenPairs) {
    // wk_weave's pairs run at 0 and 90 degrees: --theta 30 turns the weave.
    KnobFlags f;
    f.theta = "30";
    Session s = loadPreset("wk_weave");
    applyKnobFlags(f, s);
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("p1").theta, 30.0f);
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("m1").theta, 30.0f);
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("p2").theta, 120.0f);
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("m2").theta, 120.0f);
}

TEST(KnobFlags, ThetaReplacesAnOrientationFieldAndSaysSo) {
    KnobFlags f;
    f.theta = "-20";
    Session s = loadPreset("wk_spiral_stripes");
    ASSERT_TRUE(s.diffusion.map);
    const std::vector<std::string> notes = applyKnobFlags(f, s);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_TRUE(contains(notes[0], "'spiral' orientation field")) << notes[0];
    EXPECT_FALSE(s.diffusion.map); // a map without a scale image goes: plain 3x3 kernels
    EXPECT_FLOAT_EQ(s.diffusion.anisotropic.at("p").theta, -20.0f);
}

TEST(KnobFlags, ThetaMakesIsotropicDiffusionAnisotropic) {
    KnobFlags f;
    f.theta = "60";
    Session s = loadPreset("gs_coral");
    ASSERT_EQ(s.diffusion.type, DiffusionType::Isotropic);
    const std::vector<std::string> notes = applyKnobFlags(f, s);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_TRUE(contains(notes[0], "--anisotropy 4")) << notes[0];
    EXPECT_EQ(s.diffusion.type, DiffusionType::Anisotropic);
    for (const char* c : {"u", "v"}) {
        const AnisotropicTensor& t = s.diffusion.anisotropic.at(c);
        EXPECT_FLOAT_EQ(t.theta, 60.0f);
        EXPECT_FLOAT_EQ(t.a1, 1.0f); // the model's rate along theta
        EXPECT_FLOAT_EQ(t.a2 * t.a2, 1.0f / float(cli::kDefaultAnisotropy));
    }

    f.anisotropy = "9";
    Session nine = loadPreset("gs_coral");
    EXPECT_TRUE(applyKnobFlags(f, nine).empty()); // asked for: no note
    EXPECT_FLOAT_EQ(nine.diffusion.anisotropic.at("v").a2, 1.0f / 3.0f);

    KnobFlags alone;
    alone.anisotropy = "2";
    Session s2 = loadPreset("turk_large_spots");
    applyKnobFlags(alone, s2);
    EXPECT_FLOAT_EQ(s2.diffusion.anisotropic.at("a").theta, 0.0f);
    EXPECT_FLOAT_EQ(s2.diffusion.anisotropic.at("b").a2, 1.0f / std::sqrt(2.0f));
}

TEST(KnobFlags, OrientationFieldsAsTheJsonMap) {
    KnobFlags f;
    f.orientation = {"concentric:0.5,0.25"};
    Session s = loadPreset("wk_zebra"); // tensors at 90: a field puts them at 0 along it
    applyKnobFlags(f, s);
    const Session twin = presetWithJson("wk_zebra", json::parse(R"({"diffusion": {
        "tensors": {"p": {"theta": 0}, "m": {"theta": 0}},
        "map": {"orientation": {"type": "concentric", "centre": [0.5, 0.25]}}}})"));
    EXPECT_EQ(diffusionToJson(s.diffusion), diffusionToJson(twin.diffusion));
    ASSERT_TRUE(s.diffusion.map);
    EXPECT_EQ(s.diffusion.map->orientation.type, OrientationField::Type::Concentric);
    EXPECT_FLOAT_EQ(s.diffusion.map->orientation.centreY, 0.25f);

    // --theta with a field turns the tensors relative to it.
    f.theta = "90";
    Session radialAcross = loadPreset("wk_zebra");
    applyKnobFlags(f, radialAcross);
    EXPECT_FLOAT_EQ(radialAcross.diffusion.anisotropic.at("m").theta, 90.0f);
    EXPECT_EQ(radialAcross.diffusion.map->orientation.type, OrientationField::Type::Concentric);

    // Several fields blend; the spiral preset's scale is kept.
    KnobFlags blend;
    blend.orientation = {"radial:0.25,0.5", "spiral:45:0.75,0.5"};
    Session b = loadPreset("wk_spiral_stripes");
    applyKnobFlags(blend, b);
    const OrientationField& o = b.diffusion.map->orientation;
    EXPECT_EQ(o.type, OrientationField::Type::Blend);
    ASSERT_EQ(o.parts.size(), 2u);
    EXPECT_EQ(o.parts[1].type, OrientationField::Type::Spiral);
    EXPECT_FLOAT_EQ(o.parts[1].angle, 45.0f);
    EXPECT_FLOAT_EQ(o.parts[0].centreX, 0.25f);
}

TEST(KnobFlags, OrientationRefusalsNameTheFlagAndTheReason) {
    KnobFlags theta;
    theta.theta = "10";
    EXPECT_TRUE(contains(errorFor("gs_generalized_c", theta), "diffusion is generalized"));
    // A cascade that changes model needs isotropic diffusion (the session reader's rule).
    EXPECT_TRUE(contains(errorFor("turk_giraffe", theta), "--theta 10: stage 2"));
    theta.theta = "ten";
    EXPECT_TRUE(contains(errorFor("wk_zebra", theta), "--theta: 'ten' is not a number"));
    // The JSON reader's range, with the flag in front.
    theta.theta = "5000";
    const std::string big = errorFor("wk_zebra", theta);
    EXPECT_TRUE(contains(big, "--theta 5000: field 'diffusion.tensors.")) << big;
    EXPECT_TRUE(contains(big, ".theta' is 5000, accepted range is [-3600, 3600]")) << big;

    KnobFlags ratio;
    ratio.anisotropy = "3";
    EXPECT_TRUE(contains(errorFor("wk_zebra", ratio), "already anisotropic"));
    ratio.anisotropy = "0.5";
    EXPECT_TRUE(contains(errorFor("gs_coral", ratio), "--anisotropy 0.5: accepted are 1..10000"));

    KnobFlags far;
    far.orientation = {"radial:20,0.5"};
    const std::string centre = errorFor("wk_zebra", far);
    EXPECT_TRUE(contains(centre, "field 'diffusion.map.orientation.centre[0]' is 20")) << centre;
    KnobFlags missing;
    missing.orientation = {"image:no_such_image.png"};
    EXPECT_TRUE(contains(errorFor("wk_zebra", missing), "no_such_image.png: image not found"));
}

TEST(KnobFlags, ParamMapsGoThroughTheJsonReader) {
    KnobFlags f;
    f.paramMaps = {"k=linear_x:0.05:0.065", "F=radial:0.03:0.05:0.25,0.75"};
    Session s = loadPreset("gs_coral");
    applyKnobFlags(f, s);
    const Session twin = presetWithJson("gs_coral", json::parse(R"({"param_maps": {
        "k": {"field": "linear_x", "range": [0.05, 0.065]},
        "F": {"field": "radial", "range": [0.03, 0.05], "centre": [0.25, 0.75]}}})"));
    EXPECT_EQ(paramMapsToJson(s.paramMaps), paramMapsToJson(twin.paramMaps));
    EXPECT_EQ(s.paramMaps.at("F").field, ParamMapSpec::Field::Radial);
    EXPECT_FLOAT_EQ(s.paramMaps.at("F").centreY, 0.75f);

    // Out of range: the JSON reader's words for the JSON twin, behind the flag.
    KnobFlags wide;
    wide.paramMaps = {"k=linear_x:0:1"};
    const std::string flagError = errorFor("gs_coral", wide);
    const std::string jsonError = errorForJson(
        "gs_coral",
        json::parse(R"({"param_maps": {"k": {"field": "linear_x", "range": [0, 1]}}})"));
    const std::string reason = "field 'param_maps.k.range[1]' is 1, accepted range is [0, 0.2]";
    EXPECT_TRUE(contains(flagError, "--param-map 'k=linear_x:0:1': " + reason)) << flagError;
    EXPECT_TRUE(contains(jsonError, reason)) << jsonError;

    KnobFlags unknown;
    unknown.paramMaps = {"kk=linear_x:0:0.1"};
    EXPECT_TRUE(contains(errorFor("gs_coral", unknown), "(did you mean 'k'?)"));
    KnobFlags twice;
    twice.paramMaps = {"k=linear_x:0.05:0.06", "k=noise:0.05:0.06"};
    EXPECT_TRUE(contains(errorFor("gs_coral", twice), "'k' is mapped twice"));
    KnobFlags noise;
    noise.paramMaps = {"k=noise:0.05:0.06:0.5"};
    EXPECT_TRUE(contains(errorFor("gs_coral", noise), "field 'param_maps.k.scale' is 0.5"));
}

TEST(KnobFlags, ParamMapsRefuseWhatTheSessionReaderRefuses) {
    KnobFlags f;
    f.paramMaps = {"k=linear_x:0.05:0.06"};
    EXPECT_TRUE(contains(errorFor("gs_coral_multigrid", f), "coarse-to-fine schedule"));
    f.paramMaps = {"s=linear_x:0.03:0.06"};
    EXPECT_TRUE(contains(errorFor("turk_giraffe", f), "changes the model"));
    // turk_leopard's second stage sets s.
    EXPECT_TRUE(contains(errorFor("turk_leopard", f), "stage 2 of this cascade sets 's'"));
}

TEST(KnobFlags, ParamMapImagesAreAbsoluteAndNoneRemovesAMap) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "morphogen_knob_flags_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path mask = dir / "mask.png";
    std::ofstream(mask) << "not read by the flags";
    KnobFlags f;
    f.paramMaps = {"k=image:" + mask.string() + ":0.06:0.07"};
    Session s = loadPreset("gs_coral");
    applyKnobFlags(f, s);
    EXPECT_EQ(s.paramMaps.at("k").image, mask.string());
    EXPECT_FLOAT_EQ(s.paramMaps.at("k").max, 0.07f);

    Session haunch = loadPreset("wk_zebra_haunch");
    ASSERT_EQ(haunch.paramMaps.count("Dp"), 1u);
    KnobFlags none;
    none.paramMaps = {"Dp=none"};
    applyKnobFlags(none, haunch);
    EXPECT_EQ(haunch.paramMaps.count("Dp"), 0u);
    EXPECT_TRUE(contains(errorFor("gs_coral", none), "no map of 'Dp' to remove"));
    std::filesystem::remove_all(dir);
}

TEST(KnobFlags, InitialConditionsAsTheJson) {
    KnobFlags f;
    f.init = "grid"; // a spelling the JSON accepts too
    f.spacing = "20";
    f.jitter = "0.1";
    f.spotRadius = "2.5";
    Session s = loadPreset("gs_coral");
    applyKnobFlags(f, s);
    EXPECT_EQ(s.init.type, InitialCondition::Type::JitteredGrid);
    EXPECT_FLOAT_EQ(s.init.spacing, 20.0f);
    EXPECT_FLOAT_EQ(s.init.jitter, 0.1f);
    EXPECT_FLOAT_EQ(s.init.spotRadius, 2.5f);
    const Session twin = presetWithJson("gs_coral", json::parse(R"({"init": {
        "type": "jittered_grid", "spacing": 20, "jitter": 0.1, "radius": 2.5}})"));
    EXPECT_EQ(initialConditionToJson(s.init), initialConditionToJson(twin.init));

    KnobFlags spots;
    spots.spots = "7";
    spots.initInside = {"v=0.3"};
    spots.initNoise = {"u=0,v=0"};
    Session g = loadPreset("gs_coral");
    applyKnobFlags(spots, g);
    EXPECT_EQ(g.init.spotCount, 7);
    EXPECT_FLOAT_EQ(g.init.inside.at("v"), 0.3f);
    EXPECT_FLOAT_EQ(g.init.inside.at("u"), 0.5f); // merged, not replaced
    EXPECT_FLOAT_EQ(g.init.noise.at("u"), 0.0f);

    KnobFlags square;
    square.init = "centre_square";
    square.square = "0.4";
    Session q = loadPreset("gs_coral");
    applyKnobFlags(square, q);
    EXPECT_EQ(q.init.type, InitialCondition::Type::CentreSquare);
    EXPECT_FLOAT_EQ(q.init.squareFraction, 0.4f);
}

TEST(KnobFlags, InitialConditionRefusals) {
    KnobFlags spacing;
    spacing.spacing = "10"; // gs_coral starts from seed spots
    EXPECT_TRUE(contains(errorFor("gs_coral", spacing),
                         "--spacing 10: applies to --init jittered_grid; this session starts "
                         "from seed_spots"));
    KnobFlags half;
    half.spots = "2.5";
    EXPECT_TRUE(
        contains(errorFor("gs_coral", half), "--spots 2.5: field 'init.count' must be an integer"));
    KnobFlags jitter;
    jitter.init = "jittered_grid";
    jitter.jitter = "2";
    EXPECT_TRUE(contains(errorFor("gs_coral", jitter),
                         "--jitter 2: field 'init.jitter' is 2, accepted range is [0, 1]"));
    KnobFlags type;
    type.init = "sead_spots";
    EXPECT_TRUE(contains(errorFor("gs_coral", type), "(did you mean 'seed_spots'?)"));
    // Turk's start has no inside values: spots would start like everything else.
    KnobFlags turk;
    turk.init = "seed_spots";
    EXPECT_TRUE(contains(errorFor("turk_large_spots", turk), "add --init-inside"));
    turk.initInside = {"a=8"};
    EXPECT_EQ(errorFor("turk_large_spots", turk), "");
    turk.initInside = {"q=8"};
    EXPECT_TRUE(contains(errorFor("turk_large_spots", turk),
                         "--init-inside 'q=8': field 'init.inside.q' is not a chemical"));
}

// --gravity ANGLE:STRENGTH is the JSON "gravity" block, read by its reader:
// the same values, ranges and messages (prefixed with the flag); off clears it.
TEST(KnobFlags, GravityIsTheJsonBlock) {
    KnobFlags f;
    f.gravity = "250:0.4";
    Session s = loadPreset("watercolour_wet_in_wet");
    applyKnobFlags(f, s);
    EXPECT_EQ(s.gravity, presetWithJson("watercolour_wet_in_wet",
                                        {{"gravity", {{"angle", 250}, {"strength", 0.4}}}})
                             .gravity);
    EXPECT_EQ(s.gravity, (Gravity{250.0, 0.4}));
    f.gravity = "off";
    applyKnobFlags(f, s);
    EXPECT_FALSE(s.gravity.active());
    EXPECT_TRUE(loadPreset("watercolour_drops").gravity.active());

    f.gravity = "270";
    EXPECT_TRUE(contains(errorFor("watercolour_drops", f), "is not ANGLE:STRENGTH"));
    f.gravity = "270:fast";
    EXPECT_TRUE(contains(errorFor("watercolour_drops", f), "'fast' is not a number"));
    f.gravity = "270:-1";
    const std::string negative = errorFor("watercolour_drops", f);
    EXPECT_TRUE(contains(negative, "--gravity")) << negative;
    EXPECT_TRUE(contains(negative, "gravity.strength")) << negative;
    f.gravity = "400:1";
    EXPECT_TRUE(contains(errorFor("watercolour_drops", f), "gravity.angle"));

    // --gravity-direction X,Y,Z: the block's direction (on a model), strength kept.
    KnobFlags d;
    d.gravityDirection = "1,-2,0.5";
    Session drops = loadPreset("watercolour_drops");
    applyKnobFlags(d, drops);
    EXPECT_EQ(drops.gravity.direction, (std::array<double, 3>{1, -2, 0.5}));
    EXPECT_EQ(drops.gravity.strength, loadPreset("watercolour_drops").gravity.strength);
    d.gravityDirection = "0,-1";
    EXPECT_TRUE(contains(errorFor("watercolour_drops", d), "is not X,Y,Z"));
    d.gravityDirection = "0,0,0";
    const std::string zero = errorFor("watercolour_drops", d);
    EXPECT_TRUE(contains(zero, "--gravity-direction")) << zero;
    EXPECT_TRUE(contains(zero, "gravity.direction")) << zero;
    d.gravityDirection = "0,down,0";
    EXPECT_TRUE(contains(errorFor("watercolour_drops", d), "'down' is not a number"));
}
