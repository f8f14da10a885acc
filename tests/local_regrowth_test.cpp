// Localized re-growth inside a live run (core/sim/local_regrowth.hpp): the
// active set's phases and settle checks, and SessionRun following localized
// surface strokes: tiles outside the set keep their values bit for bit, the
// re-growth ends, and a saved session and a checkpoint replay it exactly.

#include <algorithm>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "atlas_checks.hpp"
#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/local_regrowth.hpp"
#include "core/sim/session_run.hpp"
#include "core/surface/surface_setup.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

State constantState(int width, int height, float value) {
    State s(width, height, 1);
    std::fill(s.plane(0), s.plane(0) + s.cellCount(), value);
    return s;
}

// turk_small_spots on the sample sphere with few small tiles.
Session sphereSession() {
    Session s = loadPreset("turk_small_spots");
    s.length = 60;
    s.surface.mesh = "sample:sphere";
    s.surface.tiles = 120;
    s.surface.tileSize = 4;
    s.steps = 400;
    return s;
}

LiveEdit localizedDab(float value = 3.0f) {
    LiveEdit e;
    e.stroke = StrokeSpec{};
    e.stroke->mode = BrushMode::Add;
    e.stroke->chemical = "b";
    e.stroke->value = value;
    e.stroke->surface = true;
    e.stroke->surfacePoints = {{0.0, 0.0, 1.0}};
    e.stroke->radius = 0.12;
    e.stroke->falloff = 0.5;
    e.stroke->localized = true;
    return e;
}

} // namespace

TEST(LocalRegrowth, GrowsWhereTheChangeReachesTheSetsEdgeAndEndsWhenSettled) {
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(4, 10, 10));
    auto n = std::make_shared<const TileNeighbourhoods>(*atlas);
    LocalRegrowthOptions o;
    o.checkEvery = 20;
    LocalRegrowth r(n, atlas, {55}, o);
    EXPECT_FALSE(r.over());
    EXPECT_EQ(r.tiles().size(), 9u); // A1 = N(A0)
    EXPECT_EQ(r.phase(), 1);
    EXPECT_EQ(r.stepsBeforeChange(), 20);
    // What the next check reads: tile t's cells moved by `by`.
    State state = constantState(atlas->width(), atlas->height(), 0.5f);
    const auto move = [&](int tile, float by) {
        for (int v = 0; v < atlas->tileSize(); ++v)
            for (int u = 0; u < atlas->tileSize(); ++u)
                state.plane(0)[atlas->tileCell(tile, u, v)] += by;
    };
    int reads = 0;
    const auto read = [&] {
        ++reads;
        return state;
    };
    EXPECT_FALSE(r.stepped(15, read)); // no check yet
    EXPECT_EQ(reads, 0);
    EXPECT_EQ(r.stepsBeforeChange(), 5);
    EXPECT_FALSE(r.stepped(5, read)); // the first check takes the reference
    EXPECT_EQ(reads, 1);
    // The change stays in the stroke's own tile (the centre of A1): no growth.
    move(55, 0.1f);
    EXPECT_FALSE(r.stepped(20, read));
    EXPECT_EQ(r.tiles().size(), 9u);
    // It reaches a tile of the set's outer ring: the set grows by a ring.
    move(54, 0.1f);
    EXPECT_TRUE(r.stepped(20, read));
    EXPECT_EQ(r.phase(), 2);
    EXPECT_EQ(r.tiles().size(), 25u);
    EXPECT_FALSE(r.over());
    // Another stroke far away: the set takes its neighbourhood in, same phase.
    r.touch({0});
    EXPECT_EQ(r.tiles().size(), 34u);
    EXPECT_EQ(r.phase(), 2);
    // Nothing moves between two checks: settled, over.
    EXPECT_FALSE(r.stepped(20, read)); // reference again after the touch
    EXPECT_TRUE(r.stepped(20, read));
    EXPECT_TRUE(r.over());
    EXPECT_TRUE(r.settled());
}

