#include "bench/bench_memory.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli/peak_memory.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

extern char** environ;

namespace morphogen::bench {

namespace fs = std::filesystem;

namespace {

struct ChildRun {
    int exitCode = -1;
    double peakMb = 0;     // its VmHWM
    std::string lastError; // the last line of its stderr when it failed
};

std::string lastLine(const fs::path& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty())
            last = line;
    return last;
}

// Runs this executable with `args` (stdout to /dev/null, stderr to
// `errFile`) and waits for it; it writes its peak memory to `peakFile`.
ChildRun runChild(const std::vector<std::string>& args, const fs::path& errFile,
                  const fs::path& peakFile) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e)
        if (std::string(*e).rfind(std::string(cli::kPeakMemoryEnv) + "=", 0) != 0)
            env.emplace_back(*e);
    env.push_back(std::string(cli::kPeakMemoryEnv) + "=" + peakFile.string());
    std::vector<char*> envp;
    for (std::string& e : env)
        envp.push_back(e.data());
    envp.push_back(nullptr);
    fs::remove(peakFile);

    std::vector<char*> argv;
    std::string self = "/proc/self/exe";
    argv.push_back(self.data());
    std::vector<std::string> copies = args;
    for (std::string& a : copies)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errFile.c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int spawned =
        posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throw std::runtime_error("bench: cannot start a render process: " +
                                 std::string(std::strerror(spawned)));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            throw std::runtime_error("bench: waiting for a render process failed: " +
                                     std::string(std::strerror(errno)));
    ChildRun run;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    long long kb = -1;
    std::ifstream(peakFile) >> kb;
    if (run.exitCode != 0)
        run.lastError = lastLine(errFile);
    else if (kb <= 0) {
        run.exitCode = 1;
        run.lastError = "it reported no peak memory (VmHWM of /proc/self/status)";
    }
    run.peakMb = double(kb) * 1024.0 / 1e6;
    return run;
}

// The largest state the session holds: its cells times the most chemicals of
// any stage's model, in floats.
double stateMb(const Session& session) {
    std::size_t chemicals = 0;
    for (const Session& s : segmentSessions(session))
        chemicals = std::max(chemicals, s.reactionModel().chemicals().size());
    return double(session.width) * double(session.height) * double(chemicals) * 4.0 / 1e6;
}

ChildRun renderOnce(const MemoryBench& bench, const std::string& backend, int size,
                    const fs::path& dir) {
    std::vector<std::string> args = {"render",
                                     "--preset",
                                     bench.preset,
                                     "--size",
                                     std::to_string(size),
                                     "--steps",
                                     std::to_string(kMemoryBenchSteps),
                                     "--backend",
                                     backend,
                                     "--out",
                                     (dir / "render.png").string()};
    if (!bench.context.empty())
        args.insert(args.end(), {"--context", bench.context});
    if (!bench.gpuDevice.empty())
        args.insert(args.end(), {"--gpu-device", bench.gpuDevice});
    return runChild(args, dir / "stderr.txt", dir / "peak.txt");
}

} // namespace

nlohmann::json benchMemory(const MemoryBench& bench) {
    nlohmann::json rows = nlohmann::json::array();
    const Session base = loadPreset(bench.preset);
    std::printf("\n%-26s %-8s %-6s %10s %10s %11s %10s %12s\n", "memory (render, 10 steps)",
                "backend", "size", "peak MB", "state MB", "baseline MB", "peak/state",
                "growth/state");
    if (!base.stages.empty()) {
        std::printf("(skipped: preset %s is a cascade, whose stages set their own steps)\n",
                    bench.preset.c_str());
        return rows;
    }
    // The renders' images and stderr, removed however the rows end.
    struct TempDir {
        fs::path path;
        ~TempDir() {
            std::error_code ec;
            fs::remove_all(path, ec);
        }
    } temp{fs::temp_directory_path() / ("morphogen-bench-memory-" + std::to_string(::getpid()))};
    const fs::path& dir = temp.path;
    fs::create_directories(dir);
    for (const std::string& backend : bench.backends) {
        std::fprintf(stderr, "bench: memory of a 16x16 %s render (the baseline)...\n",
                     backend.c_str());
        const ChildRun baseline = renderOnce(bench, backend, 16, dir);
        for (int n : bench.sizes) {
            std::fprintf(stderr, "bench: memory of a %dx%d %s render...\n", n, n, backend.c_str());
            Session s = base;
            resizeSession(s, n, n);
            const double state = stateMb(s);
            const ChildRun run = renderOnce(bench, backend, n, dir);
            nlohmann::json row = {{"backend", backend},
                                  {"size", n},
                                  {"steps", kMemoryBenchSteps},
                                  {"state_mb", state}};
            if (run.exitCode != 0 || baseline.exitCode != 0) {
                const ChildRun& failed = run.exitCode != 0 ? run : baseline;
                row["error"] =
                    "render exited " + std::to_string(failed.exitCode) + ": " + failed.lastError;
                std::printf("%-26s %-8s %-6d failed: %s\n", "", backend.c_str(), n,
                            row["error"].get<std::string>().c_str());
            } else {
                const double growth = (run.peakMb - baseline.peakMb) / state;
                row["peak_rss_mb"] = run.peakMb;
                row["baseline_rss_mb"] = baseline.peakMb;
                row["peak_over_state"] = run.peakMb / state;
                row["growth_over_state"] = growth;
                std::printf("%-26s %-8s %-6d %10.1f %10.1f %11.1f %10.2f %12.2f\n", "",
                            backend.c_str(), n, run.peakMb, state, baseline.peakMb,
                            run.peakMb / state, growth);
            }
            std::fflush(stdout);
            rows.push_back(row);
        }
    }
    return rows;
}

} // namespace morphogen::bench
