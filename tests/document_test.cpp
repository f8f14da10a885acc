// The designer's document on the CPU backend, no window: strokes, parameter
// drags, resets and history branches undo and redo exactly, and a saved
// session replays to the canvas' state bit for bit.

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"
#include "ui/document.hpp"

using namespace morphogen;
using morphogen::ui::Document;
using morphogen::ui::GrowthHistory;
using morphogen::ui::readStateFile;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

Session small() {
    Session s = loadPreset("gs_coral");
    s.width = s.height = 40;
    return s;
}

StrokeSpec brush(BrushMode mode = BrushMode::Add) {
    StrokeSpec b;
    b.mode = mode;
    b.chemical = "v";
    b.value = 0.3f;
    b.radius = 0.1;
    return b;
}

float difference(const State& a, const State& b) {
    return test::maxAbsDifference(a, b);
}

} // namespace

TEST(Document, OpensOpenEndedAtTheSessionsSize) {
    Document doc(cpu());
    doc.open(small());
    EXPECT_EQ(doc.live().width, 40);
    EXPECT_EQ(doc.advance(30), 30);
    EXPECT_EQ(doc.steps(), 30);
    // Past the preset's own steps: the canvas keeps growing.
    Session s = small();
    s.steps = 10;
    doc.open(s);
    EXPECT_EQ(doc.advance(25), 25);
    EXPECT_FALSE(doc.run().finished());
}

TEST(Document, StrokeUndoAndRedoAreExact) {
    Document doc(cpu());
    doc.open(small());
    doc.advance(20);
    const State before = doc.run().state();
    doc.beginStroke(brush());
    doc.extendStroke({{0.3, 0.3}});
    doc.extendStroke({{0.5, 0.4}, {0.6, 0.6}});
    doc.endStroke();
    const State painted = doc.run().state();
    EXPECT_GT(difference(before, painted), 0.1f);
    EXPECT_EQ(doc.undoLabel(), "add stroke");
    doc.advance(7); // the pattern goes on; undo takes it back to before the stroke
    doc.undo();
    EXPECT_EQ(difference(doc.run().state(), before), 0.0f);
    EXPECT_EQ(doc.steps(), 20);
    EXPECT_TRUE(doc.run().edits().empty());
    doc.redo();
    EXPECT_EQ(difference(doc.run().state(), painted), 0.0f);
    EXPECT_EQ(doc.run().edits().size(), 2u); // one edit per extension
}

TEST(Document, AParameterDragIsOneUndoStep) {
    Document doc(cpu());
    doc.open(small());
    const float f0 = doc.live().params.at("F");
    doc.beginChange("change F");
    for (float f : {0.03f, 0.035f, 0.04f})
        doc.setParam("F", f);
    doc.endChange();
    EXPECT_EQ(doc.live().params.at("F"), 0.04f);
    doc.advance(5);
    doc.undo();
    EXPECT_EQ(doc.live().params.at("F"), f0);
    EXPECT_FALSE(doc.canUndo());
    doc.redo();
    EXPECT_EQ(doc.live().params.at("F"), 0.04f);
}

TEST(Document, SavedSessionReplaysTheCanvas) {
    Document doc(cpu());
    doc.open(small());
    doc.advance(15);
    doc.beginChange("change k");
    doc.setParam("k", 0.058f);
    doc.endChange();
    doc.advance(10);
    doc.beginStroke(brush(BrushMode::Randomise));
    doc.extendStroke({{0.7, 0.2}, {0.2, 0.7}});
    doc.endStroke();
    doc.advance(12);
    const std::string path =
        (std::filesystem::temp_directory_path() / "morphogen_document_test.json").string();
    doc.save(path);
    EXPECT_FALSE(doc.dirty());
    const Session saved = loadSessionFile(path);
    EXPECT_EQ(saved.steps, 37);
    EXPECT_FALSE(saved.coarseToFine);
    const RunResult again = runSession(saved, cpu(), {});
    EXPECT_EQ(difference(again.state, doc.run().state()), 0.0f);
    std::filesystem::remove(path);
}

TEST(Document, ResetAndItsUndo) {
    Document doc(cpu());
    doc.open(small());
    doc.advance(25);
    const State grown = doc.run().state();
    doc.reset();
    EXPECT_EQ(doc.steps(), 0);
    doc.undo();
    EXPECT_EQ(doc.steps(), 25);
    EXPECT_EQ(difference(doc.run().state(), grown), 0.0f);
    doc.reseed(99);
    EXPECT_EQ(doc.session().seed, 99u);
    EXPECT_EQ(doc.steps(), 0);
}

TEST(Document, HistoryBranchesAndUndoesTheBranch) {
    Document doc(cpu());
    doc.open(small());
    doc.advance(10);
    doc.recordSnapshot();
    const State atTen = doc.run().state();
    doc.advance(10);
    doc.recordSnapshot();
    doc.advance(5);
    const State atTwentyFive = doc.run().state();
    ASSERT_EQ(doc.history().size(), 2u);
    doc.branch(0);
    EXPECT_EQ(doc.steps(), 10);
    EXPECT_EQ(difference(doc.run().state(), atTen), 0.0f);
    EXPECT_EQ(doc.history().size(), 1u);
    doc.undo();
    EXPECT_EQ(doc.steps(), 25);
    EXPECT_EQ(difference(doc.run().state(), atTwentyFive), 0.0f);
}

