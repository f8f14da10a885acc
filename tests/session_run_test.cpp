// SessionRun on the CPU backend: advancing in uneven pieces is the same run as
// runSession, positions at stage and level boundaries, stop and resume, live
// parameter and dt changes, and a rebuild that keeps the state.

#include <atomic>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/param_map.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

// Turk's giraffe: Turing spots, then a stage that switches to Meinhardt's
// stripes with a freeze rule and a reset.
Session smallGiraffe() {
    Session s = loadPreset("turk_giraffe");
    s.width = s.height = 32;
    s.length = 0; // one unit per cell
    s.stages[0].steps = 260;
    s.stages[1].steps = 90;
    s.steps = 350;
    return s;
}

Session smallSchedule() {
    Session s = loadPreset("gs_coral");
    s.length = 0; // one unit per cell at the finest level
    applySchedule(s, {{16, 16, 120}, {24, 24, 70}, {32, 32, 60}});
    return s;
}

// Advances in the repeating pieces until the run ends.
RunResult advanceInPieces(const Session& s, const std::vector<int>& pieces, int checkEvery) {
    SessionRun run(s, cpu(), checkEvery);
    for (std::size_t i = 0; !run.finished(); ++i)
        run.advance(pieces[i % pieces.size()]);
    return run.result();
}

void expectSameRun(const RunResult& a, const RunResult& b) {
    ASSERT_EQ(a.state.width(), b.state.width());
    ASSERT_EQ(a.state.channels(), b.state.channels());
    EXPECT_EQ(test::maxAbsDifference(a.state, b.state), 0.0f);
    EXPECT_EQ(a.stepsDone, b.stepsDone);
    EXPECT_EQ(sessionToJson(a.completed), sessionToJson(b.completed));
}

} // namespace

TEST(SessionRun, UnevenPiecesAcrossACascadeWithAModelChangeAreOneRunSession) {
    const Session s = smallGiraffe();
    const RunResult whole = runSession(s, cpu(), {});
    // The stripes model's chemicals.
    ASSERT_EQ(whole.state.channels(), int(s.outputModel().chemicals().size()));
    ASSERT_NE(s.outputModel().name(), s.reactionModel().name());
    expectSameRun(advanceInPieces(s, {7, 1, 50, 13, 200}, 250), whole);
    expectSameRun(advanceInPieces(s, {3, 97}, 40), whole);
    expectSameRun(advanceInPieces(s, {1000}, 0), whole);
}

TEST(SessionRun, UnevenPiecesAcrossAScheduleAreOneRunSession) {
    const Session s = smallSchedule();
    const RunResult whole = runSession(s, cpu(), {});
    EXPECT_EQ(whole.state.width(), 32);
    expectSameRun(advanceInPieces(s, {7, 1, 50, 13}, 250), whole);
    expectSameRun(advanceInPieces(s, {119, 2}, 30), whole);
}

TEST(SessionRun, PositionAtSegmentBoundaries) {
    const Session s = smallGiraffe();
    SessionRun run(s, cpu());
    RunPosition p = run.position();
    EXPECT_TRUE(p.stages);
    EXPECT_EQ(p.segments, 2);
    EXPECT_EQ(p.segment, 0);
    EXPECT_EQ(p.segmentStep, 0);
    EXPECT_EQ(p.segmentSteps, 260);
    EXPECT_EQ(p.totalSteps, 350);
    EXPECT_EQ(run.advance(259), 259);
    p = run.position();
    EXPECT_EQ(p.segment, 0);
    EXPECT_EQ(p.segmentStep, 259);
    EXPECT_EQ(run.segmentRemaining(), 1);
    // The last step of stage 1: the run stands at stage 2, step 0, with the
    // new model's simulator.
    EXPECT_EQ(run.advance(1), 1);
    p = run.position();
    EXPECT_EQ(p.segment, 1);
    EXPECT_EQ(p.segmentStep, 0);
    EXPECT_EQ(p.segmentSteps, 90);
    EXPECT_EQ(p.stepsDone, 260);
    EXPECT_EQ(run.segmentSession().model, "meinhardt_stripes");
    EXPECT_EQ(run.state().channels(), int(s.outputModel().chemicals().size()));
    // Past the end: only what is left runs.
    EXPECT_EQ(run.advance(1000), 90);
    p = run.position();
    EXPECT_TRUE(p.finished);
    EXPECT_EQ(p.stepsDone, 350);
    EXPECT_EQ(run.advance(10), 0);

    SessionRun levels(smallSchedule(), cpu());
    EXPECT_FALSE(levels.position().stages);
    EXPECT_EQ(levels.advance(130), 130);
    p = levels.position();
    EXPECT_EQ(p.segment, 1);
    EXPECT_EQ(p.segmentStep, 10);
    EXPECT_EQ(levels.state().width(), 24);
}

