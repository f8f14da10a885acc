// What `map` and `sweep` start from (--start) and the sessions their --pick writes.

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/analysis/pattern_classifier.hpp"
#include "core/base/errors.hpp"
#include "core/models/reaction_model.hpp"
#include "core/sim/exploration_points.hpp"
#include "core/sim/initial_state.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

const ReactionModel& model(const std::string& name) {
    const ReactionModel* m = findModel(name);
    EXPECT_NE(m, nullptr) << name;
    return *m;
}

// A Gray-Scott sweep as `sweep --model gray_scott --x k:.. --y F:..` makes it, noise start.
SweepSpec grayScottSweep(int columns, int rows, int tile) {
    SweepSpec spec;
    const ReactionModel& gs = model("gray_scott");
    spec.base.model = gs.name();
    for (const ParamSpec& p : gs.params())
        spec.base.params[p.name] = p.defaultValue;
    spec.base.dt = gs.defaultDt();
    spec.base.init = noiseStart(gs.defaultInit(), gs);
    spec.base.steps = 10;
    spec.x = {"k", 0.05f, 0.07f};
    spec.y = {"F", 0.02f, 0.05f};
    spec.columns = columns;
    spec.rows = rows;
    spec.tile = tile;
    spec.base.width = spec.base.height = tile;
    return spec;
}

// Share of cells whose v is raised into a seed (u = 0.5, v = 0.25 inside, v ~ 0 outside).
double seededShare(const State& s, int x0, int y0, int w, int h) {
    int seeded = 0;
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x)
            seeded += s.at(1, x, y) > 0.1f;
    return double(seeded) / (w * h);
}

} // namespace

TEST(ExplorationStart, NamesReadBothWays) {
    EXPECT_EQ(parseExplorationStart("noise"), ExplorationStart::Noise);
    EXPECT_EQ(parseExplorationStart("Preset"), ExplorationStart::Preset);
    EXPECT_FALSE(parseExplorationStart("seeds").has_value());
    EXPECT_EQ(toString(ExplorationStart::Noise), "noise");
    EXPECT_EQ(explorationStartNames(), "noise, preset");
}

// Noise around Gray-Scott's trivial state u = 1, v = 0 decays everywhere, so the noise start
// seeds the whole area instead: discs on a fully jittered lattice, about a fifth covered, in
// every region of a large grid.
TEST(ExplorationStart, GrayScottNoiseStartSeedsTheWholeArea) {
    const ReactionModel& gs = model("gray_scott");
    const InitialCondition start = noiseStart(gs.defaultInit(), gs);
    EXPECT_EQ(start.type, InitialCondition::Type::JitteredGrid);
    EXPECT_EQ(start.jitter, 1.0f);
    EXPECT_EQ(start.spotRadius, gs.defaultInit().spotRadius);
    EXPECT_NEAR(start.spacing, 4 * std::sqrt(2.0f) * start.spotRadius, 1e-4);
    EXPECT_EQ(start.inside.at("v"), 0.25f);
    EXPECT_EQ(start.base.at("u"), 1.0f);

    Session s;
    s.model = "gray_scott";
    s.params = {{"F", 0.03f}, {"k", 0.06f}, {"Du", 0.2097f}, {"Dv", 0.105f}};
    s.width = s.height = 256;
    s.init = start;
    const State state = initialState(s);
    const double share = seededShare(state, 0, 0, 256, 256);
    EXPECT_GT(share, 0.10);
    EXPECT_LT(share, 0.30);
    // Every 64 x 64 block holds seeds: a map's or sweep's every region starts.
    for (int by = 0; by < 4; ++by)
        for (int bx = 0; bx < 4; ++bx)
            EXPECT_GT(seededShare(state, bx * 64, by * 64, 64, 64), 0.03) << bx << "," << by;
    // The model's own start on the same grid seeds far less of it (20 spots).
    s.init = gs.defaultInit();
    EXPECT_LT(seededShare(initialState(s), 0, 0, 256, 256), 0.03);
}

TEST(ExplorationStart, GrayScottNoiseStartKeepsAPresetsSeedValues) {
    const ReactionModel& gs = model("gray_scott");
    // McGraw's centre square, with his large noise: seeds of its values, the model's radius.
    const Session mcgraw = loadPreset("gs_generalized_e");
    const InitialCondition fromSquare = noiseStart(mcgraw.init, gs);
    EXPECT_EQ(fromSquare.type, InitialCondition::Type::JitteredGrid);
    EXPECT_EQ(fromSquare.noise.at("v"), mcgraw.init.noise.at("v"));
    EXPECT_EQ(fromSquare.spotRadius, gs.defaultInit().spotRadius);
    // A noise preset has no background to seed into: the model's seeds.
    const InitialCondition fromNoise = noiseStart(loadPreset("gs_uniform").init, gs);
    EXPECT_EQ(fromNoise.type, InitialCondition::Type::JitteredGrid);
    EXPECT_EQ(fromNoise.base.at("u"), 1.0f);
    EXPECT_EQ(fromNoise.inside.at("v"), 0.25f);
}

