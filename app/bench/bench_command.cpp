// morphogen bench: throughput of the GPU step against a same-format copy pass
// on the same context (the ratio is the figure: it cancels the machine's
// speed), and of the CPU backend, at several grid sizes; then the domain,
// surface, convergence and resolution sections, and the peak memory of renders
// against the state they simulate (bench_memory.hpp).

#include <chrono>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "bench/bench_command.hpp"
#include "bench/bench_copy_pass.hpp"
#include "bench/bench_designer.hpp"
#include "bench/bench_domains.hpp"
#include "bench/bench_memory.hpp"
#include "bench/bench_models.hpp"
#include "bench/bench_resolution.hpp"
#include "bench/bench_surface.hpp"
#include "bench/bench_timing.hpp"
#include "cli/commands.hpp"
#include "core/analysis/pattern_stats.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "gl/backend.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::bench {

namespace {

struct BenchFlags {
    std::string json;
    std::string sizes = "256,512,1024";
    std::string preset = "gs_coral";
    std::string context;
    std::string gpuDevice;
    double seconds = 1.0;
    bool noCpu = false;
    bool noGpu = false;
    std::string operatorSizes = "512,1024";
    int convergenceSize = 1024;
    bool noConvergence = false;
    bool noDomains = false;
    bool noSurface = false;
    std::string memorySizes = "1024,2048,4096";
    bool noMemory = false;
    bool noResolution = false;
    bool noThroughput = false;
    bool noDesigner = false;
    int designerSize = 512;
    ResolutionBenchFlags resolution;
};

using Clock = std::chrono::steady_clock;

// McGraw's Table 2 set (e), measured beside operatorVariants' set (c): ranks 2
// and 4 only, so its 5x5 kernel is centrally symmetric and the CPU sums it
// folded (cpu_kernels.hpp), which set (c)'s, with rank-3 terms, is not.
std::pair<std::string, Session> evenKernelVariant(const Session& base) {
    Session even = base;
    even.diffusion.type = DiffusionType::Generalized;
    for (const ChemicalSpec& c : base.reactionModel().chemicals())
        even.diffusion.generalized[c.name] = "e";
    return {"5x5 even set (e)", even};
}

// The diffusion operators of issue-level interest, on the same model and grid.
std::vector<std::pair<std::string, Session>> operatorVariants(const Session& base) {
    std::vector<std::pair<std::string, Session>> variants;
    variants.emplace_back("5-point", base);
    Session anisotropic = base;
    anisotropic.diffusion.type = DiffusionType::Anisotropic;
    for (const ChemicalSpec& c : base.reactionModel().chemicals())
        anisotropic.diffusion.anisotropic[c.name] = {30.0f, 1.2f, 0.8f};
    variants.emplace_back("anisotropic 3x3", anisotropic);
    Session generalized = base;
    generalized.diffusion.type = DiffusionType::Generalized;
    for (const ChemicalSpec& c : base.reactionModel().chemicals())
        generalized.diffusion.generalized[c.name] = "c";
    variants.emplace_back("generalized 5x5", generalized);
    // Set (e) beside (c): even-order, so the CPU folds it into pair sums.
    variants.push_back(evenKernelVariant(base));
    return variants;
}

struct Convergence {
    double seconds = 0;
    int steps = 0;
    int features = 0;
    bool converged = false;
};

// Whether the last three feature counts changed by at most 1% each.
bool settled(const std::vector<int>& counts) {
    const std::size_t n = counts.size();
    if (n < 4 || counts[n - 1] <= 0)
        return false;
    for (std::size_t k = n - 3; k < n; ++k)
        if (std::abs(counts[k] - counts[k - 1]) > 0.01 * counts[k])
            return false;
    return true;
}

// Runs until the feature (spot) count stops changing: within 1% over three
// checks spaced `checkTime` simulated time units apart. Coarse levels of a
// schedule run to convergence too (at most maxSteps each, in whole checks),
// then hand over to the next size: a SessionRun whose levels end early.
Convergence timeToConverge(const Session& session, const SimulatorFactory& make, double checkTime,
                           int maxSteps) {
    const int chunk = std::max(1, int(std::lround(checkTime / session.dt)));
    const int levelSteps = (maxSteps + chunk - 1) / chunk * chunk;
    Session s = session;
    if (s.schedule.empty()) {
        s.steps = levelSteps;
    } else {
        std::vector<ScheduleLevel> levels = s.schedule;
        for (ScheduleLevel& level : levels)
            level.steps = levelSteps;
        applySchedule(s, std::move(levels));
    }
    const int chemical = s.reactionModel().displayChemical();
    Convergence result;
    const auto start = Clock::now();
    // Blow-up is only checked at level ends: each count reads the state back already.
    SessionRun run(s, make, 0);
    std::vector<int> counts;
    while (!run.finished()) {
        const RunPosition at = run.position();
        const bool lastLevel = at.segment + 1 == at.segments;
        run.advance(chunk);
        if (!lastLevel && run.position().segment != at.segment) {
            counts.clear(); // the level ran all its steps without settling
            continue;
        }
        counts.push_back(featureCount(run.state(), chemical));
        result.converged = settled(counts);
        if (result.converged && !lastLevel) {
            run.endSegment();
            counts.clear();
        } else if (result.converged) {
            break;
        }
    }
    result.steps = run.position().stepsDone;
    result.features = counts.empty() ? 0 : counts.back();
    result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return result;
}

// A comma-separated list of sizes given to `flag`.
std::vector<int> parseSizes(const std::string& flag, const std::string& text) {
    std::vector<int> sizes;
    // Every item between commas counts, the empty ones too: "16," is refused
    // rather than read as "16" (getline drops a trailing empty item).
    std::vector<std::string> items;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        items.push_back(
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos)
            break;
        start = comma + 1;
    }
    if (text.empty())
        items.clear();
    for (const std::string& item : items) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 8 || v > kMaxGridSide)
            throw InputError(flag + " '" + text + "': '" + item + "' is not a size in 8.." +
                             std::to_string(kMaxGridSide));
        sizes.push_back(int(v));
    }
    if (sizes.empty())
        throw InputError(flag + " is empty");
    return sizes;
}