TEST(SessionRun, AStageOfNoStepsIsPassedThroughOnEntry) {
    Session s = smallGiraffe();
    s.stages.insert(s.stages.begin() + 1, Stage{});
    s.stages[1].steps = 0;
    SessionRun run(s, cpu());
    run.advance(260);
    EXPECT_EQ(run.position().segment, 2);
    EXPECT_EQ(run.position().segmentStep, 0);
}

TEST(SessionRun, StoppedAndResumedIsTheSameRun) {
    const Session s = smallGiraffe();
    const RunResult whole = runSession(s, cpu(), {});
    SessionRun run(s, cpu());
    run.advance(100);
    // Stopped: reading the state and the completed session changes nothing.
    const Session partial = run.completed();
    EXPECT_EQ(partial.steps, 100);
    ASSERT_EQ(partial.stages.size(), 1u);
    EXPECT_EQ(partial.stages[0].steps, 100);
    const State middle = run.state();
    // The completed session reproduces the stopped state.
    EXPECT_EQ(test::maxAbsDifference(runSession(partial, cpu(), {}).state, middle), 0.0f);
    while (!run.finished())
        run.advance(33);
    expectSameRun(run.result(), whole);
}

TEST(SessionRun, RunSessionCancelledInTheSecondLevelReproducesItsState) {
    const Session s = smallSchedule();
    std::atomic<bool> cancel{false};
    RunOptions options;
    options.chunk = 20;
    options.cancel = &cancel;
    options.progress = [&](int done, int) { cancel.store(done >= 140); };
    const RunResult r = runSession(s, cpu(), options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(r.stepsDone, 140);
    EXPECT_EQ(r.state.width(), 32); // the coarse state brought to the final size
    ASSERT_EQ(r.completed.schedule.size(), 3u);
    EXPECT_EQ(r.completed.schedule[1].steps, 20);
    EXPECT_EQ(test::maxAbsDifference(runSession(r.completed, cpu(), {}).state, r.state), 0.0f);
}

TEST(SessionRun, EndSegmentMovesToTheNextAndRecordsTheStepsRun) {
    const Session s = smallSchedule();
    SessionRun run(s, cpu());
    run.advance(30);
    run.endSegment();
    EXPECT_EQ(run.position().segment, 1);
    EXPECT_EQ(run.state().width(), 24);
    run.advance(10000);
    const Session done = run.completed();
    EXPECT_EQ(done.schedule[0].steps, 30);
    EXPECT_EQ(done.steps, 30 + 70 + 60);
    EXPECT_EQ(test::maxAbsDifference(runSession(done, cpu(), {}).state, run.result().state), 0.0f);
}

TEST(SessionRun, BlowUpNamesTheStageAndTheStepRange) {
    Session s = test::smallSession("gs_coral", 32, 440);
    s.stages.resize(2);
    s.stages[0].steps = 40;
    s.stages[1].steps = 400;
    s.stages[1].dt = 5.0f; // 5 * 8 * 0.2097 > 2: diffusion alone is unstable
    SessionRun run(s, cpu(), 25);
    try {
        while (!run.finished())
            run.advance(1000);
        FAIL() << "expected a blow-up";
    } catch (const BlowUpError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("of stage 2"), std::string::npos) << message;
        // Steps count within the stage, in checks 25 steps apart.
        EXPECT_EQ(e.step() % 25, 0);
        const std::string range = "between step " + std::to_string(e.step() - 24) + " and step " +
                                  std::to_string(e.step()) + " ";
        EXPECT_NE(message.find(range), std::string::npos) << message;
        EXPECT_EQ(run.position().segment, 1);
    }
}