TEST(LocalRegrowth, GoesGlobalWhenTheSetPassesTheThreshold) {
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(4, 10, 10));
    auto n = std::make_shared<const TileNeighbourhoods>(*atlas);
    LocalRegrowth r(n, atlas, {55});
    float value = 0;
    const auto read = [&] {
        value += 1.0f; // everything keeps changing: the set grows at every check
        return constantState(atlas->width(), atlas->height(), value);
    };
    int checks = 0;
    while (!r.over() && checks < 100) {
        r.stepped(r.stepsBeforeChange(), read);
        ++checks;
    }
    EXPECT_TRUE(r.over());
    EXPECT_FALSE(r.settled());
    EXPECT_EQ(checks, 3); // reference, A2 (25 tiles), A3 (49 > 40): global
}

TEST(LocalRegrowth, SessionRunStepsOnlyTheActiveTilesAndReplaysExactly) {
    Session s = sphereSession();
    const SurfaceSetup setup = setUpSurface(s);
    const Atlas& atlas = *setup.tiles.atlas;
    SessionRun run(s, cpu(), 0);
    run.advance(200 * run.substeps());
    ASSERT_EQ(run.regrowth(), nullptr);
    run.applyEdit(localizedDab());
    ASSERT_NE(run.regrowth(), nullptr);
    const std::vector<int> active = run.regrowth()->tiles();
    EXPECT_FALSE(active.empty());
    EXPECT_LT(int(active.size()), atlas.tileCount() / 2);
    const State atStroke = run.state();
    const RunCheckpoint mid = run.checkpoint();

    // A few steps: tiles outside the set hold their values bit for bit, some inside change.
    const int few = std::min(run.regrowth()->stepsBeforeChange(), 5);
    run.advance(few);
    const State later = run.state();
    int outsideChanged = 0, insideChanged = 0;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const bool in = std::binary_search(active.begin(), active.end(), t);
        const bool same = test::tileEqual(atStroke, later, atlas, t);
        outsideChanged += !in && !same;
        insideChanged += in && !same;
    }
    EXPECT_EQ(outsideChanged, 0);
    EXPECT_GT(insideChanged, 0);

    // The re-growth ends (settled or past the threshold) within the session.
    while (run.regrowth() && !run.finished())
        run.advance(25);
    EXPECT_EQ(run.regrowth(), nullptr);
    const State end = run.state();

    // A checkpoint taken during the re-growth resumes it identically.
    RunCheckpoint now = run.checkpoint();
    run.restore(mid);
    ASSERT_NE(run.regrowth(), nullptr);
    EXPECT_EQ(run.regrowth()->tiles(), active);
    run.advance(now.stepsDone - run.position().stepsDone);
    EXPECT_EQ(run.position().stepsDone, now.stepsDone);
    EXPECT_EQ(test::maxAbsDifference(run.state(), end), 0.0f);

    // The saved session replays the localized stroke step for step (saved on
    // a session step: completed() records whole session steps).
    const int sub = run.substeps();
    run.advance(10 * sub + (sub - run.position().stepsDone % sub) % sub);
    const nlohmann::json j = sessionToJson(run.completed());
    EXPECT_EQ(j["edits"][0]["stroke"]["localized"], true);
    Session again = sessionFromJson(j, "regrowth.json");
    validateSession(again, "regrowth.json");
    (void)setUpSurface(again);
    const RunResult replay = runSession(again, cpu(), {});
    EXPECT_EQ(test::maxAbsDifference(replay.state, run.state()), 0.0f);

    // Without localized re-growth the same stroke changes tiles far from it.
    SessionRun global(s, cpu(), 0);
    global.advance(200 * global.substeps());
    LiveEdit plain = localizedDab();
    plain.stroke->localized = false;
    global.applyEdit(plain);
    EXPECT_EQ(global.regrowth(), nullptr);
    const State g0 = global.state();
    global.advance(few);
    int farChanged = 0;
    const State g1 = global.state();
    for (int t = 0; t < atlas.tileCount(); ++t)
        farChanged += !std::binary_search(active.begin(), active.end(), t) &&
                      !test::tileEqual(g0, g1, atlas, t);
    EXPECT_GT(farChanged, 0); // the pattern is still growing there
}

TEST(LocalRegrowth, AParameterChangeEndsIt) {
    Session s = sphereSession();
    (void)setUpSurface(s);
    SessionRun run(s, cpu(), 0);
    run.advance(50 * run.substeps());
    run.applyEdit(localizedDab());
    ASSERT_NE(run.regrowth(), nullptr);
    LiveEdit e;
    e.params = {{"s", s.params.at("s")}};
    run.applyEdit(e);
    EXPECT_EQ(run.regrowth(), nullptr);
}