TEST(ExplorationStart, NoiseModelsKeepTheirNoise) {
    const Session turing = loadPreset("mcgraw_turing");
    const InitialCondition kept = noiseStart(turing.init, turing.reactionModel());
    EXPECT_EQ(kept.type, InitialCondition::Type::Noise);
    EXPECT_EQ(kept.noise, turing.init.noise);
    EXPECT_EQ(kept.base, turing.init.base);
    // Stripe initiators (3 raised cells) become the preset's substrate plus the model's noise.
    const Session initiators = loadPreset("meinhardt_stripe_initiators");
    const ReactionModel& meinhardt = initiators.reactionModel();
    const InitialCondition noise = noiseStart(initiators.init, meinhardt);
    EXPECT_EQ(noise.type, InitialCondition::Type::Noise);
    EXPECT_EQ(noise.base, initiators.init.base);
    EXPECT_EQ(noise.noise.at("substrate"), meinhardt.defaultInit().noise.at("substrate"));
}

TEST(TilePick, ReadsColumnAndRowFromZero) {
    const TilePick pick = parseTilePick("--pick", "2,5", 4, 8);
    EXPECT_EQ(pick.column, 2);
    EXPECT_EQ(pick.row, 5);
    const TilePick corner = parseTilePick("--pick", " 3 , 7 ", 4, 8);
    EXPECT_EQ(corner.column, 3);
    EXPECT_EQ(corner.row, 7);
}

TEST(TilePick, RefusesOutsideTheGridAndOtherText) {
    EXPECT_EQ(messageOf([] { parseTilePick("--pick", "4,0", 4, 8); }),
              "--pick '4,0': column 4 is outside the 4x8 grid (columns 0..3 from the left, rows "
              "0..7 from the bottom)");
    EXPECT_NE(messageOf([] { parseTilePick("--pick", "0,8", 4, 8); }).find("row 8 is outside"),
              std::string::npos);
    EXPECT_NE(messageOf([] { parseTilePick("--pick", "-1,2", 4, 8); }).find("column -1"),
              std::string::npos);
    for (const char* bad : {"2x5", "2", "2,5,1", "a,b", "2.5,1", ""})
        EXPECT_NE(messageOf([bad] { parseTilePick("--pick", bad, 4, 8); }).find("expected COL,ROW"),
                  std::string::npos)
            << bad;
}

TEST(PointPick, ReadsValuesWithinTheAxes) {
    const SweepAxis k{"k", 0.045f, 0.07f}, f{"F", 0.01f, 0.09f};
    const PointPick pick = parsePointPick("--pick", "0.06,0.035", k, f);
    EXPECT_EQ(pick.x, 0.06f);
    EXPECT_EQ(pick.y, 0.035f);
    // The ends, as typed from the axis flags, are on the map.
    const PointPick ends = parsePointPick("--pick", "0.045,0.09", k, f);
    EXPECT_EQ(ends.x, k.min);
    EXPECT_EQ(ends.y, f.max);
    EXPECT_EQ(messageOf([&] { parsePointPick("--pick", "0.08,0.035", k, f); }),
              "--pick '0.08,0.035': k = 0.08 is outside the map's x axis (k 0.045..0.07)");
    EXPECT_NE(messageOf([&] {
                  parsePointPick("--pick", "0.06,0.1", k, f);
              }).find("F = 0.1 is outside the map's y axis"),
              std::string::npos);
    for (const char* bad : {"0.06", "0.06;0.03", "x,0.03", "0.06,", "nan,0.03"})
        EXPECT_NE(messageOf([&] { parsePointPick("--pick", bad, k, f); }).find("expected X,Y"),
                  std::string::npos)
            << bad;
}