namespace {

// The message of the blow-up `s` runs into ("" and a failure when it does not).
std::string blowUpMessage(const Session& s) {
    SessionRun run(s, cpu(), 25);
    try {
        while (!run.finished())
            run.advance(1000);
    } catch (const BlowUpError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a blow-up";
    return "";
}

} // namespace

TEST(SessionRun, ABlowUpFromPiledUpStrokesBlamesTheStrokesNotTheTimeStep) {
    // Twelve strokes adding v on one spot at a stable dt: v leaves Gray-Scott's
    // sane range because of the strokes, and a smaller dt would not help.
    Session s = test::smallSession("gs_coral", 32, 100);
    for (int i = 0; i < 12; ++i) {
        LiveEdit e;
        e.step = 10 + i;
        StrokeSpec stroke;
        stroke.mode = BrushMode::Add;
        stroke.chemical = "v";
        stroke.value = 0.5f;
        stroke.points = {{0.5, 0.5}};
        stroke.radius = 0.2;
        e.stroke = stroke;
        s.edits.push_back(e);
    }
    const std::string message = blowUpMessage(s);
    EXPECT_NE(message.find("the time step is within its stability limit, so it is not the "
                           "cause: 12 strokes put chemicals in"),
              std::string::npos)
        << message;
    EXPECT_EQ(message.find("--dt"), std::string::npos) << message;
    // At an unstable dt the time step is still named first.
    s.dt = 5.0f;
    const std::string unstable = blowUpMessage(s);
    EXPECT_NE(unstable.find("try a smaller time step such as --dt"), std::string::npos) << unstable;
}

// --- Live changes ----------------------------------------------------------------

namespace {

Session smallCoral() {
    Session s = test::smallSession("gs_coral", 32, 80);
    return s;
}

State initial(const Session& s) {
    return makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
}

// `steps` steps of `s` on a CPU simulator built for it, from `start`.
State runFrom(const Session& s, const State& start, int steps) {
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(steps);
    return sim.state();
}

} // namespace

TEST(LiveChanges, ParamsChangedMidRunEqualARunBuiltWithThem) {
    const Session s = smallCoral();
    SessionRun run(s, cpu());
    run.advance(40);
    const State middle = run.state();
    run.setParams({{"F", 0.03f}, {"k", 0.055f}});
    run.advance(40);
    Session changed = s;
    changed.params["F"] = 0.03f;
    changed.params["k"] = 0.055f;
    EXPECT_EQ(test::maxAbsDifference(run.state(), runFrom(changed, middle, 40)), 0.0f);
    // And the change mattered.
    EXPECT_GT(test::maxAbsDifference(run.state(), runFrom(s, middle, 40)), 1e-4f);
    EXPECT_EQ(run.completed().params.at("F"), 0.03f);
}

TEST(LiveChanges, ADiffusionRateChangedMidRunIsLive) {
    const Session s = smallCoral();
    CpuSimulator sim(s);
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed);
    sim.setState(start);
    sim.run(20);
    const State middle = sim.state();
    Session changed = s;
    changed.params["Du"] = 0.1f;
    sim.setParams(changed.params);
    sim.run(20);
    EXPECT_EQ(test::maxAbsDifference(sim.state(), runFrom(changed, middle, 20)), 0.0f);
    // A zero rate switches the CPU to its generic path.
    changed.params["Dv"] = 0.0f;
    const State before = sim.state();
    sim.setParams(changed.params);
    sim.run(10);
    EXPECT_EQ(test::maxAbsDifference(sim.state(), runFrom(changed, before, 10)), 0.0f);
}

TEST(LiveChanges, AGeneralizedKernelFromZeroRatesIsLive) {
    Session s = smallCoral();
    s.diffusion.type = DiffusionType::Generalized;
    s.diffusion.generalized = {{"u", "c"}, {"v", "c"}};
    Session still = s;
    // A zero kernel (on the CPU: the generic path; the change re-picks the fused one).
    still.params["Du"] = still.params["Dv"] = 0.0f;
    CpuSimulator sim(still);
    sim.setState(initial(still));
    sim.run(10);
    const State middle = sim.state();
    sim.setParams(s.params);
    sim.run(20);
    EXPECT_EQ(test::maxAbsDifference(sim.state(), runFrom(s, middle, 20)), 0.0f);
    EXPECT_GT(test::maxAbsDifference(sim.state(), runFrom(still, middle, 20)), 1e-4f);
}

// The generic path (here forced by a param map) keeps its own copy of the
// kernel taps; a live rate change must reach them too.
TEST(LiveChanges, AKernelRateChangedOnTheGenericPathIsLive) {
    Session s = smallCoral();
    s.diffusion.type = DiffusionType::Generalized;
    s.diffusion.generalized = {{"u", "c"}, {"v", "c"}};
    s.paramMaps["F"] = {ParamMapSpec::Field::LinearX, 0.03f, 0.05f};
    CpuSimulator sim(s);
    sim.setState(initial(s));
    sim.run(10);
    const State middle = sim.state();
    Session changed = s;
    changed.params["Du"] = 0.5f * s.params.at("Du");
    sim.setParams(changed.params);
    sim.run(20);
    EXPECT_EQ(test::maxAbsDifference(sim.state(), runFrom(changed, middle, 20)), 0.0f);
    EXPECT_GT(test::maxAbsDifference(sim.state(), runFrom(s, middle, 20)), 1e-5f);
}