void checkFlags(const BenchFlags& f) {
    parseSizes("--sizes", f.sizes);
    parseSizes("--operator-sizes", f.operatorSizes); // refused before any row runs
    parseSizes("--memory-sizes", f.memorySizes);
    if (!(f.seconds > 0 && f.seconds <= kMaxBenchSeconds)) {
        std::ostringstream os;
        os << "--seconds " << f.seconds << ": accepted are numbers in (0, " << kMaxBenchSeconds
           << "] (seconds per measurement)";
        throw InputError(os.str());
    }
    if (f.convergenceSize < 32 || f.convergenceSize > kMaxGridSide || f.convergenceSize % 2 != 0)
        throw InputError("--convergence-size " + std::to_string(f.convergenceSize) +
                         ": accepted are even sizes in 32.." + std::to_string(kMaxGridSide));
    if (!f.noResolution)
        checkResolutionFlags(f.resolution);
}

// The headless context of the GPU rows, described in the report; null (GPU
// rows skipped) when there is none.
std::unique_ptr<gl::Context> openContext(const BenchFlags& f, nlohmann::json& report) {
    std::unique_ptr<gl::Context> context;
    try {
        context = gl::createHeadlessContext(gl::parseContextFlag(f.context),
                                            gl::parseGpuDeviceFlag(f.gpuDevice));
        report["gl_renderer"] = context->renderer();
        report["gl_version"] = context->version();
        report["gl_context"] = gl::toString(context->kind());
        report["gl_display"] = context->description();
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench: no GL context, GPU rows skipped: %s\n", e.what());
        report["gl_error"] = e.what();
    }
    return context;
}

