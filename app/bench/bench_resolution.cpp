#include "bench/bench_resolution.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/progress.hpp"
#include "cli/render_output.hpp"
#include "cli/settle_flags.hpp"
#include "core/analysis/pattern_stats.hpp"
#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/segments.hpp"
#include "gl/backend.hpp"

namespace morphogen::bench {

namespace {

using Clock = std::chrono::steady_clock;

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ','))
        items.push_back(item);
    return items;
}

// Ascending; each a multiple of the smallest, so a result area-averages
// down to the smallest size in whole blocks.
std::vector<int> parseResolutionSizes(const std::string& text) {
    std::vector<int> sizes;
    for (const std::string& item : splitList(text)) {
        char* end = nullptr;
        const long v = std::strtol(item.c_str(), &end, 10);
        if (item.empty() || *end != '\0' || v < 16 || v > kMaxGridSide)
            throw InputError("--resolution-sizes '" + text + "': '" + item +
                             "' is not a size in 16.." + std::to_string(kMaxGridSide));
        sizes.push_back(int(v));
    }
    if (sizes.empty())
        throw InputError("--resolution-sizes is empty");
    std::sort(sizes.begin(), sizes.end());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    for (int n : sizes)
        if (n % sizes.front() != 0)
            throw InputError("--resolution-sizes '" + text + "': " + std::to_string(n) +
                             " is not a multiple of the smallest size, " +
                             std::to_string(sizes.front()) +
                             " (each result is area-averaged down to it)");
    return sizes;
}

std::vector<Session> parsePresets(const std::string& text) {
    std::vector<Session> presets;
    for (const std::string& name : splitList(text)) {
        if (name.empty())
            throw InputError("--resolution-presets '" + text + "': an empty name");
        presets.push_back(loadPreset(name)); // InputError for an unknown name
    }
    if (presets.empty())
        throw InputError("--resolution-presets is empty");
    return presets;
}

struct Rendered {
    double seconds = 0;
    int steps = 0;
    bool settled = false;
    double cellSize = 1;
    std::string plan;
    int chemical = 0;
    State state;
    double wavelengthCells = 0;
    int features = 0;

    double wavelengthUnits() const { return wavelengthCells * cellSize; }
};

// `session` at its size as `render --preset` runs it: until settled (the
// preset default, no --steps), its stability check, the automatic plan.
Rendered renderAsRender(Session session, const gl::Backend& backend) {
    cli::SettleRun settle(cli::SettleFlags{}, session, true, false);
    cli::checkStability(session, false);
    Rendered r;
    r.cellSize = session.cellSize();
    r.plan = describePlan(session);
    r.chemical = colormapChemical(session.colormap, session.outputModel());
    cli::Progress progress(session.name, 1); // carries the settle note; never drawn here
    RunOptions options;
    options.chunk = cli::runChunk(session);
    settle.attach(options, progress);
    const auto start = Clock::now();
    RunResult result = runSession(session, backend.makeSimulator, options);
    r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    r.steps = result.stepsDone;
    r.settled = result.settled;
    r.state = std::move(result.state);
    r.wavelengthCells = spectrumStats(r.state, r.chemical).dominantWavelength;
    r.features = featureCount(r.state, r.chemical, session.edges == EdgeMode::Periodic);
    return r;
}

// The chemical's plane averaged over factor x factor blocks.
std::vector<double> boxDown(const State& state, int chemical, int factor) {
    const int w = state.width() / factor, h = state.height() / factor;
    const float* p = state.plane(chemical);
    std::vector<double> out(std::size_t(w) * h, 0.0);
    for (int y = 0; y < state.height(); ++y)
        for (int x = 0; x < state.width(); ++x)
            out[std::size_t(y / factor) * w + x / factor] += p[std::size_t(y) * state.width() + x];
    for (double& v : out)
        v /= double(factor) * factor;
    return out;
}

// NaN when either side is constant.
double pearson(const std::vector<double>& a, const std::vector<double>& b) {
    const double n = double(a.size());
    double ma = 0, mb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        ma += a[i];
        mb += b[i];
    }
    ma /= n;
    mb /= n;
    double sab = 0, saa = 0, sbb = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        sab += (a[i] - ma) * (b[i] - mb);
        saa += (a[i] - ma) * (a[i] - ma);
        sbb += (b[i] - mb) * (b[i] - mb);
    }
    return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : std::nan("");
}

// max / min - 1 over positive values; NaN when one is not positive.
double spread(const std::vector<double>& values) {
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    return *lo > 0 ? *hi / *lo - 1.0 : std::nan("");
}

const char* yesNo(bool b) {
    return b ? "yes" : "no";
}

