#include "ui/crash_recovery.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <regex>

#include <signal.h>
#include <unistd.h>

namespace morphogen::ui {

namespace {

namespace fs = std::filesystem;

bool processRuns(long pid) {
    if (pid <= 0)
        return false;
    if (pid == long(::getpid()))
        return true;
    return !(::kill(pid_t(pid), 0) != 0 && errno == ESRCH);
}

// "20261207-031820": local time of `when`.
std::string stamp(fs::file_time_type when) {
    const auto system = std::chrono::time_point_cast<std::chrono::system_clock::duration>(
        when - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
    const std::time_t t = std::chrono::system_clock::to_time_t(system);
    std::tm local{};
    localtime_r(&t, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y%m%d-%H%M%S", &local);
    return text;
}

// `prefix` + stamp + "-N.json" in `dir` that does not exist yet.
fs::path freshName(const fs::path& dir, const std::string& prefix, const std::string& when) {
    for (int n = 1;; ++n) {
        const fs::path p = dir / (prefix + when + "-" + std::to_string(n) + ".json");
        std::error_code ec;
        if (!fs::exists(p, ec))
            return p;
    }
}

// Renames without replacing: link then unlink, so a file made meanwhile
// under the new name is never lost.
bool renameNoReplace(const fs::path& from, const fs::path& to) {
    if (::link(from.c_str(), to.c_str()) != 0)
        return false;
    ::unlink(from.c_str());
    return true;
}

} // namespace

std::string autosavePathFor(const std::string& stateDir, long pid) {
    return (fs::path(stateDir) / ("autosave-" + std::to_string(pid) + ".json")).string();
}

std::vector<std::string> keepCrashedAutosaves(const std::string& stateDir) {
    static const std::regex autosave(R"(^autosave(-([0-9]{1,9}))?\.json$)");
    static const std::regex recovered(R"(^recovered-.*\.json$)");
    std::error_code ec;
    std::vector<fs::path> crashed;
    for (const fs::directory_entry& e : fs::directory_iterator(stateDir, ec)) {
        const std::string name = e.path().filename().string();
        std::smatch m;
        if (!std::regex_match(name, m, autosave))
            continue;
        // autosave.json: an older designer's, which did not record its process.
        if (m[2].matched && processRuns(std::stol(m[2].str())))
            continue;
        crashed.push_back(e.path());
    }
    for (const fs::path& p : crashed) {
        const std::string when = stamp(fs::last_write_time(p, ec));
        bool moved = false;
        for (int attempt = 0; attempt < 100 && !moved; ++attempt)
            moved = renameNoReplace(p, freshName(stateDir, "recovered-", when));
        if (!moved)
            std::fprintf(stderr, "morphogen design: cannot keep the crashed session %s aside: %s\n",
                         p.c_str(), std::strerror(errno));
    }
    std::vector<std::pair<fs::file_time_type, std::string>> found;
    for (const fs::directory_entry& e : fs::directory_iterator(stateDir, ec))
        if (std::regex_match(e.path().filename().string(), recovered))
            found.emplace_back(fs::last_write_time(e.path(), ec), e.path().string());
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second > b.second;
    });
    std::vector<std::string> paths;
    for (const auto& f : found)
        paths.push_back(f.second);
    return paths;
}

std::string markRestored(const std::string& recovered) {
    const fs::path from(recovered);
    std::string name = from.filename().string();
    const std::string prefix = "recovered-";
    if (name.rfind(prefix, 0) == 0)
        name = name.substr(prefix.size());
    name = fs::path(name).stem().string();
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path to = freshName(from.parent_path(), "restored-", name);
        if (renameNoReplace(from, to))
            return to.string();
    }
    throw fs::filesystem_error("cannot mark the session restored", from,
                               std::error_code(errno, std::generic_category()));
}

} // namespace morphogen::ui
