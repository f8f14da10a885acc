// morphogen sweep: a grid of independent simulations, one per pair of
// parameter values, with a labelled contact sheet and per-tile pattern stats.
// On either backend the whole grid is one simulation on a tiled grid domain
// (side-by-side tiles, each periodic on its own): one draw (GPU) or one pass
// over all tiles (CPU) per step advances every tile.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/exploration.hpp"
#include "cli/flag_values.hpp"
#include "cli/plot_frame.hpp"
#include "cli/progress.hpp"
#include "cli/render_output.hpp"
#include "core/analysis/pattern_classifier.hpp"
#include "core/analysis/result_checks.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/output/colormap.hpp"
#include "core/sim/sweep.hpp"
#include "gl/backend.hpp"

namespace morphogen::cli {

namespace {

using Clock = std::chrono::steady_clock;

struct SweepFlags {
    std::string model;
    std::string preset;
    std::string x, y;
    std::string grid;
    std::string out;
    int tile = 128;
    std::string steps; // checked by flag_values.hpp
    std::string seed;
    std::string backend = "auto";
    std::string context;
    std::string gpuDevice;
    bool compare = false;
    std::string start = "noise";
    std::string pick;
    std::string pickOut;
    int pickSize = 256;
};

void parseGrid(const std::string& text, int& columns, int& rows) {
    std::smatch m;
    if (!std::regex_match(text, m, std::regex("([0-9]{1,4})x([0-9]{1,4})")))
        throw InputError("--grid '" + text + "': expected COLUMNSxROWS, e.g. 16x16");
    columns = std::stoi(m[1]);
    rows = std::stoi(m[2]);
    if (columns < 1 || rows < 1)
        throw InputError("--grid '" + text + "': needs at least one column and one row");
    // Every tile is a simulation, a picture on the sheet and a row of stats.
    if (static_cast<long long>(columns) * rows > kMaxSweepTiles)
        throw InputError("--grid '" + text + "': " + std::to_string(columns * rows) +
                         " tiles; accepted are up to " + std::to_string(kMaxSweepTiles) +
                         " (e.g. 64x64)");
}

std::string formatValue(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

struct TileResult {
    int column = 0, row = 0;
    float x = 0, y = 0;
    bool finite = true; // no NaN or infinite value in any chemical
    PatternStats stats;
    PatternClass cls = PatternClass::Uniform;
};

bool finiteState(const State& state) {
    for (int c = 0; c < state.channels(); ++c)
        if (planeRange(state.plane(c), state.cellCount()).nonFinite > 0)
            return false;
    return true;
}

// A tile that went NaN or infinite: red diagonal hatching, which no colour
// map draws, instead of the colours its NaNs would map to (a flat tile that
// would read as "uniform").
void hatch(std::vector<float>& rgb, int side) {
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const bool line = (x + y) % 8 < 3;
            float* p = &rgb[(std::size_t(y) * std::size_t(side) + std::size_t(x)) * 3];
            p[0] = line ? 0.85f : 1.0f;
            p[1] = p[2] = line ? 0.1f : 1.0f;
        }
}

// Colour-mapped tiles with a gap, a value label under every column and left
// of every row (thinned out where they would overlap), the parameter names
// and a title.
void writeSheet(const std::string& path, const SweepSpec& spec, const std::vector<State>& tiles,
                int steps) {
    const ReactionModel& model = spec.base.reactionModel();
    const int chemical = colormapChemical(spec.base.colormap, model);
    // Small tiles are enlarged so that the sheet stays readable.
    const int zoom = std::max(1, (48 + spec.tile - 1) / spec.tile);
    const int side = spec.tile * zoom, gap = 2, pitch = side + gap;
    const int plotW = spec.columns * pitch - gap, plotH = spec.rows * pitch - gap;
    const std::string title = model.name() + ": " + spec.x.param + " (columns) vs " + spec.y.param +
                              " (rows), " + std::to_string(steps) + " steps, " +
                              std::to_string(spec.tile) + " cells per tile";
    PlotAxis xAxis{spec.x.param, {}}, yAxis{spec.y.param, {}};
    for (int column = 0; column < spec.columns; ++column)
        xAxis.ticks.emplace_back(column * pitch + side / 2,
                                 formatValue(sweepValue(spec.x, column, spec.columns)));
    for (int row = 0; row < spec.rows; ++row)
        yAxis.ticks.emplace_back((spec.rows - 1 - row) * pitch + side / 2,
                                 formatValue(sweepValue(spec.y, row, spec.rows)));
    PlotFrame plot = drawPlotFrame(plotW, plotH, xAxis, yAxis, title);
    for (int row = 0; row < spec.rows; ++row)
        for (int column = 0; column < spec.columns; ++column) {
            const State& tile = tiles[std::size_t(row * spec.columns + column)];
            std::vector<float> big(std::size_t(side) * side * 3);
            if (!finiteState(tile)) {
                hatch(big, side);
            } else {
                const std::vector<float> rgb =
                    applyColormap(tile, chemical, spec.base.colormap, spec.base.edges);
                for (int y = 0; y < side; ++y)
                    for (int x = 0; x < side; ++x)
                        for (int c = 0; c < 3; ++c)
                            big[(std::size_t(y) * side + x) * 3 + c] =
                                rgb[(std::size_t(y / zoom) * spec.tile + x / zoom) * 3 + c];
            }
            plot.canvas.paste(big, side, side, plot.left + column * pitch,
                              plot.top + (spec.rows - 1 - row) * pitch);
        }
    writeRgbImage(path, plot.canvas.rgb, plot.canvas.width, plot.canvas.height, 8);
}

// A stat for stats.csv: empty when it is not a finite number (a tile that
// went NaN or infinite), never "nan" or "inf" passed off as a value.
std::string csvNumber(double v) {
    if (!std::isfinite(v))
        return "";
    std::ostringstream os;
    os << v;
    return os.str();
}

// stats.csv and stats.json into `files`. A tile that went NaN or infinite has
// its class ("unstable") and "finite": false, and no numbers: empty fields in
// the CSV, no keys in the JSON (nlohmann would write NaN as null).
void writeStats(const std::filesystem::path& dir, const SweepSpec& spec,
                const std::vector<TileResult>& results, int steps, const std::string& backend,
                const std::string& start, OutputFiles& files) {
    std::ostringstream csv;
    csv << "column,row,x_value,y_value,mean,variance,dominant_wavelength,feature_count,"
           "orientation_strength,class\n";
    nlohmann::json tiles = nlohmann::json::array();
    for (const TileResult& r : results) {
        const PatternStats& s = r.stats;
        const auto number = [&](double v) { return r.finite ? csvNumber(v) : std::string(); };
        csv << r.column << ',' << r.row << ',' << formatValue(r.x) << ',' << formatValue(r.y) << ','
            << number(s.mean) << ',' << number(s.variance) << ',' << number(s.dominantWavelength)
            << ',' << number(s.featureCount) << ',' << number(s.orientationStrength) << ','
            << toString(r.cls) << '\n';
        nlohmann::json tile = {{"column", r.column}, {"row", r.row}, {"x", r.x}, {"y", r.y}};
        if (!r.finite)
            tile["finite"] = false;
        const std::pair<const char*, double> stats[] = {
            {"mean", s.mean},
            {"variance", s.variance},
            {"dominant_wavelength", s.dominantWavelength},
            {"feature_count", s.featureCount},
            {"orientation_strength", s.orientationStrength}};
        for (const auto& [key, value] : stats)
            if (r.finite && std::isfinite(value))
                tile[key] = key == std::string("feature_count") ? nlohmann::json(s.featureCount)
                                                                : nlohmann::json(value);
        tile["class"] = toString(r.cls);
        tiles.push_back(tile);
    }
    writeTextAtomically(files.stage((dir / "stats.csv").string()), csv.str());
    nlohmann::json j = {{"model", spec.base.model},
                        {"x", {{"param", spec.x.param}, {"min", spec.x.min}, {"max", spec.x.max}}},
                        {"y", {{"param", spec.y.param}, {"min", spec.y.min}, {"max", spec.y.max}}},
                        {"grid", {spec.columns, spec.rows}},
                        {"tile", spec.tile},
                        {"start", start},
                        {"steps", steps},
                        {"backend", backend},
                        {"tiles", tiles}};
    writeTextAtomically(files.stage((dir / "stats.json").string()), j.dump(2) + "\n");
}

// Names the tiles that went NaN or infinite (at most a few, then a count) on
// stderr, with what to try; nothing when there are none.
void warnNonFiniteTiles(const SweepSpec& spec, const std::vector<TileResult>& results, float dt) {
    std::vector<const TileResult*> bad;
    for (const TileResult& r : results)
        if (!r.finite)
            bad.push_back(&r);
    if (bad.empty())
        return;
    constexpr std::size_t kNamed = 8;
    std::ostringstream os;
    os << "warning: " << bad.size() << " of " << results.size()
       << " tiles went NaN or infinite (blew up): ";
    for (std::size_t i = 0; i < std::min(bad.size(), kNamed); ++i)
        os << (i ? "; " : "") << "column " << bad[i]->column << ", row " << bad[i]->row << " ("
           << spec.x.param << " " << formatValue(bad[i]->x) << ", " << spec.y.param << " "
           << formatValue(bad[i]->y) << ")";
    if (bad.size() > kNamed)
        os << "; and " << bad.size() - kNamed << " more";
    os << ". They are hatched red in sheet.png, class \"unstable\" with empty stats in "
          "stats.csv and \"finite\": false without stats in stats.json. These values do not "
          "run at dt "
       << dt << ": narrow --x or --y to leave them out, or sweep from a preset with a smaller dt";
    std::fprintf(stderr, "morphogen: %s\n", os.str().c_str());
}

double seconds(Clock::time_point since) {
    return std::chrono::duration<double>(Clock::now() - since).count();
}

// Runs every tile as its own simulation, row by row; returns the tiles in
// row-major order, bottom row first.
std::vector<State> runOneByOne(const Session& batched, const SimulatorFactory& make,
                               Progress* progress) {
    const int columns = batched.tiles.columns, rows = batched.tiles.rows;
    std::vector<State> tiles;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Session tile = tileSession(batched, column, row);
            tiles.push_back(runTile(tile, make));
            if (progress)
                progress->update(int(tiles.size()) * batched.steps / (columns * rows));
        }
    return tiles;
}

// The sweep described by the flags, checked; base.dt is the smallest stable
// dt over the grid's corners.
SweepSpec sweepSpec(const SweepFlags& f) {
    SweepSpec spec;
    spec.base = explorationBase(f.model, f.preset, "sweep");
    const ReactionModel& model = spec.base.reactionModel();
    spec.x = parseAxis("--x", f.x, model);
    spec.y = parseAxis("--y", f.y, model);
    if (spec.x.param == spec.y.param)
        throw InputError("--x and --y must sweep different parameters");
    parseGrid(f.grid, spec.columns, spec.rows);
    if (f.tile < 8 || f.tile > 4096)
        throw InputError("--tile " + std::to_string(f.tile) + ": accepted are 8..4096 cells");
    spec.tile = f.tile;
    if (static_cast<long long>(spec.columns) * spec.tile > kMaxGridSide ||
        static_cast<long long>(spec.rows) * spec.tile > kMaxGridSide)
        throw InputError("--grid " + f.grid + " of --tile " + std::to_string(f.tile) + " exceeds " +
                         std::to_string(kMaxGridSide) + " cells per side");
    Session& base = spec.base;
    const ExplorationStart start = parseStartFlag(f.start);
    useStart(base, start, f.tile, !f.preset.empty());
    base.description = "sweep of " + spec.x.param + " x " + spec.y.param + " from " +
                       (f.preset.empty() ? "model " + f.model : "preset " + f.preset) + ", " +
                       startDescription(start);
    base.width = base.height = spec.tile;
    base.length = 0; // one unit per cell: the tiles show the presets' design scale
    base.schedule.clear();
    base.stages.clear();
    base.paramMaps.clear();
    if (!f.steps.empty())
        base.steps = int(integerFlag("--steps", f.steps, 0, kMaxSteps));
    if (!f.seed.empty())
        base.seed = std::uint64_t(integerFlag("--seed", f.seed, 0, kMaxSeed));
    base.colormap.name = canonicalColormapName(base.colormap.name);
    colormapAnchors(base.colormap); // 'custom' without stops is refused before the run

    // Stability at the corners covers the grid: a rate grows monotonically
    // along an axis. The smallest dt found applies to every tile.
    Session batched = batchedSession(spec);
    for (int row : {0, spec.rows - 1})
        for (int column : {0, spec.columns - 1}) {
            Session corner = tileSession(batched, column, row);
            validateSession(corner, "sweep");
            checkStability(corner, false);
            base.dt = std::min(base.dt, corner.dt);
            batched.dt = base.dt; // warn once, not at every corner
        }
    return spec;
}

// Times the tiles run one by one against the batched run and prints both.
void compareOneByOne(const Session& batched, const SimulatorFactory& make,
                     const std::string& backendName, const std::vector<State>& tiles,
                     double batchedSeconds) {
    const Clock::time_point again = Clock::now();
    const std::vector<State> single = runOneByOne(batched, make, nullptr);
    const double singleSeconds = seconds(again);
    float worst = 0;
    for (std::size_t t = 0; t < tiles.size(); ++t)
        for (int c = 0; c < tiles[t].channels(); ++c)
            for (std::size_t i = 0; i < tiles[t].cellCount(); ++i)
                worst = std::max(worst, std::fabs(tiles[t].plane(c)[i] - single[t].plane(c)[i]));
    const int tile = batched.width / batched.tiles.columns;
    std::printf("%s batched: %.3f s, one by one: %.3f s, one-by-one / batched = %.2f "
                "(%d tiles of %d x %d, %d steps; max |difference| %.3g)\n",
                backendName.c_str(), batchedSeconds, singleSeconds, singleSeconds / batchedSeconds,
                int(tiles.size()), tile, tile, batched.steps, double(worst));
}

// Per-tile stats and classes, row-major from the bottom row.
std::vector<TileResult> measureTiles(const SweepSpec& spec, const std::vector<State>& tiles) {
    const ReactionModel& model = spec.base.reactionModel();
    const int chemical = colormapChemical(spec.base.colormap, model);
    std::vector<TileResult> results;
    for (int row = 0; row < spec.rows; ++row)
        for (int column = 0; column < spec.columns; ++column) {
            TileResult r;
            r.column = column;
            r.row = row;
            r.x = sweepValue(spec.x, column, spec.columns);
            r.y = sweepValue(spec.y, row, spec.rows);
            const State& tile = tiles[std::size_t(row * spec.columns + column)];
            r.finite = finiteState(tile);
            const PatternStats measured = measurePattern(tile, chemical);
            r.cls = classifyPattern(measured, &model.chemicals()[std::size_t(chemical)]);
            r.stats = statsForClass(measured, r.cls);
            results.push_back(r);
        }
    return results;
}

std::filesystem::path outputFolder(const std::string& out) {
    const std::filesystem::path dir(out);
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
        throw InputError("--out '" + out + "' cannot be created as a folder");
    return dir;
}

// --pick: the tile's values are known without running the sweep, so only the session is written.
void pick(const SweepFlags& f, const SweepSpec& spec) {
    const TilePick tile = parseTilePick("--pick", f.pick, spec.columns, spec.rows);
    checkPickSize(f.pickSize);
    Session picked = pickTile(batchedSession(spec), tile, f.pickSize);
    const std::string where = "column " + std::to_string(tile.column) + ", row " +
                              std::to_string(tile.row) + " of the " + std::to_string(spec.columns) +
                              "x" + std::to_string(spec.rows) + " grid";
    picked.name = "sweep_pick";
    picked.description = picked.model + " at " + spec.x.param + " " +
                         formatValue(picked.params.at(spec.x.param)) + ", " + spec.y.param + " " +
                         formatValue(picked.params.at(spec.y.param)) + ": sweep tile " + where +
                         ", at the tile's scale; " + startDescription(parseStartFlag(f.start));
    const std::string path =
        !f.pickOut.empty() ? f.pickOut
                           : (outputFolder(f.out) / ("pick_" + std::to_string(tile.column) + "_" +
                                                     std::to_string(tile.row) + ".json"))
                                 .string();
    writePick(picked, path, where, spec.x, spec.y);
}

void sweep(const SweepFlags& f) {
    const SweepSpec spec = sweepSpec(f);
    if (!f.pick.empty())
        return pick(f, spec);
    const Session batched = batchedSession(spec);
    const std::filesystem::path dir = outputFolder(f.out);
    checkWritable((dir / "sheet.png").string());

    gl::Backend backend =
        gl::makeBackend(gl::parseBackendChoice(f.backend), gl::parseContextFlag(f.context),
                        gl::parseGpuDeviceFlag(f.gpuDevice));
    std::fprintf(stderr, "morphogen: %s\n", backend.reason.c_str());
    const std::string backendName = backend.context != nullptr ? "gpu" : "cpu";
    const int tileCount = spec.columns * spec.rows;

    Progress progress("sweep " + std::to_string(spec.columns) + "x" + std::to_string(spec.rows) +
                          " " + spec.x.param + " x " + spec.y.param,
                      batched.steps);
    const Clock::time_point start = Clock::now();
    RunOptions options;
    options.chunk = runChunk(batched);
    options.progress = [&](int done, int) { progress.update(done); };
    const State all = runBatched(batched, backend.makeSimulator, options);
    std::vector<State> tiles;
    for (int row = 0; row < spec.rows; ++row)
        for (int column = 0; column < spec.columns; ++column)
            tiles.push_back(extractTile(all, column, row, spec.tile));
    const double mainSeconds = seconds(start);
    progress.finish("done: " + std::to_string(tileCount) + " tiles of " +
                    std::to_string(batched.steps) + " steps");
    if (f.compare)
        compareOneByOne(batched, backend.makeSimulator, backendName, tiles, mainSeconds);

    const std::vector<TileResult> results = measureTiles(spec, tiles);
    warnNonFiniteTiles(spec, results, batched.dt);
    OutputFiles files; // the sheet, its stats and its session replace the previous ones together
    writeSheet(files.stage((dir / "sheet.png").string()), spec, tiles, batched.steps);
    writeStats(dir, spec, results, batched.steps, backendName, toString(parseStartFlag(f.start)),
               files);
    saveSessionFile(batched, files.stage((dir / "session.json").string()));
    files.commit();
    std::printf("%s\n", dir.string().c_str());
}

} // namespace