// Step throughput per size: the GPU step against its copy pass, and the CPU.
nlohmann::json throughputRows(const Session& base, const BenchFlags& f, bool gpuRows) {
    std::printf("%-6s %14s %14s %14s %10s %14s %12s\n", "size", "gpu step it/s", "gpu copy it/s",
                "gpu cells/s", "step/copy", "cpu it/s", "cpu cells/s");
    nlohmann::json rows = nlohmann::json::array();
    for (int n : parseSizes("--sizes", f.sizes)) {
        Session s = base;
        s.width = s.height = n;
        const double cells = double(n) * n;
        const State initial = makeInitialState(s.init, s.reactionModel(), s.params, n, n, s.seed);
        const int batch = std::max(1, int(2e6 / cells));
        nlohmann::json row;
        row["size"] = n;
        double gpuStep = 0, gpuCopy = 0, cpu = 0;
        if (gpuRows) {
            std::fprintf(stderr, "bench: %dx%d gpu step...\n", n, n);
            gl::GpuSimulator gpu(s);
            gpu.setState(initial);
            gpuStep = measureStepsPerSecond([&](int k) { gpu.run(k); }, [] { glFinish(); },
                                            f.seconds, batch);
            std::fprintf(stderr, "bench: %dx%d gpu copy...\n", n, n);
            CopyPass copy(n, n, int(s.reactionModel().chemicals().size()));
            gpuCopy = measureStepsPerSecond([&](int k) { copy.run(k); }, [] { glFinish(); },
                                            f.seconds, batch);
            row["gpu_step_iterations_per_s"] = gpuStep;
            row["gpu_step_cell_updates_per_s"] = gpuStep * cells;
            row["gpu_copy_iterations_per_s"] = gpuCopy;
            row["gpu_step_over_copy"] = gpuStep / gpuCopy;
        }
        if (!f.noCpu) {
            std::fprintf(stderr, "bench: %dx%d cpu step...\n", n, n);
            CpuSimulator cpuSim(s);
            cpuSim.setState(initial);
            cpu = measureStepsPerSecond([&](int k) { cpuSim.run(k); }, [] {}, f.seconds, batch);
            row["cpu_iterations_per_s"] = cpu;
            row["cpu_cell_updates_per_s"] = cpu * cells;
            if (gpuRows)
                row["gpu_step_over_cpu"] = gpuStep / cpu;
        }
        std::printf("%-6d %14.1f %14.1f %14.3g %10.3f %14.1f %12.3g\n", n, gpuStep, gpuCopy,
                    gpuStep * cells, gpuCopy > 0 ? gpuStep / gpuCopy : 0.0, cpu, cpu * cells);
        std::fflush(stdout);
        rows.push_back(row);
    }
    return rows;
}

// Operators: the 3x3 and 5x5 passes beside the 5-point one (McGraw's GPU ran
// the 5x5 pass at 0.33 of the isotropic rate at 512^2).
nlohmann::json operatorRows(const Session& base, const BenchFlags& f, bool gpuRows) {
    std::printf("\n%-16s %-6s %14s %10s %14s %10s\n", "operator", "size", "gpu it/s", "vs 5-point",
                "cpu it/s", "vs 5-point");
    nlohmann::json rows = nlohmann::json::array();
    for (int n : parseSizes("--operator-sizes", f.operatorSizes)) {
        double gpuBase = 0, cpuBase = 0;
        for (auto& [name, variant] : operatorVariants(base)) {
            Session s = variant;
            s.width = s.height = n;
            const State initial =
                makeInitialState(s.init, s.reactionModel(), s.params, n, n, s.seed);
            const int batch = std::max(1, int(2e6 / (double(n) * n)));
            nlohmann::json row;
            row["operator"] = name;
            row["size"] = n;
            double gpu = 0, cpu = 0;
            if (gpuRows) {
                std::fprintf(stderr, "bench: %dx%d gpu %s...\n", n, n, name.c_str());
                gl::GpuSimulator sim(s);
                sim.setState(initial);
                gpu = measureStepsPerSecond([&](int k) { sim.run(k); }, [] { glFinish(); },
                                            f.seconds, batch);
                gpuBase = gpuBase > 0 ? gpuBase : gpu;
                row["gpu_iterations_per_s"] = gpu;
                row["gpu_over_5_point"] = gpu / gpuBase;
            }
            if (!f.noCpu) {
                std::fprintf(stderr, "bench: %dx%d cpu %s...\n", n, n, name.c_str());
                CpuSimulator sim(s);
                sim.setState(initial);
                cpu = measureStepsPerSecond([&](int k) { sim.run(k); }, [] {}, f.seconds, batch);
                cpuBase = cpuBase > 0 ? cpuBase : cpu;
                row["cpu_iterations_per_s"] = cpu;
                row["cpu_over_5_point"] = cpu / cpuBase;
            }
            std::printf("%-16s %-6d %14.1f %10.3f %14.1f %10.3f\n", name.c_str(), n, gpu,
                        gpuBase > 0 ? gpu / gpuBase : 0.0, cpu, cpuBase > 0 ? cpu / cpuBase : 0.0);
            std::fflush(stdout);
            rows.push_back(row);
        }
    }
    return rows;
}

