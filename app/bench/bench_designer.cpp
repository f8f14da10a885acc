#include "bench/bench_designer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "bench/bench_timing.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"

namespace morphogen::bench {

namespace {

namespace fs = std::filesystem;

struct DesignerRun {
    bool ok = false;
    double fps = 0, stepsPerSecond = 0;
    // Milliseconds per frame in each part (the script's `frame:` line): where
    // the time that is not the simulation's goes.
    std::array<double, 6> frameMs{};
    bool frameKnown = false;
    std::string error;
};

constexpr std::array<const char*, 6> kFrameParts = {"events",    "simulate", "display",
                                                    "interface", "draw",     "present"};

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

// The designer on `session` at `stepsPerFrame` (0: auto) for `frames` frames
// after 30 to settle; its script's last `rates` line.
DesignerRun runDesigner(const fs::path& dir, const fs::path& session, int stepsPerFrame,
                        int frames) {
    const fs::path script = dir / "script.txt";
    // The presets' thumbnails first: they render on a worker on the first
    // start (then come from the cache, which the runs share).
    std::ofstream(script) << "open " << session.string() << "\n"
                          << "wait-thumbnails\n"
                          << "until-step 2\n"
                          << "steps-per-frame " << stepsPerFrame << "\n"
                          << "frames 30\n"
                          << "rates\n"
                          << "frames " << frames << "\n"
                          << "rates\n"
                          << "quit\n";
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    const std::string command = quoted(self) + " design --backend cpu --script " +
                                quoted(script.string()) + " --config-dir " +
                                quoted((dir / "config").string()) + " --state-dir " +
                                quoted((dir / "state").string()) + " > " + quoted(out.string()) +
                                " 2> " + quoted(err.string());
    DesignerRun run;
    const int status = std::system(command.c_str());
    std::ifstream in(out);
    std::string line, last, frame;
    while (std::getline(in, line)) {
        if (line.rfind("rates:", 0) == 0)
            last = line;
        else if (line.rfind("frame:", 0) == 0)
            frame = line;
    }
    long long f = 0, steps = 0;
    double span = 0;
    if (status != 0 || last.empty() ||
        std::sscanf(last.c_str(), "rates: %lld frames, %lld steps in %lf s", &f, &steps, &span) !=
            3 ||
        span <= 0) {
        std::ifstream e(err);
        std::string l;
        while (std::getline(e, l))
            if (!l.empty())
                run.error = l;
        if (run.error.empty())
            run.error =
                "the designer printed no rates (exit status " + std::to_string(status) + ")";
        return run;
    }
    run.ok = true;
    std::array<double, 6>& t = run.frameMs;
    run.frameKnown = std::sscanf(frame.c_str(),
                                 "frame: %lf ms events, %lf simulate, %lf display, %lf interface, "
                                 "%lf draw, %lf present",
                                 &t[0], &t[1], &t[2], &t[3], &t[4], &t[5]) == 6;
    run.fps = double(f) / span;
    run.stepsPerSecond = double(steps) / span;
    return run;
}

} // namespace

nlohmann::json benchDesigner(const DesignerBench& bench) {
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-30s %-6s %12s %10s %12s %12s\n", "designer (cpu backend)", "size",
                "steps/frame", "frames/s", "steps/s", "of bench cpu");
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::printf("  skipped: no display ($DISPLAY); run the bench under xvfb-run\n");
        return {{"runs", rows}, {"skipped", "no display"}};
    }
    const int n = bench.size;
    Session s = loadPreset(bench.preset);
    resizeSession(s, n, n);
    s.length = n; // one cell per unit: a session step is one simulator step
    s.steps = 1;

    // The baseline, as the throughput rows measure it, again after every
    // designer run: on a shared machine the host's speed drifts by 10-30%
    // within minutes, so each run is compared with the baselines on either
    // side of it, and the fixed-steps row is the median of kRounds runs.
    std::fprintf(stderr, "bench: %dx%d cpu step (designer baseline)...\n", n, n);
    CpuSimulator cpu(s);
    cpu.setState(makeInitialState(s.init, s.reactionModel(), s.params, n, n, s.seed));
    const int batch = std::max(1, int(2e6 / (double(n) * n)));
    const auto measureBaseline = [&] {
        return measureStepsPerSecond([&](int k) { cpu.run(k); }, [] {}, bench.seconds, batch);
    };
    double before = measureBaseline();
    double lowest = before, highest = before;

    const fs::path dir =
        fs::temp_directory_path() / ("morphogen-bench-designer-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path session = dir / "session.json";
    saveSessionFile(s, session.string());
    // 80% of the baseline at 30 frames/s, in whole steps per frame.
    const int target = std::max(1, int(std::ceil(0.8 * before / 30.0)));
    const int frames = std::max(150, int(bench.seconds * 30));
    constexpr int kRounds = 3;
    std::vector<double> ratios, rates; // of the fixed-steps runs
    int met = 0;
    for (int round = 0; round <= kRounds; ++round) {
        const bool automatic = round == kRounds; // the auto mode once, last
        const int stepsPerFrame = automatic ? 0 : target;
        const std::string label = automatic ? "auto" : std::to_string(stepsPerFrame);
        const std::string of = automatic ? ""
                                         : " (run " + std::to_string(round + 1) + " of " +
                                               std::to_string(kRounds) + ")";
        std::fprintf(stderr, "bench: designer at %s steps per frame%s...\n", label.c_str(),
                     of.c_str());
        const DesignerRun run = runDesigner(dir, session, stepsPerFrame, frames);
        const double after = measureBaseline();
        lowest = std::min(lowest, after);
        highest = std::max(highest, after);
        const double baseline = 0.5 * (before + after);
        before = after;
        nlohmann::json row = {
            {"size", n}, {"steps_per_frame", label}, {"baseline_cpu_iterations_per_s", baseline}};
        if (!run.ok) {
            std::printf("%-30s %-6d %12s  failed: %s\n", "", n, label.c_str(), run.error.c_str());
            row["error"] = run.error;
        } else {
            std::printf("%-30s %-6d %12s %10.1f %12.0f %12.3f\n", "", n, label.c_str(), run.fps,
                        run.stepsPerSecond, run.stepsPerSecond / baseline);
            row["frames_per_s"] = run.fps;
            row["steps_per_s"] = run.stepsPerSecond;
            row["over_baseline"] = run.stepsPerSecond / baseline;
            if (run.frameKnown) {
                nlohmann::json parts;
                std::printf("%-30s frame ms:", "");
                for (std::size_t k = 0; k < kFrameParts.size(); ++k) {
                    parts[kFrameParts[k]] = run.frameMs[k];
                    std::printf(" %s %.2f", kFrameParts[k], run.frameMs[k]);
                }
                std::printf("\n");
                row["frame_ms"] = parts;
            }
            if (!automatic) {
                ratios.push_back(run.stepsPerSecond / baseline);
                rates.push_back(run.fps);
                met += run.fps >= 30.0 && ratios.back() >= 0.8 ? 1 : 0;
            }
        }
        std::fflush(stdout);
        rows.push_back(row);
    }
    const auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    std::printf("  baseline: %.0f - %.0f cpu it/s at %dx%d (measured before and after each "
                "run; a row is over the mean of the two around it)\n"
                "  goal: 0.8 of the baseline at 30 frames/s or more: met in %d of %d runs "
                "(medians %.3f of the baseline, %.1f frames/s)\n",
                lowest, highest, n, n, met, int(ratios.size()), median(ratios), median(rates));
    const nlohmann::json goal = {{"runs", int(ratios.size())},
                                 {"runs_meeting_goal", met},
                                 {"median_over_baseline", median(ratios)},
                                 {"median_frames_per_s", median(rates)}};
    std::error_code ec;
    fs::remove_all(dir, ec);
    return {{"runs", rows}, {"goal", goal}};
}

} // namespace morphogen::bench