std::string percentText(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, std::isfinite(fraction) ? "%.1f%%" : "n/a", 100.0 * fraction);
    return text;
}

nlohmann::json rowJson(const Rendered& r, int size) {
    return {{"size", size},
            {"cell_size", r.cellSize},
            {"plan", r.plan},
            {"seconds", r.seconds},
            {"steps", r.steps},
            {"settled", r.settled},
            {"wavelength_cells", r.wavelengthCells},
            {"wavelength_units", r.wavelengthUnits()},
            {"features", r.features}};
}

constexpr double kGoalSpread = 0.05; // the issue: within 5% across sizes

nlohmann::json presetRows(const Session& preset, const std::vector<int>& sizes,
                          const gl::Backend& backend, std::vector<Rendered>& rendered) {
    nlohmann::json rows = nlohmann::json::array();
    std::vector<double> wavelengths, features;
    const int smallest = sizes.front();
    for (int n : sizes) {
        Session s = preset;
        resizeSession(s, n, n);
        std::fprintf(stderr, "bench: resolution %s at %dx%d until settled...\n",
                     preset.name.c_str(), n, n);
        Rendered r = renderAsRender(s, backend);
        const double correlation =
            pearson(boxDown(r.state, r.chemical, n / smallest),
                    boxDown(rendered.empty() ? r.state : rendered.front().state,
                            rendered.empty() ? r.chemical : rendered.front().chemical, 1));
        std::printf("%-18s %6d %10.4g %9.2f %8d %8s %11.2f %9d %10.3f\n", preset.name.c_str(), n,
                    r.cellSize, r.seconds, r.steps, yesNo(r.settled), r.wavelengthUnits(),
                    r.features, correlation);
        std::fflush(stdout);
        nlohmann::json row = rowJson(r, n);
        row["correlation_with_smallest"] = correlation;
        rows.push_back(row);
        wavelengths.push_back(r.wavelengthUnits());
        features.push_back(r.features);
        rendered.push_back(std::move(r));
    }

    // Time to the largest size over the time at 512 (the figure), or
    // at the smallest size when 512 is not measured.
    const int largest = sizes.back();
    const auto at512 = std::find(sizes.begin(), sizes.end(), 512);
    const std::size_t ref =
        at512 != sizes.end() && largest > 512 ? std::size_t(at512 - sizes.begin()) : 0;
    const double ratio = rendered.back().seconds / rendered[ref].seconds;
    const double cells = double(largest) / sizes[ref] * largest / sizes[ref];
    const double wavelengthSpread = spread(wavelengths), featureSpread = spread(features);
    // Reported apart: a stripe pattern's segment count moves as walls join
    // where a finer grid resolves a thin neck, while its wavelength holds.
    const bool wavelengthWithin = wavelengthSpread <= kGoalSpread;
    const bool featuresWithin = featureSpread <= kGoalSpread;
    std::printf("%-18s spread over sizes: wavelength %s, features %s (goal within 5%%: %s, %s); "
                "time %d/%d %.2fx (cells %.0fx; naive explicit %.0fx; goal at most %.0fx: %s)\n",
                "", percentText(wavelengthSpread).c_str(), percentText(featureSpread).c_str(),
                yesNo(wavelengthWithin), yesNo(featuresWithin), largest, sizes[ref], ratio, cells,
                cells * cells, cells, yesNo(ratio <= cells));
    std::fflush(stdout);
    return {{"preset", preset.name},
            {"description", preset.description},
            {"length", preset.length},
            {"rows", rows},
            {"wavelength_spread", wavelengthSpread},
            {"feature_spread", featureSpread},
            {"wavelength_within_5_percent", wavelengthWithin},
            {"features_within_5_percent", featuresWithin},
            {"time_ratio",
             {{"size", largest},
              {"reference_size", sizes[ref]},
              {"seconds_ratio", ratio},
              {"cells_ratio", cells},
              {"naive_explicit_ratio", cells * cells},
              {"at_most_cells_ratio", ratio <= cells}}}};
}