// Time to a converged pattern: flat explicit, semi-implicit at 5x the
// explicit dt, coarse-to-fine n/2 -> n (the large spots' ~14-cell wavelength
// is still resolved at n/2, not at n/4); on the backend `auto` picks (the
// faster one on this machine).
nlohmann::json convergenceRows(const BenchFlags& f) {
    const int n = f.convergenceSize;
    Session flat = loadPreset("turk_large_spots");
    flat.width = flat.height = n;
    // One unit per cell, as these rows measured before sessions had a length:
    // the methods compared on the same cells, not the automatic plan (whose
    // refinement the resolution section measures).
    flat.length = n;
    gl::Backend backend = gl::makeBackend(gl::BackendChoice::Auto, gl::parseContextFlag(f.context),
                                          gl::parseGpuDeviceFlag(f.gpuDevice));
    std::fprintf(stderr, "bench: convergence on the %s\n", backend.reason.c_str());
    Session semi = flat;
    semi.integrator = Integrator::SemiImplicit;
    semi.dt = 5 * flat.dt;
    Session coarse = flat;
    coarse.schedule = {{n / 2, n / 2, 0}, {n, n, 0}};
    const double checkTime = 20.0; // simulated time between feature counts
    std::printf("\n%-26s %10s %8s %10s %10s\n", "time to converged pattern", "seconds", "steps",
                "features", "vs flat");
    nlohmann::json rows = nlohmann::json::array();
    double flatSeconds = 0;
    for (auto& [name, s] : std::vector<std::pair<std::string, Session>>{
             {"flat explicit", flat}, {"semi-implicit 5x dt", semi}, {"coarse-to-fine", coarse}}) {
        std::fprintf(stderr, "bench: %dx%d %s until the spot count settles...\n", n, n,
                     name.c_str());
        const Convergence c = timeToConverge(s, backend.makeSimulator, checkTime, 40000);
        flatSeconds = flatSeconds > 0 ? flatSeconds : c.seconds;
        std::printf("%-26s %10.2f %8d %10d %10.3f%s\n", name.c_str(), c.seconds, c.steps,
                    c.features, c.seconds / flatSeconds, c.converged ? "" : " (not converged)");
        std::fflush(stdout);
        rows.push_back({{"method", name},
                        {"seconds", c.seconds},
                        {"steps", c.steps},
                        {"features", c.features},
                        {"converged", c.converged},
                        {"time_over_flat", c.seconds / flatSeconds}});
    }
    return {{"preset", flat.name}, {"size", n}, {"backend", backend.reason}, {"rows", rows}};
}

void writeJson(const std::string& path, const nlohmann::json& report) {
    writeTextAtomically(path, report.dump(2) + "\n");
}

void bench(const BenchFlags& f) {
    checkFlags(f);
    if (!f.json.empty())
        checkWritable(f.json); // before minutes of benchmarking, not after
    const Session base = loadPreset(f.preset);
    nlohmann::json report;
    report["preset"] = base.name;
    report["model"] = base.model;
    report["seconds_per_measurement"] = f.seconds;
    // The throughput and domain rows measure the GPU on this context; the
    // later sections pick their own backend.
    std::unique_ptr<gl::Context> context;
    if (!f.noGpu && (!f.noThroughput || !f.noDomains || !f.noSurface))
        context = openContext(f, report);
    const bool gpuRows = context != nullptr;

    if (!f.noThroughput) {
        report["results"] = throughputRows(base, f, gpuRows);
        report["operators"] = operatorRows(base, f, gpuRows);
        report["models"] =
            benchModels(parseSizes("--sizes", f.sizes), gpuRows, !f.noCpu, f.seconds);
    }
    if (!f.noDomains)
        report["domains"] = benchDomains(gpuRows, !f.noCpu, f.seconds);
    if (!f.noSurface)
        report["surface"] = benchSurface(gpuRows, !f.noCpu, f.seconds);
    if (!f.noConvergence)
        report["convergence"] = convergenceRows(f);
    if (!f.noMemory) {
        MemoryBench memory{
            parseSizes("--memory-sizes", f.memorySizes), f.preset, {}, f.context, f.gpuDevice};
        if (!f.noCpu)
            memory.backends.push_back("cpu");
        if (gpuRows)
            memory.backends.push_back("gpu");
        report["memory"] = benchMemory(memory);
    }
    if (!f.noResolution)
        report["resolution"] = benchResolution(f.resolution, f.context, f.gpuDevice);
    if (!f.noDesigner && !f.noCpu)
        report["designer"] = benchDesigner({f.preset, f.designerSize, f.seconds});
    if (!f.json.empty())
        writeJson(f.json, report);
}

} // namespace