TEST(Document, HistoryStaysWithinItsBudget) {
    Document doc(cpu());
    doc.open(small());
    const std::size_t snapshotBytes = 40 * 40 * 2 * sizeof(float);
    doc.setHistoryBudget(snapshotBytes * 6);
    for (int i = 0; i < 40; ++i) {
        doc.advance(1);
        doc.recordSnapshot();
    }
    EXPECT_LE(doc.history().size(), 6u);
    EXPECT_GE(doc.history().size(), 3u);
    // The span is kept: the first snapshot and the latest.
    EXPECT_EQ(doc.history().step(0), 1);
    EXPECT_EQ(doc.history().lastStep(), 40);
}

TEST(Document, HistorySpillsToDiskAndReadsBack) {
    const std::filesystem::path folder = test::scratchDir("document_history") / "spill";
    std::filesystem::remove_all(folder);
    std::vector<State> states;
    {
        Document doc(cpu());
        doc.open(small());
        const std::size_t snapshotBytes = 40 * 40 * 2 * sizeof(float);
        // Two states in memory, twenty on disk.
        doc.setHistoryBudget(snapshotBytes * 2);
        doc.setHistorySpill(folder.string(), snapshotBytes * 20);
        for (int i = 0; i < 12; ++i) {
            doc.advance(2);
            doc.recordSnapshot();
            states.push_back(doc.run().state());
        }
        const GrowthHistory& h = doc.history();
        ASSERT_EQ(h.size(), 12u); // nothing thinned: the disk holds the rest
        EXPECT_TRUE(h.spilled(0));
        EXPECT_FALSE(h.spilled(11));
        EXPECT_LE(h.memoryBytes(), snapshotBytes * 2);
        EXPECT_EQ(h.diskBytes(), snapshotBytes * 10);
        for (std::size_t i = 0; i < h.size(); ++i)
            EXPECT_EQ(difference(h.state(i), states[i]), 0.0f) << "snapshot " << i;
        // Branching from a spilled snapshot restores its state exactly.
        doc.branch(3);
        EXPECT_EQ(doc.steps(), 8);
        EXPECT_EQ(difference(doc.run().state(), states[3]), 0.0f);
        EXPECT_EQ(h.size(), 4u);
        // The dropped snapshots' files are gone.
        std::size_t files = 0;
        for ([[maybe_unused]] const auto& f : std::filesystem::directory_iterator(folder))
            ++files;
        EXPECT_EQ(files, 4u); // snapshots 0-3 were all on disk
    }
    // The history's folder goes with it.
    EXPECT_FALSE(std::filesystem::exists(folder));
}

TEST(Document, HistoryFilesThatAreDamagedAreRefusedByName) {
    const std::filesystem::path file = test::scratchDir("document_history") / "bad.state";
    {
        std::ofstream out(file, std::ios::binary);
        out << "not a state";
    }
    try {
        (void)readStateFile(file);
        FAIL() << "a damaged snapshot was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("bad.state"), std::string::npos) << e.what();
    }
}

TEST(Document, AWatercolourBrushLaysWaterAndPigmentAlongOneDrag) {
    Document doc(cpu());
    Session s = loadPreset("watercolour_wet_in_wet");
    s.width = s.height = 48;
    s.edits.clear();
    doc.open(s);
    doc.advance(5);
    StrokeSpec water;
    water.mode = BrushMode::Add;
    water.chemical = "w";
    water.value = 1.5f;
    water.radius = 0.1;
    StrokeSpec pigment = water;
    pigment.chemical = "p2";
    pigment.value = 0.4f;
    const State before = doc.run().state();
    doc.beginStroke(water, pigment);
    doc.extendStroke({{0.3, 0.5}});
    doc.extendStroke({{0.4, 0.5}});
    doc.extendStroke({{0.5, 0.5}});
    doc.endStroke();
    const State after = doc.run().state();
    // Each chemical rose by at most its own amount (one opacity stroke each),
    // and by the full amount under the path.
    const ReactionModel& m = doc.live().reactionModel();
    const int w = m.chemicalIndex("w"), p2 = m.chemicalIndex("p2");
    float riseW = 0, riseP = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) {
            riseW = std::max(riseW, after.at(w, x, y) - before.at(w, x, y));
            riseP = std::max(riseP, after.at(p2, x, y) - before.at(p2, x, y));
        }
    EXPECT_NEAR(riseW, 1.5f, 1e-4f);
    EXPECT_NEAR(riseP, 0.4f, 1e-4f);
    EXPECT_EQ(doc.run().edits().size(), 6u); // three pieces, two edits each
    // Saved, the session replays it.
    doc.advance(5);
    const std::string path = (test::scratchDir("document_watercolour") / "wc.json").string();
    doc.save(path);
    const RunResult replay = runSession(loadSessionFile(path), cpu(), {});
    EXPECT_EQ(difference(replay.state, doc.run().state()), 0.0f);
}
