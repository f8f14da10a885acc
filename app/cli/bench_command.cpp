// morphogen bench: throughput of the GPU step against a same-format copy pass
// on the same context (the ratio is the figure: it cancels the machine's
// speed), and of the CPU backend, at several grid sizes.

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/backend.hpp"
#include "cli/commands.hpp"
#include "core/cpu_simulator.hpp"
#include "core/errors.hpp"
#include "core/initial_condition.hpp"
#include "core/session.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::cli {

namespace {

struct BenchFlags {
    std::string json;
    std::string sizes = "256,512,1024";
    std::string preset = "gs_coral";
    std::string context;
    double seconds = 1.0;
    bool noCpu = false;
};

using Clock = std::chrono::steady_clock;

// Runs batches of `batch` steps until `seconds` have passed; returns steps/s.
// `finish` must wait for the work to complete (glFinish on the GPU).
template <typename Run, typename Finish>
double measure(Run&& run, Finish&& finish, double seconds, int batch) {
    run(batch); // warm-up: shader compilation, first-touch allocation
    finish();
    int steps = 0;
    const auto start = Clock::now();
    double elapsed = 0;
    do {
        run(batch);
        finish();
        steps += batch;
        elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < seconds);
    return steps / elapsed;
}

std::vector<int> parseSizes(const std::string& text) {
    std::vector<int> sizes;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 8 || v > kMaxGridSide)
            throw InputError("--sizes '" + text + "': '" + item + "' is not a size in 8.." +
                             std::to_string(kMaxGridSide));
        sizes.push_back(int(v));
    }
    if (sizes.empty())
        throw InputError("--sizes is empty");
    return sizes;
}

void bench(const BenchFlags& f) {
    const std::vector<int> sizes = parseSizes(f.sizes);
    if (!(f.seconds > 0))
        throw InputError("--seconds must be positive");
    Session base = loadPreset(f.preset);
    nlohmann::json report;
    report["preset"] = base.name;
    report["model"] = base.model;
    report["seconds_per_measurement"] = f.seconds;

    std::unique_ptr<gl::Context> context;
    try {
        context = gl::createHeadlessContext(parseContextFlag(f.context));
        report["gl_renderer"] = context->renderer();
        report["gl_version"] = context->version();
        report["gl_context"] = gl::toString(context->kind());
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench: no GL context, GPU rows skipped: %s\n", e.what());
        report["gl_error"] = e.what();
    }

    std::printf("%-6s %14s %14s %14s %10s %14s %12s\n", "size", "gpu step it/s", "gpu copy it/s",
                "gpu cells/s", "step/copy", "cpu it/s", "cpu cells/s");
    nlohmann::json rows = nlohmann::json::array();
    for (int n : sizes) {
        Session s = base;
        s.width = s.height = n;
        const double cells = double(n) * n;
        const State initial =
            makeInitialState(s.init, s.reactionModel(), s.params, n, n, s.seed);
        const int batch = std::max(1, int(2e6 / cells));
        nlohmann::json row;
        row["size"] = n;
        double gpuStep = 0, gpuCopy = 0, cpu = 0;
        if (context) {
            std::fprintf(stderr, "bench: %dx%d gpu step...\n", n, n);
            gl::GpuSimulator gpu(s);
            gpu.setState(initial);
            gpuStep = measure([&](int k) { gpu.run(k); }, [] { glFinish(); }, f.seconds, batch);
            std::fprintf(stderr, "bench: %dx%d gpu copy...\n", n, n);
            gl::CopyPass copy(n, n, gl::stateFormat(int(s.reactionModel().chemicals().size())));
            gpuCopy = measure([&](int k) { copy.run(k); }, [] { glFinish(); }, f.seconds, batch);
            row["gpu_step_iterations_per_s"] = gpuStep;
            row["gpu_step_cell_updates_per_s"] = gpuStep * cells;
            row["gpu_copy_iterations_per_s"] = gpuCopy;
            row["gpu_step_over_copy"] = gpuStep / gpuCopy;
        }
        if (!f.noCpu) {
            std::fprintf(stderr, "bench: %dx%d cpu step...\n", n, n);
            CpuSimulator cpuSim(s);
            cpuSim.setState(initial);
            cpu = measure([&](int k) { cpuSim.run(k); }, [] {}, f.seconds, batch);
            row["cpu_iterations_per_s"] = cpu;
            row["cpu_cell_updates_per_s"] = cpu * cells;
            if (context)
                row["gpu_step_over_cpu"] = gpuStep / cpu;
        }
        std::printf("%-6d %14.1f %14.1f %14.3g %10.3f %14.1f %12.3g\n", n, gpuStep, gpuCopy,
                    gpuStep * cells, gpuCopy > 0 ? gpuStep / gpuCopy : 0.0, cpu, cpu * cells);
        std::fflush(stdout);
        rows.push_back(row);
    }
    report["results"] = rows;
    if (!f.json.empty()) {
        std::ofstream out(f.json);
        if (!out)
            throw InputError(f.json + ": cannot write the benchmark JSON");
        out << report.dump(2) << "\n";
    }
}

} // namespace

void addBenchCommand(CLI::App& app) {
    auto flags = std::make_shared<BenchFlags>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Measure step throughput: GPU step vs a same-format copy pass, and the CPU backend");
    cmd->add_option("--json", flags->json, "also write the results as JSON to this file");
    cmd->add_option("--sizes", flags->sizes, "comma-separated grid sizes (default 256,512,1024)");
    cmd->add_option("--preset", flags->preset, "preset whose model is measured (default gs_coral)");
    cmd->add_option("--context", flags->context, "GL context: egl or osmesa");
    cmd->add_option("--seconds", flags->seconds, "time per measurement (default 1)");
    cmd->add_flag("--no-cpu", flags->noCpu, "skip the CPU backend");
    cmd->callback([flags] { bench(*flags); });
}

} // namespace morphogen::cli
