// Output safety (core/io/output_files.hpp): temporaries next to the final
// path, replaced together or not at all, removed on failure and by the
// signal-time cleanup; writers that write staged temporaries in place.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
    return test::freshScratchDir("morphogen_output_files_test", name);
}

std::string readText(const fs::path& path) {
    return test::readTextFile(path);
}

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

// Names in `dir` starting with ".~": temporaries (ours).
int temporariesIn(const fs::path& dir) {
    int n = 0;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
        n += e.path().filename().string().rfind(".~", 0) == 0 ? 1 : 0;
    return n;
}

} // namespace

TEST(OutputFiles, TemporaryIsHiddenInTheSameFolderWithTheExtension) {
    const std::string tmp = temporaryPathFor("/some/dir/image.png");
    const fs::path p(tmp);
    EXPECT_EQ(p.parent_path(), fs::path("/some/dir"));
    EXPECT_EQ(p.extension(), ".png"); // OIIO picks the format by it
    EXPECT_EQ(p.filename().string().rfind(".~image.", 0), 0u) << tmp;
    EXPECT_NE(temporaryPathFor("/some/dir/image.png"), tmp); // never shared
    // A name near the file system's limit still gives a temporary within it.
    const std::string longName(250, 'n');
    const fs::path longTmp(temporaryPathFor("/d/" + longName + ".json"));
    EXPECT_LE(longTmp.filename().string().size(), 255u);
    EXPECT_EQ(longTmp.extension(), ".json");
}

TEST(OutputFiles, CommitReplacesEveryFileInOrder) {
    const fs::path dir = freshDir("commit");
    writeText(dir / "a.txt", "old a");
    writeText(dir / "b.json", "old b");
    {
        OutputFiles files;
        writeTextAtomically(files.stage((dir / "a.txt").string()), "new a");
        writeTextAtomically(files.stage((dir / "b.json").string()), "new b");
        EXPECT_EQ(liveTemporaryCount(), 2);
        // Nothing visible until the commit.
        EXPECT_EQ(readText(dir / "a.txt"), "old a");
        EXPECT_EQ(temporariesIn(dir), 2);
        files.commit();
        EXPECT_EQ(files.paths().back(), (dir / "b.json").string());
    }
    EXPECT_EQ(readText(dir / "a.txt"), "new a");
    EXPECT_EQ(readText(dir / "b.json"), "new b");
    EXPECT_EQ(temporariesIn(dir), 0);
    EXPECT_EQ(liveTemporaryCount(), 0);
}

TEST(OutputFiles, AFailedWriteReplacesNothingAndLeavesNoTemporaries) {
    const fs::path dir = freshDir("failed");
    writeText(dir / "image.txt", "old image");
    writeText(dir / "session.json", "old session");
    try {
        OutputFiles files;
        writeTextAtomically(files.stage((dir / "image.txt").string()), "new image");
        // The session's writer fails after its temporary exists.
        writeFileAtomically(files.stage((dir / "session.json").string()),
                            [](const std::string& tmp) {
                                std::ofstream(tmp) << "half";
                                throw std::runtime_error("disk full");
                            });
        files.commit();
        FAIL() << "the write should have thrown";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "disk full");
    }
    EXPECT_EQ(readText(dir / "image.txt"), "old image");
    EXPECT_EQ(readText(dir / "session.json"), "old session");
    EXPECT_EQ(temporariesIn(dir), 0);
    EXPECT_EQ(liveTemporaryCount(), 0);
}

