// Growth animations: the frame schedule, runWithFrames on the CPU backend
// (frames from the one run, over cascade stages and schedule levels), locked
// colour levels, and the ffmpeg command.

#include <atomic>
#include <string>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/output/frames.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

namespace morphogen {
namespace {

// `f` throws InputError whose message contains `needle`.
template <class F> void expectInputError(F f, const std::string& needle) {
    try {
        f();
        ADD_FAILURE() << "no InputError (want '" << needle << "')";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

TEST(FrameSteps, EvenlySpacedFramesEndOnTheFinalStep) {
    EXPECT_EQ(frameSteps(60, 3, std::nullopt), (std::vector<int>{20, 40, 60}));
    EXPECT_EQ(frameSteps(100, 3, std::nullopt), (std::vector<int>{34, 67, 100}));
    EXPECT_EQ(frameSteps(100, 1, std::nullopt), (std::vector<int>{100}));
    // More frames than steps: one per step, no repeats.
    EXPECT_EQ(frameSteps(3, 5, std::nullopt), (std::vector<int>{1, 2, 3}));
}

TEST(FrameSteps, EveryKStepsAddsTheFinalStepWhenKDoesNotDivide) {
    EXPECT_EQ(frameSteps(60, std::nullopt, 20), (std::vector<int>{20, 40, 60}));
    EXPECT_EQ(frameSteps(50, std::nullopt, 20), (std::vector<int>{20, 40, 50}));
    EXPECT_EQ(frameSteps(10, std::nullopt, 20), (std::vector<int>{10}));
}

TEST(FrameSteps, BadFlagsNameTheFlag) {
    expectInputError([] { frameSteps(60, 0, std::nullopt); }, "--frames 0");
    expectInputError([] { frameSteps(60, std::nullopt, -2); }, "--every -2");
    expectInputError([] { frameSteps(60, 3, 5); }, "exclusive");
    expectInputError([] { frameSteps(60, std::nullopt, std::nullopt); }, "--frames N");
}

TEST(LockedLevels, OneValueGetsOneColourInFramesOfDifferentRanges) {
    ColorMapSpec spec;
    spec.name = "viridis";
    const FrameLevels levels{0.0f, 1.0f, "test"};
    // Frame a spans 0.2..0.4, frame b 0.1..0.9; both hold 0.3 at cell 1.
    State a(3, 1, 1), b(3, 1, 1);
    a.at(0, 0, 0) = 0.2f, a.at(0, 1, 0) = 0.3f, a.at(0, 2, 0) = 0.4f;
    b.at(0, 0, 0) = 0.1f, b.at(0, 1, 0) = 0.3f, b.at(0, 2, 0) = 0.9f;
    const std::vector<float> ra = applyLockedColormap(a, 0, spec, levels);
    const std::vector<float> rb = applyLockedColormap(b, 0, spec, levels);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(ra[3 + std::size_t(c)], rb[3 + std::size_t(c)]) << "channel " << c;
    // Per-frame min-max would give the two different colours: the flicker locking avoids.
    EXPECT_NE(applyColormap(a, 0, spec)[3], applyColormap(b, 0, spec)[3]);
}

TEST(LockedLevels, ValuesMapThroughTheRangeAndClamp) {
    ColorMapSpec grey; // grey: the colour is t
    State s(4, 1, 1);
    s.at(0, 0, 0) = 1.0f, s.at(0, 1, 0) = 2.0f, s.at(0, 2, 0) = 5.0f, s.at(0, 3, 0) = 9.0f;
    const std::vector<float> rgb = applyLockedColormap(s, 0, grey, {1.0f, 5.0f, "test"});
    EXPECT_FLOAT_EQ(rgb[0], 0.0f);
    EXPECT_FLOAT_EQ(rgb[3], 0.25f);
    EXPECT_FLOAT_EQ(rgb[6], 1.0f);
    EXPECT_FLOAT_EQ(rgb[9], 1.0f); // above the range: clamped
}

TEST(LockedLevels, FrameRangeFlagIsCheckedAndDefaultsToTheDisplayRange) {
    const Session s = loadPreset("turk_large_spots");
    const ReactionModel& m = s.outputModel();
    const FrameLevels model = frameLevels(m, 0, "");
    EXPECT_EQ(model.low, m.chemicals()[0].displayRange[0]);
    EXPECT_EQ(model.high, m.chemicals()[0].displayRange[1]);
    const FrameLevels given = frameLevels(m, 0, "0.5:2");
    EXPECT_EQ(given.low, 0.5f);
    EXPECT_EQ(given.high, 2.0f);
    expectInputError([&] { frameLevels(m, 0, "2:1"); }, "--frame-range '2:1'");
    expectInputError([&] { frameLevels(m, 0, "0.5"); }, "--frame-range '0.5'");
}

// turk_giraffe colours its net's g2, a chemical of its last stage only: a
// frame of its first stage (turing_turk) shows that model's display chemical
// over its display range, a frame of the last stage the map as given with the
// run's levels.
TEST(LockedLevels, AnEarlierStageWithoutTheMapsChemicalShowsItsOwn) {
    const Session s = loadPreset("turk_giraffe");
    const ReactionModel& last = s.outputModel();
    const ReactionModel& first = s.reactionModel();
    ASSERT_LT(first.chemicalIndex(s.colormap.chemical), 0);
    const FrameLevels levels = frameLevels(last, colormapChemical(s.colormap, last), "");
    const FrameColouring early = frameColouring(s.colormap, first, levels);
    const int shown = first.displayChemical();
    EXPECT_EQ(early.spec.chemical, first.chemicals()[std::size_t(shown)].name);
    EXPECT_EQ(early.spec.name, s.colormap.name);
    EXPECT_EQ(early.levels.low, first.chemicals()[std::size_t(shown)].displayRange[0]);
    EXPECT_EQ(early.levels.high, first.chemicals()[std::size_t(shown)].displayRange[1]);
    const FrameColouring late = frameColouring(s.colormap, last, levels);
    EXPECT_EQ(late.spec.chemical, s.colormap.chemical);
    EXPECT_EQ(late.levels.low, levels.low);
    EXPECT_EQ(late.levels.high, levels.high);
}

// Frames through a cascade: the last frame is runSession's final state exactly,
// and each frame comes at its step.
TEST(RunWithFrames, CascadeFramesComeFromTheOneRunAndEndOnItsResult) {
    Session s = loadPreset("turk_giraffe");
    s.width = s.height = 24;
    s.stages[0].steps = 70;
    s.stages[1].steps = 50;
    s.steps = 120;
    ASSERT_EQ(sessionTotalSteps(s), 120);
    RunOptions options;
    options.chunk = 40;
    const std::vector<int> steps = frameSteps(sessionTotalSteps(s), 4, std::nullopt);
    ASSERT_EQ(steps, (std::vector<int>{30, 60, 90, 120}));
    std::vector<int> seen;
    State last;
    const RunResult r =
        runWithFrames(s, cpu(), options, steps, [&](int index, const RunResult& sofar) {
            EXPECT_EQ(index, int(seen.size()));
            seen.push_back(sofar.stepsDone);
            last = sofar.state;
        });
    EXPECT_EQ(seen, steps);
    const RunResult plain = runSession(s, cpu(), options);
    EXPECT_EQ(r.stepsDone, 120);
    EXPECT_EQ(test::maxAbsDifference(r.state, plain.state), 0.0f);
    EXPECT_EQ(test::maxAbsDifference(last, plain.state), 0.0f);
}

// Frames taken on a coarse schedule level are resampled to the final size.
TEST(RunWithFrames, ScheduleLevelFramesHaveTheFinalSize) {
    Session s = loadPreset("gs_coral");
    applySchedule(s, {{16, 16, 40}, {24, 24, 40}});
    std::vector<int> widths;
    runWithFrames(s, cpu(), RunOptions{}, frameSteps(sessionTotalSteps(s), std::nullopt, 20),
                  [&](int, const RunResult& sofar) { widths.push_back(sofar.state.width()); });
    EXPECT_EQ(widths, (std::vector<int>{24, 24, 24, 24}));
}

TEST(RunWithFrames, CancelStopsAfterTheCurrentChunkKeepingEarlierFrames) {
    Session s = loadPreset("gs_coral");
    s.width = s.height = 16;
    s.steps = 100;
    std::atomic<bool> cancel{false};
    RunOptions options;
    options.chunk = 10;
    options.cancel = &cancel;
    int frames = 0;
    const RunResult r = runWithFrames(s, cpu(), options, frameSteps(100, 5, std::nullopt),
                                      [&](int, const RunResult&) {
                                          if (++frames == 2)
                                              cancel = true;
                                      });
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(frames, 2);
    EXPECT_EQ(r.stepsDone, 40);
}

TEST(Video, FfmpegCommandByExtension) {
    const std::string mp4 = ffmpegCommand("out/a_frames", "a.mp4", 24);
    EXPECT_NE(mp4.find("-framerate 24 -i 'out/a_frames/frame_%05d.png'"), std::string::npos);
    EXPECT_NE(mp4.find("libx264"), std::string::npos);
    EXPECT_NE(mp4.find("'a.mp4'"), std::string::npos);
    EXPECT_NE(ffmpegCommand("d", "a.GIF", 30).find("palettegen"), std::string::npos);
    expectInputError([] { videoFormatForPath("a.avi"); }, "'.avi'");
    // A quote in a path stays one shell word.
    EXPECT_NE(ffmpegCommand("d", "it's.gif", 30).find("'it'\\''s.gif'"), std::string::npos);
}

} // namespace
} // namespace morphogen