// One preset at one size, refined (the automatic plan) against every step at
// that size (coarseToFine off: substeps of dt on the full grid).
nlohmann::json comparisonRow(const Session& preset, int size, const Rendered* refinedRow,
                             const gl::Backend& backend) {
    Session s = preset;
    resizeSession(s, size, size);
    Rendered refined;
    if (refinedRow) {
        refined = *refinedRow;
    } else {
        std::fprintf(stderr, "bench: resolution %s at %dx%d refined...\n", preset.name.c_str(),
                     size, size);
        refined = renderAsRender(s, backend);
    }
    const bool refines = !planResolution(s).refine.empty();
    s.coarseToFine = false;
    std::fprintf(stderr, "bench: resolution %s at %dx%d, every step at full size...\n",
                 preset.name.c_str(), size, size);
    const Rendered direct = renderAsRender(s, backend);
    const double correlation = pearson(boxDown(refined.state, refined.chemical, 1),
                                       boxDown(direct.state, direct.chemical, 1));
    // Both grow from the same start noise, a field in model units, so the
    // layouts agree as far as the discretisation lets them; growth from noise
    // amplifies small differences, so a low figure means the features were
    // placed differently, not that the pattern is wrong.
    const std::string note =
        !refines ? "the plan does not refine at this size: both run every step at full size"
        : correlation >= 0.5
            ? "both grow from the same start noise (a field in model units): the refined "
              "layout largely matches the full-resolution one"
            : "the layouts differ: growth from noise amplifies the coarse base's "
              "discretisation, which placed the features differently; compare wavelength "
              "and feature count";
    std::printf("\n%-34s %9s %8s %11s %9s\n",
                ("refined vs direct, " + preset.name + " " + std::to_string(size)).c_str(),
                "seconds", "steps", "wavelength", "features");
    std::printf("%-34s %9.2f %8d %11.2f %9d\n", "refined (coarse-to-fine)", refined.seconds,
                refined.steps, refined.wavelengthUnits(), refined.features);
    std::printf("%-34s %9.2f %8d %11.2f %9d\n", "direct (every step at full size)", direct.seconds,
                direct.steps, direct.wavelengthUnits(), direct.features);
    std::printf("correlation %.3f (%s)\n", correlation, note.c_str());
    std::fflush(stdout);
    return {{"preset", preset.name},
            {"size", size},
            {"plan_refines", refines},
            {"refined", rowJson(refined, size)},
            {"direct", rowJson(direct, size)},
            {"direct_over_refined_seconds", direct.seconds / refined.seconds},
            {"correlation", correlation},
            {"note", note}};
}

} // namespace

void checkResolutionFlags(const ResolutionBenchFlags& flags) {
    parseResolutionSizes(flags.sizes);
    parsePresets(flags.presets);
    if (flags.compareSize != 0 && (flags.compareSize < 16 || flags.compareSize > kMaxGridSide))
        throw InputError("--resolution-compare-size " + std::to_string(flags.compareSize) +
                         ": accepted are 0 (no comparison) or sizes in 16.." +
                         std::to_string(kMaxGridSide));
}

nlohmann::json benchResolution(const ResolutionBenchFlags& flags, const std::string& context,
                               const std::string& gpuDevice) {
    const std::vector<int> sizes = parseResolutionSizes(flags.sizes);
    const std::vector<Session> presets = parsePresets(flags.presets);
    gl::Backend backend = gl::makeBackend(gl::BackendChoice::Auto, gl::parseContextFlag(context),
                                          gl::parseGpuDeviceFlag(gpuDevice));
    std::fprintf(stderr, "bench: resolution on the %s\n", backend.reason.c_str());
    const auto start = Clock::now();
    std::printf("\n%-18s %6s %10s %9s %8s %8s %11s %9s %10s\n", "resolution", "size", "units/cell",
                "seconds", "steps", "settled", "wavelength", "features",
                ("corr " + std::to_string(sizes.front())).c_str());
    nlohmann::json rows = nlohmann::json::array();
    std::vector<Rendered> first; // the first preset's results, for the comparison
    for (std::size_t i = 0; i < presets.size(); ++i) {
        std::vector<Rendered> rendered;
        rows.push_back(presetRows(presets[i], sizes, backend, rendered));
        if (i == 0)
            first = std::move(rendered);
        else
            rendered.clear(); // states of large sizes are large
    }
    nlohmann::json report = {{"backend", backend.reason},
                             {"sizes", sizes},
                             {"wavelength", "dominantWavelength (spectrum peak) x cell size, in "
                                            "model units; quantised to length / whole cycles"},
                             {"steps", "steps run, each of its own level's dt: a substep "
                                       "counts as one"},
                             {"presets", rows}};
    if (flags.compareSize > 0) {
        const auto at = std::find(sizes.begin(), sizes.end(), flags.compareSize);
        const Rendered* refined =
            at != sizes.end() ? &first[std::size_t(at - sizes.begin())] : nullptr;
        report["comparison"] = comparisonRow(presets.front(), flags.compareSize, refined, backend);
    }
    report["seconds"] = std::chrono::duration<double>(Clock::now() - start).count();
    std::printf("resolution section: %.1f s\n", report["seconds"].get<double>());
    std::fflush(stdout);
    return report;
}

} // namespace morphogen::bench