TEST(LocalRegrowth, OnlySurfaceStrokesAreLocalized) {
    Session s = loadPreset("gs_coral");
    s.width = s.height = 32;
    nlohmann::json j = sessionToJson(s);
    j["edits"] = nlohmann::json::parse(
        R"([{"step": 1, "stroke": {"mode": "add", "chemical": "v", "value": 0.5,
             "points": [[0.5, 0.5]], "localized": true}}])");
    try {
        Session bad = sessionFromJson(j, "canvas.json");
        validateSession(bad, "canvas.json");
        FAIL() << "a localized canvas stroke was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("localized"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("surface"), std::string::npos) << e.what();
    }
}

namespace {

// Stretches the ring of the sphere round z = 0.8 along z (a slab across the
// mesh: small near the pole, so the re-growth stays local).
LiveEdit stretchNearThePole(double factor) {
    LiveEdit e;
    e.deform = DeformSpec{};
    e.deform->centre = {0.0, 0.0, 0.8};
    e.deform->direction = {0.0, 0.0, 1.0};
    e.deform->radius = 0.08;
    e.deform->factor = factor;
    return e;
}

} // namespace

TEST(SurfaceDeformEdit, MovesTheSurfaceRegrowsThereAndReplays) {
    Session s = sphereSession();
    s.surface.tiles = 400; // enough that the ring's tiles and their neighbours stay under 40%
    const SurfaceSetup setup = setUpSurface(s);
    ASSERT_TRUE(s.surfaceGeometry);
    SessionRun run(s, cpu(), 0);
    run.advance(100 * run.substeps());
    const RunCheckpoint before = run.checkpoint();
    const auto positionsBefore = run.segmentSession().atlasPositions;
    const auto weightsBefore = run.segmentSession().atlasWeights;
    run.applyEdit(stretchNearThePole(1.6));
    // The texels moved (the slab stretched, the cap beyond it shifted up by
    // 0.6 x 0.08) and the metric changed; the re-growth starts from the
    // deformed tiles.
    const auto& after = *run.segmentSession().atlasPositions;
    float highest = -10, highestBefore = -10;
    for (std::size_t i = 0; i < after.size(); ++i) {
        highest = std::max(highest, after[i][2]);
        highestBefore = std::max(highestBefore, (*positionsBefore)[i][2]);
    }
    EXPECT_NEAR(highest - highestBefore, 0.6f * 0.08f, 1e-3f);
    EXPECT_NE(run.segmentSession().atlasWeights, weightsBefore);
    ASSERT_NE(run.regrowth(), nullptr) << setup.tiles.atlas->tileCount() << " tiles";
    EXPECT_FALSE(run.regrowth()->tiles().empty());
    run.advance(40 * run.substeps());
    const State end = run.state();

    // Saved and replayed: the deformation is recorded and re-done.
    const nlohmann::json j = sessionToJson(run.completed());
    ASSERT_TRUE(j["edits"][0].contains("deform"));
    EXPECT_EQ(j["edits"][0]["deform"]["factor"], 1.6);
    Session again = sessionFromJson(j, "deform.json");
    validateSession(again, "deform.json");
    (void)setUpSurface(again);
    EXPECT_EQ(test::maxAbsDifference(runSession(again, cpu(), {}).state, end), 0.0f);

    // Back to before the deformation: the surface and the state as they were;
    // forward again to after it: the deformed surface comes back.
    const RunCheckpoint deformed = run.checkpoint();
    run.restore(before);
    EXPECT_EQ(run.segmentSession().atlasWeights, weightsBefore);
    EXPECT_EQ(run.segmentSession().atlasPositions, positionsBefore);
    EXPECT_EQ(test::maxAbsDifference(run.state(), before.state), 0.0f);
    run.restore(deformed);
    EXPECT_NE(run.segmentSession().atlasWeights, weightsBefore);
    run.advance(5 * run.substeps());
}

