// Live edits (core/session/live_edit.hpp) on the CPU backend: a session's
// "edits" read and write back, bad ones are refused by field; a run with
// edits recorded by applyEdit, saved through completed() and replayed from
// the JSON, ends in the same state bit for bit; strokes change only the
// cells they cover; checkpoints restore a run exactly.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "core/sim/stroke_brush.hpp"
#include "core/surface/surface_setup.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

Session smallCoral(int steps = 120) {
    Session s = loadPreset("gs_coral");
    s.width = s.height = 48;
    s.coarseToFine = false;
    s.steps = steps;
    return s;
}

StrokeSpec dab(double x, double y, const std::string& chemical = "v", float value = 0.5f) {
    StrokeSpec s;
    s.mode = BrushMode::Add;
    s.chemical = chemical;
    s.value = value;
    s.points = {{x, y}};
    s.radius = 0.1;
    s.falloff = 0.5;
    return s;
}

Session fromJson(const nlohmann::json& j) {
    Session s = sessionFromJson(j, "edits.json");
    validateSession(s, "edits.json");
    return s;
}

std::string refusal(const nlohmann::json& j) {
    try {
        fromJson(j);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(LiveEdit, JsonRoundTrip) {
    Session s = smallCoral();
    LiveEdit a;
    a.step = 10;
    a.params["F"] = 0.05f;
    a.dt = 0.5f;
    LiveEdit b;
    b.step = 40;
    b.stroke = dab(0.25, 0.75);
    b.stroke->points.push_back({0.5, 0.5});
    LiveEdit c;
    c.step = 40;
    c.stroke = StrokeSpec{};
    c.stroke->mode = BrushMode::Paint;
    c.stroke->param = "k";
    c.stroke->value = 0.061f;
    c.stroke->points = {{0.1, 0.1}};
    s.edits = {a, b, c};
    const nlohmann::json j = sessionToJson(s);
    const Session back = fromJson(j);
    ASSERT_EQ(back.edits.size(), 3u);
    EXPECT_TRUE(back.edits[0] == a);
    EXPECT_TRUE(back.edits[1] == b);
    EXPECT_TRUE(back.edits[2] == c);
    EXPECT_EQ(sessionToJson(back), j);
}

TEST(LiveEdit, BadEditsAreRefusedByField) {
    nlohmann::json base = sessionToJson(smallCoral());
    auto with = [&](nlohmann::json edits) {
        nlohmann::json j = base;
        j["edits"] = std::move(edits);
        return refusal(j);
    };
    EXPECT_NE(with(nlohmann::json::object()).find("field 'edits' must be an array"),
              std::string::npos);
    EXPECT_NE(with({{{"params", {{"F", 0.04}}}}}).find("edits[0].step' is missing"),
              std::string::npos);
    EXPECT_NE(with({{{"step", 5}}, {{"step", 2}}}).find("edits are in step order"),
              std::string::npos);
    EXPECT_NE(with({{{"step", 500}}}).find("after the session's last step (120)"),
              std::string::npos);
    const std::string unknown = with({{{"step", 1}, {"params", {{"G", 0.04}}}}});
    EXPECT_NE(unknown.find("edits[0].params.G' is not a parameter of the model (accepted: "),
              std::string::npos)
        << unknown;
    EXPECT_NE(with({{{"step", 1}, {"params", {{"F", 7.0}}}}}).find("edits[0].params.F"),
              std::string::npos);
    const nlohmann::json stroke = {
        {"mode", "add"}, {"chemical", "v"}, {"value", 0.5}, {"points", {{0.5, 0.5}}}};
    auto strokeWith = [&](const std::string& key, nlohmann::json value) {
        nlohmann::json st = stroke;
        if (value.is_null())
            st.erase(key);
        else
            st[key] = std::move(value);
        return with({{{"step", 1}, {"stroke", st}}});
    };
    EXPECT_EQ(strokeWith("radius", 0.05), "");
    EXPECT_NE(strokeWith("mode", "smudge").find("accepted: add, remove"), std::string::npos);
    EXPECT_NE(strokeWith("chemical", "w").find("not a chemical of the model (accepted: u, v)"),
              std::string::npos);
    EXPECT_NE(strokeWith("chemical", nullptr).find("writes a chemical"), std::string::npos);
    EXPECT_NE(strokeWith("radius", 0.0).find("stroke.radius' is 0"), std::string::npos);
    EXPECT_NE(strokeWith("radius", -1.0).find("accepted range"), std::string::npos);
    EXPECT_NE(strokeWith("points", nlohmann::json::array()).find("non-empty array"),
              std::string::npos);
    EXPECT_NE(strokeWith("points", {{0.5}}).find("got [0.5]"), std::string::npos);
    EXPECT_NE(strokeWith("points", {{5.0, 0.5}}).find("got [5.0,0.5]"), std::string::npos);
    EXPECT_NE(strokeWith("value", "lots").find("must be a number"), std::string::npos);
    EXPECT_NE(strokeWith("param", "F").find("only used by mode 'paint'"), std::string::npos);
}

TEST(LiveEdit, StrokeRegionCoversTheSweptDisc) {
    const Session s = smallCoral();
    StrokeSpec line = dab(0.25, 0.5);
    line.points.push_back({0.75, 0.5});
    line.radius = 2.0 / 48.0; // two cells
    line.falloff = 0;
    const BrushRegion region = strokeRegion(line, s.domain());
    // The segment runs from cell (11.5, 23.5) to (35.5, 23.5): rows 22..25 lie within 2 of it,
    // rows 23 and 24 (0.5 away) over columns 10..37, rows 22 and 25 (1.5 away) over 11..36.
    for (const BrushRegion::Cell& c : region.cells()) {
        const int x = int(c.index % 48), y = int(c.index / 48);
        EXPECT_GE(x, 10);
        EXPECT_LE(x, 37);
        EXPECT_GE(y, 22);
        EXPECT_LE(y, 25);
        EXPECT_EQ(c.weight, 1.0f);
    }
    EXPECT_EQ(region.cells().size(), std::size_t(2 * 28 + 2 * 26));
}

TEST(LiveEdit, StrokeChangesOnlyItsCells) {
    const Session s = smallCoral(40);
    SessionRun run(s, cpu(), 0);
    run.advance(20);
    const State before = run.state();
    LiveEdit e;
    e.stroke = dab(0.3, 0.6);
    run.applyEdit(e);
    const State after = run.state();
    const BrushRegion region = strokeRegion(*e.stroke, s.domain());
    std::vector<char> inRegion(std::size_t(48 * 48), 0);
    for (const BrushRegion::Cell& c : region.cells())
        inRegion[c.index] = 1;
    int changed = 0;
    for (int i = 0; i < 48 * 48; ++i) {
        const bool differs = before.at(1, i % 48, i / 48) != after.at(1, i % 48, i / 48);
        EXPECT_EQ(before.at(0, i % 48, i / 48), after.at(0, i % 48, i / 48));
        if (!inRegion[std::size_t(i)])
            EXPECT_FALSE(differs) << "cell " << i;
        changed += differs;
    }
    EXPECT_GT(changed, int(region.cells().size()) / 2);
    EXPECT_EQ(run.edits().size(), 1u);
    EXPECT_EQ(run.edits()[0].step, 20);
}

TEST(LiveEdit, RecordedRunReplaysBitForBit) {
    Session s = smallCoral(100000); // open-ended, as the designer runs it
    SessionRun run(s, cpu(), 0);
    run.advance(30);
    LiveEdit a;
    a.params["F"] = 0.045f;
    run.applyEdit(a);
    run.advance(25);
    LiveEdit b;
    b.stroke = dab(0.5, 0.5);
    b.stroke->points.push_back({0.7, 0.4});
    run.applyEdit(b);
    LiveEdit c;
    c.dt = 0.8f;
    c.stroke = StrokeSpec{};
    c.stroke->mode = BrushMode::Paint;
    c.stroke->param = "k";
    c.stroke->value = 0.058f;
    c.stroke->points = {{0.2, 0.2}};
    c.stroke->radius = 0.2;
    run.advance(17);
    run.applyEdit(c);
    run.advance(40);
    LiveEdit d;
    d.stroke = dab(0.9, 0.1, "u", 0.3f);
    d.stroke->mode = BrushMode::Remove;
    run.applyEdit(d); // at the very end: applies before the replay's result
    const State live = run.state();

    Session saved = run.completed();
    EXPECT_EQ(saved.steps, 112);
    EXPECT_EQ(saved.params.at("F"), s.params.at("F")); // the edit, not the final value
    ASSERT_EQ(saved.edits.size(), 4u);
    EXPECT_EQ(saved.edits[3].step, 112);
    const Session replayed = fromJson(sessionToJson(saved));
    const RunResult again = runSession(replayed, cpu(), {});
    EXPECT_EQ(test::maxAbsDifference(again.state, live), 0.0f);
    // And the replay records the same edits.
    EXPECT_EQ(sessionToJson(again.completed), sessionToJson(saved));

    // Without the edits the run differs: the test can tell.
    Session plain = saved;
    plain.edits.clear();
    EXPECT_GT(test::maxAbsDifference(runSession(plain, cpu(), {}).state, live), 0.01f);
}

TEST(LiveEdit, CheckpointRestoresTheRunExactly) {
    Session s = smallCoral(100000);
    SessionRun run(s, cpu(), 0);
    run.advance(20);
    LiveEdit paint;
    paint.stroke = StrokeSpec{};
    paint.stroke->mode = BrushMode::Paint;
    paint.stroke->param = "F";
    paint.stroke->value = 0.03f;
    paint.stroke->points = {{0.5, 0.5}};
    paint.stroke->radius = 0.25;
    run.applyEdit(paint);
    LiveEdit hold;
    hold.stroke = StrokeSpec{};
    hold.stroke->mode = BrushMode::Hold;
    hold.stroke->points = {{0.2, 0.8}};
    run.applyEdit(hold);
    run.advance(10);
    const RunCheckpoint mark = run.checkpoint();
    const State atMark = run.state();

    // Continue the original for 30 steps: the reference.
    SessionRun reference(s, cpu(), 0);
    reference.advance(20);
    reference.applyEdit(paint);
    reference.applyEdit(hold);
    reference.advance(40);

    // The run goes on differently, then goes back and repeats the reference's path.
    LiveEdit other;
    other.params["k"] = 0.05f;
    other.stroke = dab(0.5, 0.5);
    run.applyEdit(other);
    run.advance(15);
    run.restore(mark);
    EXPECT_EQ(test::maxAbsDifference(run.state(), atMark), 0.0f);
    EXPECT_EQ(run.sessionStepsDone(), 30);
    EXPECT_EQ(run.edits().size(), 2u);
    run.advance(30);
    EXPECT_EQ(test::maxAbsDifference(run.state(), reference.state()), 0.0f);
}

TEST(LiveEdit, CascadeEditsReplayAcrossStages) {
    Session s = loadPreset("turk_giraffe");
    s.width = s.height = 32;
    s.length = 0;
    s.coarseToFine = false;
    s.stages[0].steps = 60;
    s.stages[1].steps = 40;
    s.steps = 100;
    SessionRun run(s, cpu(), 0);
    run.advance(50);
    LiveEdit a;
    a.stroke = StrokeSpec{};
    a.stroke->mode = BrushMode::Randomise;
    a.stroke->chemical = run.segmentSession().reactionModel().chemicalNames().substr(0, 1);
    a.stroke->value = 0.5f;
    a.stroke->seed = 7;
    a.stroke->points = {{0.4, 0.4}};
    run.applyEdit(a);
    run.advance(30); // into the second stage
    const State live = run.state();
    const Session saved = run.completed();
    const RunResult again = runSession(fromJson(sessionToJson(saved)), cpu(), {});
    EXPECT_EQ(test::maxAbsDifference(again.state, live), 0.0f);
}

TEST(LiveEdit, AStrokeDoesNotBuildUpOnItself) {
    // A drag back and forth over the same place, recorded piece by piece,
    // adds the amount once (an opacity brush); a second stroke adds it again.
    Session s = smallCoral(100000);
    s.init = InitialCondition{}; // a flat start: only the brush changes v
    SessionRun run(s, cpu(), 0);
    const float v0 = run.state().at(1, 24, 24);
    StrokeSpec piece = dab(0.5, 0.5, "v", 0.1f);
    piece.falloff = 0;
    const std::vector<std::array<double, 2>> path = {
        {0.5, 0.5}, {0.6, 0.5}, {0.4, 0.5}, {0.6, 0.5}, {0.5, 0.5}};
    for (std::size_t i = 0; i < path.size(); ++i) {
        LiveEdit e;
        e.stroke = piece;
        e.stroke->points = {path[i > 0 ? i - 1 : 0], path[i]};
        e.stroke->continues = i > 0;
        run.applyEdit(e);
    }
    const State once = run.state();
    EXPECT_NEAR(once.at(1, 24, 23) - v0, 0.1f, 1e-6f);
    // Replayed from the JSON: the same.
    const Session saved = fromJson(sessionToJson(run.completed()));
    SessionRun replay(saved, cpu(), 0);
    EXPECT_EQ(test::maxAbsDifference(replay.state(), once), 0.0f);
    // A new stroke over it builds up.
    LiveEdit again;
    again.stroke = piece;
    run.applyEdit(again);
    EXPECT_NEAR(run.state().at(1, 24, 23) - v0, 0.2f, 1e-6f);
}

TEST(LiveEdit, SurfaceStrokesLandOnTheMeshAndReplay) {
    // A session on the sample sphere (radius 1) with few small tiles.
    Session s = loadPreset("turk_small_spots");
    s.length = 60;
    s.surface.mesh = "sample:sphere";
    s.surface.tiles = 120;
    s.surface.tileSize = 4;
    s.steps = 30;
    const SurfaceSetup setup = setUpSurface(s);
    ASSERT_TRUE(s.atlasPositions);
    const Session& run0 = s;
    SessionRun run(run0, cpu(), 0);
    run.advance(10 * run.substeps());
    const State before = run.state();
    LiveEdit e;
    e.stroke = StrokeSpec{};
    e.stroke->mode = BrushMode::Add;
    e.stroke->chemical = "b";
    e.stroke->value = 2.0f;
    e.stroke->surface = true;
    e.stroke->surfacePoints = {{0.0, 0.0, 1.0}, {0.0, 0.6, 0.8}}; // an arc's chord near +z
    e.stroke->radius = 0.15;
    e.stroke->falloff = 0;
    run.applyEdit(e);
    const State after = run.state();
    // Exactly the texels within 0.15 of the chord changed (b += 2), across tile seams.
    const int b = s.reactionModel().chemicalIndex("b");
    const Atlas& atlas = *setup.tiles.atlas;
    int changed = 0, tilesTouched = 0;
    std::vector<char> touched(std::size_t(atlas.tileCount()), 0);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        const int x = int(i % std::uint32_t(atlas.width())),
                  y = int(i / std::uint32_t(atlas.width()));
        const float d = after.at(b, x, y) - before.at(b, x, y);
        if (!atlas.used(i)) {
            EXPECT_EQ(d, 0.0f);
            continue;
        }
        const Eigen::Vector3f p = setup.tiles.texelPositions[i];
        // Distance to the chord from (0,0,1) to (0,0.6,0.8).
        const Eigen::Vector3f a(0, 0, 1), ab = Eigen::Vector3f(0, 0.6f, 0.8f) - a;
        const float t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0f, 1.0f);
        const float dist = (p - (a + t * ab)).norm();
        if (dist < 0.149f) {
            EXPECT_NEAR(d, 2.0f, 1e-5f) << "texel " << i << " at " << dist;
            ++changed;
            if (!touched[std::size_t(atlas.tileOf(i))]++)
                ++tilesTouched;
        } else if (dist > 0.151f) {
            EXPECT_EQ(d, 0.0f) << "texel " << i << " at " << dist;
        }
    }
    EXPECT_GT(changed, 20);
    EXPECT_GT(tilesTouched, 3); // the stroke crosses tile seams
    run.advance(5 * run.substeps());
    // Saved and replayed (the JSON, then the mesh set up again): the same state.
    Session saved = run.completed();
    const nlohmann::json j = sessionToJson(saved);
    EXPECT_EQ(j["edits"][0]["stroke"]["space"], "surface");
    Session again = sessionFromJson(j, "surface-edits.json");
    validateSession(again, "surface-edits.json");
    (void)setUpSurface(again);
    const RunResult replay = runSession(again, cpu(), {});
    EXPECT_EQ(test::maxAbsDifference(replay.state, run.state()), 0.0f);
}