TEST(OutputFiles, AFolderInTheWayIsFoundBeforeAnyRename) {
    const fs::path dir = freshDir("folder");
    writeText(dir / "image.txt", "old image");
    fs::create_directory(dir / "session.json"); // appeared during the run
    {
        OutputFiles files;
        writeTextAtomically(files.stage((dir / "image.txt").string()), "new image");
        writeTextAtomically(files.stage((dir / "session.json").string()), "new session");
        try {
            files.commit();
            FAIL() << "commit should have refused the folder";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("session.json: cannot write here: it is a folder"),
                      std::string::npos)
                << e.what();
        }
    }
    EXPECT_EQ(readText(dir / "image.txt"), "old image");
    EXPECT_TRUE(fs::is_directory(dir / "session.json"));
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(OutputFiles, APathStagedTwiceIsRefused) {
    const fs::path dir = freshDir("twice");
    OutputFiles files;
    files.stage((dir / "x.png").string());
    EXPECT_THROW(files.stage((dir / "." / "x.png").string()), InputError);
}

TEST(OutputFiles, MessagesNameTheFinalPathNotTheTemporary) {
    const fs::path dir = freshDir("messages");
    OutputFiles files;
    const std::string tmp = files.stage((dir / "raw.png").string());
    EXPECT_EQ(finalPathOf(tmp), (dir / "raw.png").string());
    State state(4, 4, 1);
    try {
        writeRawImage(tmp, state, {"u"}); // PNG cannot hold raw floats
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "raw.png").string(), 0), 0u) << e.what();
    }
}