TEST(PickTile, IsTheTilesValuesAtFullSizeAndTheTilesScale) {
    SweepSpec spec = grayScottSweep(3, 2, 16);
    spec.base.dt = 0.7f; // a sweep's dt is its corners' smallest stable one
    const Session batched = batchedSession(spec);
    const Session picked = pickTile(batched, {2, 1}, 256);
    EXPECT_FALSE(picked.tiles.active());
    EXPECT_EQ(picked.params.at("k"), sweepValue(spec.x, 2, 3));
    EXPECT_EQ(picked.params.at("F"), sweepValue(spec.y, 1, 2));
    EXPECT_EQ(picked.params.at("k"), 0.07f);
    EXPECT_EQ(picked.params.at("F"), 0.05f);
    EXPECT_EQ(picked.params.at("Du"), spec.base.params.at("Du"));
    EXPECT_EQ(picked.width, 256);
    EXPECT_EQ(picked.height, 256);
    EXPECT_EQ(picked.length, 256.0); // one unit per cell, as the tile
    EXPECT_EQ(picked.cellSize(), 1.0);
    EXPECT_EQ(picked.dt, 0.7f);
    EXPECT_EQ(picked.steps, spec.base.steps);
    EXPECT_EQ(picked.init.type, InitialCondition::Type::JitteredGrid);
    EXPECT_EQ(picked.init.spacing, spec.base.init.spacing);
    const TilePick first{0, 0};
    EXPECT_EQ(pickTile(batched, first, 64).params.at("k"), 0.05f);
    EXPECT_EQ(pickTile(batched, first, 64).params.at("F"), 0.02f);
}

TEST(PickTile, SeedSpotsStayAsDenseAsOnTheTile) {
    SweepSpec spec = grayScottSweep(2, 2, 32);
    spec.base.init = model("gray_scott").defaultInit();
    spec.base.init.spotCount = 3;
    const Session picked = pickTile(batchedSession(spec), {1, 1}, 128);
    EXPECT_EQ(picked.init.type, InitialCondition::Type::SeedSpots);
    EXPECT_EQ(picked.init.spotCount, 3 * 16);
}

TEST(PickPoint, SetsTheMapsValuesUniformly) {
    Session map = loadPreset("turk_cheetah"); // a cascade whose second stage sets s
    map.width = map.height = 64;
    map.length = 0;
    const SweepAxis s{"s", 0.03f, 0.06f}, noise{"beta_noise", 0.0f, 3.0f};
    map.paramMaps["s"] = {ParamMapSpec::Field::LinearX, s.min, s.max};
    map.paramMaps["beta_noise"] = {ParamMapSpec::Field::LinearY, noise.min, noise.max};
    map.paramMaps["Da"] = {ParamMapSpec::Field::Radial, 0.5f, 1.0f};
    ASSERT_FALSE(map.stages.empty());
    const Session picked = pickPoint(map, s, noise, {0.04f, 1.5f}, 128);
    EXPECT_EQ(picked.params.at("s"), 0.04f);
    EXPECT_EQ(picked.params.at("beta_noise"), 1.5f);
    EXPECT_EQ(picked.paramMaps.count("s"), 0u);
    EXPECT_EQ(picked.paramMaps.count("beta_noise"), 0u);
    EXPECT_EQ(picked.paramMaps.count("Da"), 1u); // not swept: kept as the map had it
    for (const Stage& stage : picked.stages)
        EXPECT_EQ(stage.params.count("s"), 0u); // the map's s overrode the stage's
    EXPECT_EQ(picked.width, 128);
    EXPECT_EQ(picked.length, 128.0);
    EXPECT_NO_THROW(validateSession(picked, "test"));
}

// The honest check: a noise-start sweep tile and its picked session at twice the size settle to
// the same pattern: the same wavelength and the same features per area.
TEST(PickTile, RendersTheTilesPatternAtFullSize) {
    SweepSpec spec = grayScottSweep(2, 1, 64);
    spec.x = {"k", 0.0567f, 0.0611f}; // stripes, then spots
    spec.y = {"F", 0.03f, 0.05f};     // one row: F 0.03
    spec.base.steps = 6000;
    spec.base.width = spec.base.height = spec.tile;
    const Session batched = batchedSession(spec);
    for (int column : {0, 1}) {
        const State tile = test::runCpu(tileSession(batched, column, 0));
        const State full = test::runCpu(pickTile(batched, {column, 0}, 128));
        const PatternStats a = measurePattern(tile, 1), b = measurePattern(full, 1);
        ASSERT_NE(classifyPattern(a), PatternClass::Uniform) << column;
        EXPECT_EQ(classifyPattern(a), classifyPattern(b)) << column;
        // 64 cells hold 5 wavelengths: the spectrum's bins are ~15% apart there.
        EXPECT_NEAR(b.dominantWavelength / a.dominantWavelength, 1.0, 0.15) << column;
        // Spots count; a labyrinth is a few connected walls whatever the size.
        if (classifyPattern(a) == PatternClass::Spots)
            EXPECT_NEAR(b.featureCount / (128.0 * 128.0) / (a.featureCount / (64.0 * 64.0)), 1.0,
                        0.2)
                << a.featureCount << " spots on the tile, " << b.featureCount << " at full size";
        std::printf("column %d: wavelength %.2f / %.2f, features %d / %d (x4 area)\n", column,
                    a.dominantWavelength, b.dominantWavelength, a.featureCount, b.featureCount);
    }
}