void addBenchCommand(CLI::App& app) {
    auto flags = std::make_shared<BenchFlags>();
    CLI::App* cmd = app.add_subcommand(
        "bench",
        "Measure step throughput (GPU step vs a same-format copy pass, and the CPU backend), "
        "time to a converged pattern, presets rendered at several sizes, and the peak memory "
        "of renders");
    cmd->add_option("--json", flags->json, "also write the results as JSON to this file");
    cmd->add_option("--sizes", flags->sizes, "comma-separated grid sizes (default 256,512,1024)");
    cmd->add_option("--preset", flags->preset, "preset whose model is measured (default gs_coral)");
    cmd->add_option("--context", flags->context, "GL context: egl or osmesa");
    cmd->add_option(
        "--gpu-device", flags->gpuDevice,
        "EGL display number (default: $MORPHOGEN_GPU_DEVICE, else the first hardware renderer)");
    cmd->add_option("--seconds", flags->seconds,
                    "time per measurement, up to " + std::to_string(int(kMaxBenchSeconds)) +
                        " (default 1)");
    cmd->add_flag("--no-cpu", flags->noCpu, "skip the CPU backend");
    cmd->add_flag("--no-gpu", flags->noGpu,
                  "skip the GPU rows of the throughput and domain sections (a software renderer)");
    cmd->add_flag("--no-throughput", flags->noThroughput,
                  "skip the step-throughput and operator rows");
    cmd->add_option("--operator-sizes", flags->operatorSizes,
                    "sizes for the 5-point / 3x3 / 5x5 operator comparison (default 512,1024)");
    cmd->add_option("--convergence-size", flags->convergenceSize,
                    "grid size for time-to-converged-pattern (default 1024)");
    cmd->add_flag("--no-convergence", flags->noConvergence, "skip time-to-converged-pattern");
    cmd->add_flag("--no-domains", flags->noDomains,
                  "skip the atlas, localized-RD (plane and mesh) and batched-sweep rows");
    cmd->add_flag("--no-surface", flags->noSurface,
                  "skip the surface rows (mesh to atlas for an 82k-triangle model, throughput "
                  "on the holes model's atlas against a flat grid, a session step's cost on three "
                  "models with both integrators against a flat grid)");
    cmd->add_option("--memory-sizes", flags->memorySizes,
                    "sizes of the peak-memory renders, one process each (default 1024,2048,4096)");
    cmd->add_flag("--no-memory", flags->noMemory, "skip the peak-memory rows");
    cmd->add_flag("--no-designer", flags->noDesigner,
                  "skip the designer rows (morphogen design under the display, needs $DISPLAY: "
                  "xvfb-run)");
    cmd->add_option("--designer-size", flags->designerSize,
                    "grid size of the designer rows (default 512)")
        ->check(CLI::Range(16, 4096));
    cmd->add_flag("--no-resolution", flags->noResolution,
                  "skip the same-look-at-any-size rows (presets rendered until settled at "
                  "--resolution-sizes)");
    cmd->add_option("--resolution-sizes", flags->resolution.sizes,
                    "sizes the presets are rendered at, each a multiple of the smallest "
                    "(default 256,512,1024,2048)");
    cmd->add_option("--resolution-presets", flags->resolution.presets,
                    "presets rendered at every resolution size (default "
                    "turk_large_spots,wk_zebra,turk_leopard: spots, stripes, a cascade)");
    cmd->add_option("--resolution-compare-size", flags->resolution.compareSize,
                    "size at which the first resolution preset, refined coarse-to-fine, is "
                    "compared with every step at that size (default 512; 0 skips it)");
    cmd->callback([flags] { bench(*flags); });
}

} // namespace morphogen::bench