TEST(OutputFiles, ImagesAndSessionsAreWrittenThroughTemporaries) {
    const fs::path dir = freshDir("writers");
    const std::string image = (dir / "grey.png").string();
    writeGreyImage(image, std::vector<float>(16, 0.5f), 4, 4, 8);
    EXPECT_TRUE(fs::is_regular_file(image));
    // A row callback that throws halfway: no image, no temporary.
    const std::string broken = (dir / "broken.png").string();
    EXPECT_THROW(writeImageRows(broken, 4, 4, 1, 8,
                                [](int y, float* row) {
                                    if (y == 2)
                                        throw std::runtime_error("interrupted");
                                    std::fill(row, row + 4, 0.25f);
                                }),
                 std::runtime_error);
    EXPECT_FALSE(fs::exists(broken));
    saveSessionFile(loadPreset("gs_coral"), (dir / "s.json").string());
    EXPECT_NO_THROW(loadSessionFile((dir / "s.json").string()));
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(StagedSequence, CommitReplacesTheOldSeriesAndKeepsOtherFiles) {
    const fs::path dir = freshDir("sequence");
    for (int i = 0; i < 5; ++i)
        writeText(dir / ("frame_0000" + std::to_string(i) + ".png"), "old");
    writeText(dir / "notes.txt", "mine");
    writeText(dir / "frame_final.png", "not a numbered frame");
    {
        StagedSequence frames(dir.string(), "frame_", ".png");
        for (int i = 0; i < 2; ++i) {
            writeTextAtomically(frames.path(i), "new " + std::to_string(i));
            frames.written(i);
        }
        EXPECT_EQ(readText(dir / "frame_00000.png"), "old"); // until the commit
        frames.commit();
    }
    EXPECT_EQ(readText(dir / "frame_00000.png"), "new 0");
    EXPECT_EQ(readText(dir / "frame_00001.png"), "new 1");
    EXPECT_FALSE(fs::exists(dir / "frame_00002.png")); // no mix of two runs
    EXPECT_EQ(readText(dir / "notes.txt"), "mine");
    EXPECT_TRUE(fs::exists(dir / "frame_final.png"));
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(StagedSequence, AnUncommittedSeriesIsRemovedAndTheOldOneStays) {
    const fs::path dir = freshDir("sequence_failed");
    writeText(dir / "frame_00000.png", "old");
    {
        StagedSequence frames(dir.string(), "frame_", ".png");
        writeTextAtomically(frames.path(0), "new");
        frames.written(0);
    }
    EXPECT_EQ(readText(dir / "frame_00000.png"), "old");
    EXPECT_EQ(temporariesIn(dir), 0);
    EXPECT_EQ(liveTemporaryCount(), 0);
}

// The signal handler's cleanup, in a child process (it disables new
// registrations for good, as the process is about to end).
TEST(OutputFilesDeathTest, SignalCleanupRemovesTemporariesAndStagedSeries) {
    const fs::path dir = freshDir("signal");
    writeText(dir / "image.txt", "old");
    EXPECT_EXIT(
        {
            OutputFiles files;
            writeTextAtomically(files.stage((dir / "image.txt").string()), "new");
            StagedSequence frames(dir.string(), "frame_", ".png");
            for (int i = 0; i < 3; ++i) {
                writeTextAtomically(frames.path(i), "frame");
                frames.written(i);
            }
            // A frame being written: its own temporary, and the next index half-written.
            std::ofstream(frames.path(3)) << "half";
            removeTemporariesForSignal();
            std::_Exit(temporariesIn(dir) == 0 && readText(dir / "image.txt") == "old" ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
    EXPECT_EQ(temporariesIn(dir), 0);
}

namespace {

// Runs `body` in a child process that ends with SIGKILL (as a crash or
// `kill -9` would; `body` sends it itself while its files are live, else it
// comes when `body` returns); waits for it. The child's temporaries
// carry its process id, which no longer runs afterwards.
template <class F> void inKilledChild(F body) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        body();
        ::kill(::getpid(), SIGKILL);
        std::_Exit(0); // not reached
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited instead of being killed";
}

} // namespace

TEST(OutputFiles, ACommitKilledBetweenItsRenamesIsFinishedByTheNextRun) {
    // A render's image and session, the run killed after the image's rename:
    // the folder holds a new image beside the old session until the next run
    // to it, which finishes the commit from the journal before anything else.
    const fs::path dir = freshDir("killed_commit");
    writeText(dir / "out.png", "old image");
    writeText(dir / "out.json", "old session");
    inKilledChild([&] {
        OutputFiles files;
        writeTextAtomically(files.stage((dir / "out.png").string()), "new image");
        writeTextAtomically(files.stage((dir / "out.json").string()), "new session");
        files.commit([](int renamed) {
            if (renamed == 1)
                ::kill(::getpid(), SIGKILL);
        });
    });
    EXPECT_EQ(readText(dir / "out.png"), "new image");
    EXPECT_EQ(readText(dir / "out.json"), "old session"); // the gap the journal closes
    EXPECT_GE(temporariesIn(dir), 2);                     // the session's temporary, the journal
    recoverInterruptedOutput(dir.string());
    EXPECT_EQ(readText(dir / "out.png"), "new image");
    EXPECT_EQ(readText(dir / "out.json"), "new session");
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(OutputFiles, ACommitKilledAcrossTwoFoldersIsFinishedFromEither) {
    // A texture set in a sub-folder and the image beside it: the journal is
    // in both folders, and the next run to either finishes the whole set.
    const fs::path dir = freshDir("killed_two_folders");
    fs::create_directories(dir / "tex");
    writeText(dir / "tex" / "albedo.png", "old albedo");
    writeText(dir / "out.json", "old session");
    inKilledChild([&] {
        OutputFiles files;
        writeTextAtomically(files.stage((dir / "tex" / "albedo.png").string()), "new albedo");
        writeTextAtomically(files.stage((dir / "out.json").string()), "new session");
        files.commit([](int renamed) {
            if (renamed == 1)
                ::kill(::getpid(), SIGKILL);
        });
    });
    recoverInterruptedOutput((dir / "tex").string());
    EXPECT_EQ(readText(dir / "tex" / "albedo.png"), "new albedo");
    EXPECT_EQ(readText(dir / "out.json"), "new session");
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(OutputFiles, TemporariesOfAKilledRunAreRemovedByTheNextRunToTheFolder) {
    const fs::path dir = freshDir("killed_temporaries");
    writeText(dir / "out.png", "old image");
    inKilledChild([&] {
        OutputFiles files;
        const std::string tmp = files.stage((dir / "out.png").string());
        writeTextAtomically(tmp, "half an image");
        StagedSequence frames(dir.string(), "frame_", ".png");
        writeTextAtomically(frames.path(0), "frame");
        frames.written(0);
        ::kill(::getpid(), SIGKILL); // before the destructors clean up
    });
    EXPECT_EQ(temporariesIn(dir), 2); // a temporary and a staging folder (holding a frame)
    // A live process's temporaries stay (this one's).
    OutputFiles mine;
    writeTextAtomically(mine.stage((dir / "other.txt").string()), "mine");
    recoverInterruptedOutput(dir.string());
    EXPECT_EQ(temporariesIn(dir), 1);
    EXPECT_EQ(readText(dir / "out.png"), "old image");
    mine.commit();
    EXPECT_EQ(temporariesIn(dir), 0);
    // The next run's first stage() in a folder is what cleans it up.
    const fs::path again = freshDir("killed_then_stage");
    inKilledChild([&] {
        OutputFiles files;
        writeTextAtomically(files.stage((again / "a.png").string()), "half");
        ::kill(::getpid(), SIGKILL);
    });
    OutputFiles next;
    next.stage((again / "b.png").string());
    EXPECT_EQ(temporariesIn(again), 0) << "stage() did not clean up the killed run's temporary";
}

TEST(OutputFiles, TwoRunsCommittingToTheSamePathsNeverMixTheirFiles) {
    // Each run's pair is renamed under a lock on the folder: whichever run
    // commits last, its image and its session are the pair left.
    const fs::path dir = freshDir("concurrent");
    for (int round = 0; round < 3; ++round) {
        std::vector<pid_t> children;
        for (int run = 0; run < 2; ++run) {
            const pid_t child = ::fork();
            ASSERT_GE(child, 0);
            if (child == 0) {
                const std::string name = "run " + std::to_string(run);
                OutputFiles files;
                writeTextAtomically(files.stage((dir / "out.png").string()), name);
                writeTextAtomically(files.stage((dir / "out.json").string()), name);
                // A slow rename: the other run's commit would fall between these.
                files.commit([](int) { ::usleep(20000); });
                std::_Exit(0);
            }
            children.push_back(child);
        }
        for (pid_t child : children) {
            int status = 0;
            ASSERT_EQ(::waitpid(child, &status, 0), child);
            ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
        }
        EXPECT_EQ(readText(dir / "out.png"), readText(dir / "out.json")) << "round " << round;
    }
    EXPECT_EQ(temporariesIn(dir), 0);
}

TEST(OutputFiles, AShortWriteIsCaughtBeforeTheRename) {
    const fs::path dir = freshDir("short_write");
    writeText(dir / "data.bin", "abc");
    EXPECT_NO_THROW(checkWrittenSize((dir / "data.bin").string(), 3, "data.bin"));
    try {
        checkWrittenSize((dir / "data.bin").string(), 10, "final.bin");
        FAIL() << "a short file passed";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("final.bin: writing the file failed: 3 of 10 bytes"),
                  std::string::npos)
            << e.what();
    }
}

TEST(OutputFiles, AJournalThatDoesNotDescribeACommitMovesNothing) {
    // A journal naming a file in another folder as its "temporary" (forged, or
    // from elsewhere): recovery leaves both files where they are.
    const fs::path dir = freshDir("forged_journal");
    const fs::path elsewhere = freshDir("forged_journal_elsewhere");
    writeText(elsewhere / "secret.txt", "secret");
    writeText(dir / "out.json", "old");
    pid_t gone = ::fork();
    if (gone == 0)
        std::_Exit(0);
    ::waitpid(gone, nullptr, 0);
    const std::string pid = std::to_string(gone);
    writeText(dir / (".~commit." + pid + "-0.journal"),
              R"({"morphogen_commit": 1, "files": [[")" + (elsewhere / "secret.txt").string() +
                  R"(", ")" + (dir / "out.json").string() + R"("]], "journals": []})");
    recoverInterruptedOutput(dir.string());
    EXPECT_EQ(readText(dir / "out.json"), "old");
    EXPECT_EQ(readText(elsewhere / "secret.txt"), "secret");
}
