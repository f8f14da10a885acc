// The designer's crashed sessions (ui/crash_recovery.hpp): an autosave whose
// process is gone is kept aside under a name nothing writes to, never over
// another file, until the user restores or discards it.

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "ui/crash_recovery.hpp"

using namespace morphogen;
using namespace morphogen::ui;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) {
    return test::freshScratchDir("morphogen_crash_recovery_test", name);
}

std::string readText(const fs::path& path) {
    return test::readTextFile(path);
}

// A process id that has ended (a child, reaped).
long endedPid() {
    const pid_t child = ::fork();
    if (child == 0)
        std::_Exit(0);
    int status = 0;
    ::waitpid(child, &status, 0);
    return long(child);
}

} // namespace

TEST(CrashRecovery, AnEndedDesignersAutosaveIsKeptAsideAndALiveOnesIsNot) {
    const fs::path dir = freshDir("aside");
    const long gone = endedPid();
    std::ofstream(autosavePathFor(dir.string(), gone)) << "crashed";
    std::ofstream(autosavePathFor(dir.string(), long(::getpid()))) << "running";
    const std::vector<std::string> kept = keepCrashedAutosaves(dir.string());
    ASSERT_EQ(kept.size(), 1u);
    EXPECT_EQ(fs::path(kept[0]).filename().string().rfind("recovered-", 0), 0u) << kept[0];
    EXPECT_EQ(readText(kept[0]), "crashed");
    EXPECT_FALSE(fs::exists(autosavePathFor(dir.string(), gone)));
    EXPECT_EQ(readText(autosavePathFor(dir.string(), long(::getpid()))), "running");
}

TEST(CrashRecovery, KeptSessionsAreNeverReplacedAndComeNewestFirst) {
    const fs::path dir = freshDir("never_replaced");
    // An older designer's single autosave.json, then two more crashes.
    std::ofstream(dir / "autosave.json") << "first";
    fs::last_write_time(dir / "autosave.json",
                        fs::file_time_type::clock::now() - std::chrono::hours(2));
    ASSERT_EQ(keepCrashedAutosaves(dir.string()).size(), 1u);
    for (const char* text : {"second", "third"}) {
        const long gone = endedPid();
        std::ofstream(autosavePathFor(dir.string(), gone)) << text;
        keepCrashedAutosaves(dir.string());
    }
    const std::vector<std::string> kept = keepCrashedAutosaves(dir.string());
    ASSERT_EQ(kept.size(), 3u);
    EXPECT_EQ(readText(kept.back()), "first");
    std::set<std::string> texts;
    for (const std::string& k : kept)
        texts.insert(readText(k));
    EXPECT_EQ(texts, (std::set<std::string>{"first", "second", "third"}));
}

TEST(CrashRecovery, ARestoredSessionLeavesTheOffer) {
    const fs::path dir = freshDir("restored");
    std::ofstream(autosavePathFor(dir.string(), endedPid())) << "work";
    const std::vector<std::string> kept = keepCrashedAutosaves(dir.string());
    ASSERT_EQ(kept.size(), 1u);
    const std::string restored = markRestored(kept[0]);
    EXPECT_EQ(fs::path(restored).filename().string().rfind("restored-", 0), 0u) << restored;
    EXPECT_EQ(readText(restored), "work");
    EXPECT_TRUE(keepCrashedAutosaves(dir.string()).empty());
}