// A stroke given by fractions of the model's bounding box lands on the mesh's
// nearest point on any model, with its radius a fraction of the diagonal; the
// session keeps the fractions.
TEST(LiveEdit, ModelSpaceStrokesFitAnyModel) {
    const nlohmann::json stroke = {{"step", 0},
                                   {"stroke",
                                    {{"mode", "add"},
                                     {"chemical", "b"},
                                     {"value", 1.0},
                                     {"space", "model"},
                                     {"points", {{0.5, 1.0, 0.5}}},
                                     {"radius", 0.05}}}};
    for (const char* mesh : {"sample:sphere", "sample:torus"}) {
        Session s = loadPreset("turk_small_spots");
        s.length = 60;
        s.surface.mesh = mesh;
        s.surface.tiles = 300;
        s.surface.tileSize = 4;
        nlohmann::json j = sessionToJson(s);
        j["edits"] = nlohmann::json::array({stroke});
        Session placed = fromJson(j);
        ASSERT_TRUE(placed.edits[0].stroke && placed.edits[0].stroke->modelBox);
        const SurfaceSetup setup = setUpSurface(placed);
        const Bounds box = boundsOf(setup.mesh.mesh.positions);
        const StrokeSpec& onMesh = *placed.edits[0].stroke;
        ASSERT_EQ(onMesh.surfacePoints.size(), 1u);
        const Eigen::Vector3f p(float(onMesh.surfacePoints[0][0]),
                                float(onMesh.surfacePoints[0][1]),
                                float(onMesh.surfacePoints[0][2]));
        // The middle of the box's top face (y = max) projected: the surface's top.
        EXPECT_NEAR(p.y(), box.max.y(), 0.02f * box.diagonal()) << mesh;
        EXPECT_NEAR(onMesh.radius, 0.05 * box.diagonal(), 1e-6) << mesh;
        const nlohmann::json saved = sessionToJson(placed);
        EXPECT_EQ(saved["edits"][0]["stroke"]["space"], "model");
        EXPECT_EQ(saved["edits"][0]["stroke"]["points"][0][1], 1.0);
        EXPECT_EQ(saved["edits"][0]["stroke"]["radius"], 0.05);
    }
}