TEST(LiveChanges, DtChangedMidRunEqualsARunBuiltWithIt) {
    for (Integrator integrator : {Integrator::ExplicitEuler, Integrator::SemiImplicit}) {
        Session s = smallCoral();
        s.integrator = integrator;
        SessionRun run(s, cpu());
        run.advance(30);
        const State middle = run.state();
        run.setDt(integrator == Integrator::SemiImplicit ? 3.0f : 0.5f);
        run.advance(30);
        Session changed = s;
        changed.dt = integrator == Integrator::SemiImplicit ? 3.0f : 0.5f;
        EXPECT_EQ(test::maxAbsDifference(run.state(), runFrom(changed, middle, 30)), 0.0f)
            << toString(integrator);
        EXPECT_GT(test::maxAbsDifference(run.state(), runFrom(s, middle, 30)), 1e-5f)
            << toString(integrator);
        EXPECT_EQ(run.completed().dt, changed.dt);
    }
}

TEST(LiveChanges, AMappedParameterKeepsItsMap) {
    Session s = loadPreset("gs_coral");
    s.width = 40;
    s.height = 8;
    s.length = 0;
    s.steps = 2;
    s.dt = 0.5f;
    s.params["Du"] = s.params["Dv"] = 0.0f;
    s.init = InitialCondition{}; // u = v = 0: one step gives u = dt F
    s.paramMaps["F"] = {ParamMapSpec::Field::LinearX, 0.01f, 0.09f};
    SessionRun run(s, cpu());
    ParamValues p = s.params;
    p["F"] = 0.05f;
    run.setParams(p);
    run.advance(1);
    const State st = run.state();
    const std::vector<float> expected = evaluateParamMap(s.paramMaps["F"], 40, 8, s.seed, "");
    for (std::size_t i = 0; i < st.cellCount(); ++i)
        ASSERT_NEAR(st.plane(0)[i] / s.dt, expected[i], 1e-6f) << "cell " << i;
}

TEST(LiveChanges, BadValuesAreRefusedAndChangeNothing) {
    const Session s = smallCoral();
    SessionRun run(s, cpu());
    EXPECT_THROW(run.setParams({{"nope", 1.0f}}), InputError);
    EXPECT_THROW(run.setParams({{"F", -1.0f}}), InputError);
    EXPECT_THROW(run.setDt(0.0f), InputError);
    EXPECT_THROW(run.setDt(std::nanf("")), InputError);
    run.advance(80);
    EXPECT_EQ(
        test::maxAbsDifference(
            run.state(),
            runFrom(s, makeInitialState(s.init, s.reactionModel(), s.params, 32, 32, s.seed), 80)),
        0.0f);
}

TEST(LiveChanges, ACascadeStageChangedLiveIsRecordedSoItReproduces) {
    Session s = smallGiraffe();
    SessionRun run(s, cpu());
    run.advance(260); // at stage 2, step 0
    ParamValues p = run.segmentSession().params;
    p["Dg"] = p["Dg"] * 0.8f;
    run.setParams(p);
    run.setDt(0.8f);
    run.advance(1000);
    const RunResult r = run.result();
    EXPECT_EQ(test::maxAbsDifference(runSession(r.completed, cpu(), {}).state, r.state), 0.0f);
    EXPECT_GT(test::maxAbsDifference(runSession(s, cpu(), {}).state, r.state), 1e-5f);
}

TEST(LiveChanges, ReplaceSessionRebuildsAndKeepsTheState) {
    const Session s = smallCoral();
    SessionRun run(s, cpu());
    run.advance(40);
    const State middle = run.state();
    Session nine = s;
    nine.diffusion.stencil = Stencil::NinePoint;
    run.replaceSession(nine);
    EXPECT_EQ(test::maxAbsDifference(run.state(), middle), 0.0f);
    run.advance(40);
    EXPECT_TRUE(run.finished());
    EXPECT_EQ(test::maxAbsDifference(run.state(), runFrom(nine, middle, 40)), 0.0f);

    SessionRun other(s, cpu());
    Session turing = loadPreset("turk_large_spots");
    turing.width = turing.height = 32;
    EXPECT_THROW(other.replaceSession(turing), InputError); // other chemicals
    Session bigger = s;
    bigger.width = 64;
    EXPECT_THROW(other.replaceSession(bigger), InputError);
    other.advance(80); // still the original run
    EXPECT_EQ(test::maxAbsDifference(other.state(), runSession(s, cpu(), {}).state), 0.0f);
}

TEST(SessionRun, StoppedBeforeAModelChangeWritesAReadableSession) {
    // turk_giraffe's colour map names a chemical of its second stage's model;
    // stopped in the first stage, the completed session shows the first model.
    Session s = smallGiraffe();
    ASSERT_FALSE(s.colormap.chemical.empty());
    SessionRun run(s, cpu());
    run.advance(50);
    const Session done = run.completed();
    EXPECT_EQ(done.stages.size(), 1u);
    EXPECT_NO_THROW(sessionFromJson(sessionToJson(done), "stopped.json"));
    // Past the switch, the map keeps its chemical.
    run.advance(260);
    EXPECT_EQ(run.completed().colormap.chemical, s.colormap.chemical);
}