void addSweepCommand(CLI::App& app) {
    auto flags = std::make_shared<SweepFlags>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "A grid of independent simulations over two parameters, with a contact sheet "
                 "and per-tile pattern stats");
    cmd->add_option("--model", flags->model, "model whose defaults start every tile");
    cmd->add_option("--preset", flags->preset, "or a preset to start from");
    cmd->add_option("--x", flags->x, "PARAM:MIN:MAX across the columns")->required();
    cmd->add_option("--y", flags->y, "PARAM:MIN:MAX up the rows")->required();
    cmd->add_option("--grid", flags->grid,
                    "COLUMNSxROWS, e.g. 16x16; up to " + std::to_string(kMaxSweepTiles) + " tiles")
        ->required();
    cmd->add_option("--out", flags->out, "output folder")->required();
    cmd->add_option("--tile", flags->tile,
                    "cells per tile side, 8..4096, at most " + std::to_string(kMaxGridSide) +
                        " cells per side in all (default 128)");
    cmd->add_option("--steps", flags->steps,
                    "steps, 0.." + std::to_string(kMaxSteps) + " (default: the preset's, or 10000)")
        ->type_name("N");
    cmd->add_option("--seed", flags->seed, "random seed, 0..2^53")->type_name("N");
    cmd->add_option("--backend", flags->backend, "auto, gpu or cpu (default auto)");
    cmd->add_option("--context", flags->context, "GL context: egl or osmesa");
    cmd->add_option(
        "--gpu-device", flags->gpuDevice,
        "EGL display number (default: $MORPHOGEN_GPU_DEVICE, else the first hardware renderer)");
    cmd->add_flag("--compare-one-by-one", flags->compare,
                  "also time the same tiles run one by one on the same backend");
    cmd->add_option("--start", flags->start,
                    "noise (default: every tile shows the pattern it settles to) or preset (the "
                    "preset's or model's own start, e.g. Gray-Scott's seed spots)");
    cmd->add_option("--pick", flags->pick,
                    "COL,ROW (from 0; row 0 at the bottom, as in stats.csv): write that tile's "
                    "session at full size instead of running the sweep");
    cmd->add_option("--pick-out", flags->pickOut,
                    "where --pick writes the session (default OUT/pick_COL_ROW.json)");
    cmd->add_option("--pick-size", flags->pickSize,
                    "--pick's session size in cells, at the tile's scale (default 256)");
    cmd->callback([flags] { sweep(*flags); });
}

} // namespace morphogen::cli