TEST(LiveEdit, ModelSpaceStrokesOutsideTheBoxAreRefused) {
    Session s = loadPreset("turk_small_spots");
    s.surface.mesh = "sample:sphere";
    nlohmann::json j = sessionToJson(s);
    const auto refused = [&](const nlohmann::json& points, double radius) {
        j["edits"] = {{{"step", 0},
                       {"stroke",
                        {{"mode", "add"},
                         {"chemical", "b"},
                         {"space", "model"},
                         {"points", points},
                         {"radius", radius}}}}};
        try {
            fromJson(j);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(refused({{0.5, 1.5, 0.5}}, 0.1).find("fractions of the model's bounding box"),
              std::string::npos);
    EXPECT_NE(refused({{0.5, 0.5}}, 0.1).find("[x, y, z] fractions"), std::string::npos);
    EXPECT_NE(refused({{0.5, 0.5, 0.5}}, 0.0).find("radius"), std::string::npos);
    EXPECT_EQ(refused({{0.5, 0.5, 0.5}}, 0.1), "accepted");
}

TEST(LiveEdit, StrokesMustMatchTheSessionsSpace) {
    Session flat = smallCoral();
    LiveEdit e;
    e.step = 1;
    e.stroke = dab(0.5, 0.5);
    e.stroke->surface = true;
    e.stroke->points.clear();
    e.stroke->surfacePoints = {{0, 0, 1}};
    flat.edits = {e};
    EXPECT_NE(
        refusal(sessionToJson(flat)).find("a stroke on a surface in a session without a mesh"),
        std::string::npos);
    Session onMesh = smallCoral();
    onMesh.surface.mesh = "sample:sphere";
    e.stroke = dab(0.5, 0.5);
    onMesh.edits = {e};
    EXPECT_NE(refusal(sessionToJson(onMesh)).find("a stroke on the canvas in a session on a mesh"),
              std::string::npos);
}