TEST(SurfaceDeformEdit, RefusesWhatItCannotDo) {
    Session s = sphereSession();
    (void)setUpSurface(s);
    SessionRun run(s, cpu(), 0);
    run.advance(10 * run.substeps());
    const State before = run.state();
    // Squeezed to half: the texels' floors (surface_weights.cpp) keep the
    // weights within the run's substeps (deformSurface refuses a deformation
    // that would need more), and the run stays sane.
    {
        SessionRun squeezed(s, cpu(), 25);
        squeezed.advance(10 * squeezed.substeps());
        squeezed.applyEdit(stretchNearThePole(0.5));
        EXPECT_NO_THROW(squeezed.advance(30 * squeezed.substeps())); // blow-up checks every 25
    }
    // A slab off the mesh.
    LiveEdit away = stretchNearThePole(1.5);
    away.deform->centre = {50, 50, 50};
    EXPECT_THROW(run.applyEdit(away), InputError);
    EXPECT_EQ(test::maxAbsDifference(run.state(), before), 0.0f);
    EXPECT_TRUE(run.edits().empty());

    // In JSON: a canvas session, a zero direction and a factor out of range are refused by field.
    Session flat = loadPreset("gs_coral");
    flat.width = flat.height = 32;
    nlohmann::json j = sessionToJson(flat);
    j["edits"] = nlohmann::json::parse(
        R"([{"step": 1, "deform": {"centre": [0, 0, 0], "direction": [1, 0, 0], "radius": 0.2}}])");
    const auto refusal = [](const nlohmann::json& json) -> std::string {
        try {
            Session bad = sessionFromJson(json, "deform.json");
            validateSession(bad, "deform.json");
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_NE(refusal(j).find("without a mesh"), std::string::npos) << refusal(j);
    Session mesh = sphereSession();
    nlohmann::json m = sessionToJson(mesh);
    m["edits"] = nlohmann::json::parse(
        R"([{"step": 1, "deform": {"centre": [0, 0, 0], "direction": [0, 0, 0], "radius": 0.2}}])");
    EXPECT_NE(refusal(m).find("direction"), std::string::npos) << refusal(m);
    m["edits"][0]["deform"]["direction"] = {1, 0, 0};
    m["edits"][0]["deform"]["factor"] = 9;
    EXPECT_NE(refusal(m).find("factor"), std::string::npos) << refusal(m);
    m["edits"][0]["deform"]["factor"] = 1.5;
    m["edits"][0]["deform"]["reach"] = -0.1;
    EXPECT_NE(refusal(m).find("reach"), std::string::npos) << refusal(m);
}

TEST(SurfaceDeformEdit, ALocalStretchMovesOnlyTheSurfaceNearItAndReplays) {
    Session s = sphereSession();
    s.surface.tiles = 400;
    (void)setUpSurface(s);
    SessionRun run(s, cpu(), 0);
    run.advance(20 * run.substeps());
    const auto positionsBefore = run.segmentSession().atlasPositions;
    // The slab round z = 0.8 again, but only within 0.15 of the z axis
    // (fading out at 0.3): the cap round the pole, not the whole ring.
    LiveEdit local = stretchNearThePole(1.6);
    local.deform->centre = {0.0, 0.6, 0.8};
    local.deform->reach = 0.15;
    run.applyEdit(local);
    const auto& after = *run.segmentSession().atlasPositions;
    int moved = 0, far = 0;
    for (std::size_t i = 0; i < after.size(); ++i) {
        const auto& p = (*positionsBefore)[i];
        const double rho = std::hypot(p[0], p[1] - 0.6);
        const bool same = p == after[i];
        moved += !same;
        if (rho >= 0.3) {
            ++far;
            EXPECT_TRUE(same) << "texel " << i << " moved at " << rho << " from the axis";
        }
    }
    EXPECT_GT(moved, 0);
    EXPECT_GT(far, moved); // most of the sphere stays where it was
    run.advance(10 * run.substeps());
    // Saved with its reach and replayed to the same state.
    const nlohmann::json j = sessionToJson(run.completed());
    ASSERT_TRUE(j["edits"][0]["deform"].contains("reach"));
    EXPECT_EQ(j["edits"][0]["deform"]["reach"], 0.15);
    Session again = sessionFromJson(j, "local.json");
    validateSession(again, "local.json");
    (void)setUpSurface(again);
    EXPECT_EQ(test::maxAbsDifference(runSession(again, cpu(), {}).state, run.state()), 0.0f);
    // A slab across the model writes no reach (sessions from before it read the same).
    EXPECT_FALSE(sessionToJson([&] {
                     Session across = s;
                     across.edits = {stretchNearThePole(1.6)};
                     across.edits[0].step = 1;
                     return across;
                 }())["edits"][0]["deform"]
                     .contains("reach"));
}
