// morphogen map: one simulation whose parameters vary across the image (x and
// y each sweep one parameter linearly), with labelled axes: Pearson's
// Gray-Scott F-k map, McGraw's Fig. 6 with a generalized tensor, for any
// model and any two of its parameters.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/exploration.hpp"
#include "cli/flag_values.hpp"
#include "cli/plot_frame.hpp"
#include "cli/progress.hpp"
#include "cli/render_output.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/base/names.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/output/colormap.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"
#include "gl/backend.hpp"

namespace morphogen::cli {

namespace {

// The map's width in model units (one unit per cell at the default size).
constexpr int kMapLength = 512;

struct MapFlags {
    std::string model;
    std::string preset;
    std::string x, y;
    std::string out;
    int size = kMapLength;
    std::string steps; // checked by flag_values.hpp
    std::string seed;
    std::string tensor;
    std::vector<std::string> params;
    std::string backend = "auto";
    std::string context;
    std::string gpuDevice;
    std::string colormap;
    std::string edges = "clamped";
    std::string start = "preset";
    std::string pick;
    std::string pickOut;
    int pickSize = 256;
};

// Ticks at "nice" values of a parameter swept over `cells` cells: cell i holds
// min + (max - min) i / (cells - 1), and its tick sits on that cell. `upwards`:
// the values grow from the bottom (a y axis), whose pixel rows count down.
PlotAxis linearAxis(const SweepAxis& axis, int cells, int maxTicks, bool upwards) {
    PlotAxis plotAxis{axis.param, {}};
    for (const auto& [value, label] : axisTicks(axis.min, axis.max, maxTicks)) {
        const int cell = int(std::lround((value - axis.min) / (axis.max - axis.min) * (cells - 1)));
        plotAxis.ticks.emplace_back(upwards ? cells - 1 - cell : cell, label);
    }
    return plotAxis;
}

// What a map runs: the session, with x and y as parameter maps over the grid.
struct MapPlan {
    Session session;
    SweepAxis x, y;
    EdgeMode ownEdges = EdgeMode::Periodic; // the preset's or model's, for a picked point
};

// Reads and checks the flags; throws InputError before anything runs.
MapPlan planMap(const MapFlags& f) {
    MapPlan plan;
    Session& s = plan.session;
    s = explorationBase(f.model, f.preset, "map");
    const ReactionModel& model = s.reactionModel();
    plan.x = parseAxis("--x", f.x, model);
    plan.y = parseAxis("--y", f.y, model);
    if (plan.x.param == plan.y.param)
        throw InputError("--x and --y must sweep different parameters");
    if (f.size < 16 || f.size > kMaxGridSide)
        throw InputError("--size " + std::to_string(f.size) + ": accepted are 16.." +
                         std::to_string(kMaxGridSide));
    const ExplorationStart start = parseStartFlag(f.start);
    useStart(s, start, int(kMapLength), !f.preset.empty());
    s.description = "map of " + plan.x.param + " x " + plan.y.param + " from " +
                    (f.preset.empty() ? "model " + f.model : "preset " + f.preset) + ", " +
                    startDescription(start);
    // A map is kMapLength units across at every --size, one unit per cell at
    // the default: a larger size is the same map in more detail.
    s.width = s.height = f.size;
    s.length = kMapLength;
    plan.ownEdges = s.edges;
    // Periodic edges would join the two ends of each swept range, coupling unrelated parameter
    // values into an artefact strip along the borders; zero-flux edges keep each end to itself.
    const std::optional<EdgeMode> edges = parseEdgeMode(f.edges);
    if (!edges)
        throw InputError("--edges '" + f.edges + "' is unknown (accepted: " + edgeModeNames() +
                         ")" + didYouMean(f.edges, splitNameList(edgeModeNames())));
    s.edges = *edges;
    s.schedule.clear();
    if (!f.steps.empty())
        applySteps(s, int(integerFlag("--steps", f.steps, 0, kMaxSteps)), "--steps");
    if (!f.seed.empty())
        s.seed = std::uint64_t(integerFlag("--seed", f.seed, 0, kMaxSeed));
    for (const std::string& p : f.params) {
        // The axes set these per cell: a fixed value would have no effect.
        const std::string name = p.substr(0, p.find('='));
        for (const SweepAxis* axis : {&plan.x, &plan.y})
            if (sameSpelling(name, axis->param))
                throw InputError("--param " + p + ": " + axis->param + " is swept by --" +
                                 (axis == &plan.x ? "x" : "y") +
                                 ", so a fixed value would have no effect; fix another "
                                 "parameter, or sweep a different one");
        applyParamOverride(s, p);
    }
    if (!f.tensor.empty()) {
        s.diffusion.type = DiffusionType::Generalized;
        for (const ChemicalSpec& c : model.chemicals())
            if (!c.diffusionParam.empty())
                s.diffusion.generalized[c.name] = f.tensor;
    }
    if (!f.colormap.empty())
        s.colormap.name = f.colormap;
    s.colormap.name = canonicalColormapName(s.colormap.name);
    colormapAnchors(s.colormap); // 'custom' without stops is refused before the run
    s.paramMaps[plan.x.param] = {ParamMapSpec::Field::LinearX, plan.x.min, plan.x.max};
    s.paramMaps[plan.y.param] = {ParamMapSpec::Field::LinearY, plan.y.min, plan.y.max};
    validateSession(s, "map");
    // A map is a labelled plot (colours, axes, title): an image format. EXR
    // means raw chemical values everywhere else (render --out x.exr), which a
    // plot is not, so it is refused rather than given another meaning here.
    if (imageFormatForPath(f.out) == ImageFormat::Exr)
        throw InputError("--out " + f.out +
                         ": a map is a labelled colour plot, written as .png or .tif (.exr "
                         "holds raw chemical values, as render writes them)");
    checkWritable(f.out);
    checkStability(s, false);
    return plan;
}

// The map with the y axis on the left, the x axis below and a title.
void writeMapPlot(const std::string& path, const MapPlan& plan, const RunResult& result) {
    requireFinite(result);
    const Session& s = plan.session;
    const ReactionModel& model = s.reactionModel();
    // Fewer x ticks until their labels no longer touch (small maps, long labels).
    PlotAxis xAxis;
    for (int count = 6; count >= 2; --count) {
        xAxis = linearAxis(plan.x, s.width, count, false);
        if (xLabelStride(xAxis) == 1)
            break;
    }
    const std::string title = model.name() + ": " + plan.x.param + " (x) vs " + plan.y.param +
                              " (y), " + std::to_string(result.stepsDone) + " steps";
    PlotFrame plot =
        drawPlotFrame(s.width, s.height, xAxis, linearAxis(plan.y, s.height, 6, true), title);
    plot.canvas.paste(
        applyColormap(result.state, colormapChemical(s.colormap, model), s.colormap, s.edges),
        s.width, s.height, plot.left, plot.top);
    writeRgbImage(path, plot.canvas.rgb, plot.canvas.width, plot.canvas.height, 8);
}

std::string formatValue(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

// --pick: the point's values are known without running the map, so only the session is written.
void pick(const MapFlags& f, const MapPlan& plan) {
    const PointPick point = parsePointPick("--pick", f.pick, plan.x, plan.y);
    checkPickSize(f.pickSize);
    Session picked = pickPoint(plan.session, plan.x, plan.y, point, f.pickSize);
    // The map's clamped edges only keep the ends of its axes apart; one point tiles.
    picked.edges = plan.ownEdges;
    const std::string values = plan.x.param + " " + formatValue(point.x) + ", " + plan.y.param +
                               " " + formatValue(point.y);
    picked.name = "map_pick";
    picked.description = picked.model + " at " + values +
                         ": a point of the map, uniformly, at the map's scale; " +
                         startDescription(parseStartFlag(f.start));
    std::string path = f.pickOut;
    if (path.empty()) {
        std::filesystem::path p(f.out);
        p.replace_filename(p.stem().string() + "_pick_" + plan.x.param + formatValue(point.x) +
                           "_" + plan.y.param + formatValue(point.y) + ".json");
        path = p.string();
    }
    writePick(picked, path, "the map's point " + formatValue(point.x) + "," + formatValue(point.y),
              plan.x, plan.y);
}

void map(const MapFlags& f) {
    const MapPlan plan = planMap(f);
    if (!f.pick.empty())
        return pick(f, plan);
    const Session& s = plan.session;
    gl::Backend backend =
        gl::makeBackend(gl::parseBackendChoice(f.backend), gl::parseContextFlag(f.context),
                        gl::parseGpuDeviceFlag(f.gpuDevice));
    std::fprintf(stderr, "morphogen: %s\n", backend.reason.c_str());
    Progress progress("map " + plan.x.param + " x " + plan.y.param, s.steps);
    RunOptions options;
    options.chunk = runChunk(s);
    options.progress = [&](int done, int) { progress.update(done); };
    const RunResult result = runSession(s, backend.makeSimulator, options);
    progress.finish("done: " + std::to_string(result.stepsDone) + " steps");

    std::filesystem::path sessionPath(f.out);
    sessionPath.replace_extension(".json");
    OutputFiles files; // the map and its session replace the previous pair together
    writeMapPlot(files.stage(f.out), plan, result);
    saveSessionFile(result.completed, files.stage(sessionPath.string()));
    files.commit();
    std::printf("%s\n%s\n", f.out.c_str(), sessionPath.string().c_str());
}

} // namespace

void addMapCommand(CLI::App& app) {
    auto flags = std::make_shared<MapFlags>();
    CLI::App* cmd = app.add_subcommand(
        "map", "One simulation whose parameters vary across the image, with labelled axes");
    cmd->add_option("--model", flags->model, "model whose defaults start the map");
    cmd->add_option("--preset", flags->preset, "or a preset to start from");
    cmd->add_option("--x", flags->x, "PARAM:MIN:MAX swept left to right")->required();
    cmd->add_option("--y", flags->y, "PARAM:MIN:MAX swept bottom to top")->required();
    cmd->add_option("--out", flags->out, "output image (.png, .tif)")->required();
    cmd->add_option("--size", flags->size,
                    "map resolution in cells (default 512: one cell per unit; larger sizes are "
                    "the same map in more detail)");
    cmd->add_option("--steps", flags->steps,
                    "steps, 0.." + std::to_string(kMaxSteps) + " (default: the preset's, or 10000)")
        ->type_name("N");
    cmd->add_option("--seed", flags->seed, "random seed, 0..2^53")->type_name("N");
    cmd->add_option("--tensor", flags->tensor,
                    "generalized diffusion for every chemical: a..f or components (McGraw Fig. 6)");
    cmd->add_option("--param", flags->params, "fix another parameter: name=value (repeatable)");
    cmd->add_option("--backend", flags->backend, "auto, gpu or cpu (default auto)");
    cmd->add_option("--context", flags->context, "GL context: egl or osmesa");
    cmd->add_option(
        "--gpu-device", flags->gpuDevice,
        "EGL display number (default: $MORPHOGEN_GPU_DEVICE, else the first hardware renderer)");
    cmd->add_option("--colormap", flags->colormap, "colour map name");
    cmd->add_option(
        "--edges", flags->edges,
        "clamped (zero-flux, the default: the ends of the axes stay apart) or periodic");
    cmd->add_option("--start", flags->start,
                    "preset (default: the preset's or model's own start, e.g. Gray-Scott's seed "
                    "spots: growth fronts, as Pearson's map) or noise (every point shows the "
                    "pattern it settles to)");
    cmd->add_option("--pick", flags->pick,
                    "X,Y (values of the x and y parameters, as the axes show them): write the "
                    "session of that point at full size instead of running the map");
    cmd->add_option("--pick-out", flags->pickOut,
                    "where --pick writes the session (default: next to --out, "
                    "OUT_pick_XPARAMX_YPARAMY.json)");
    cmd->add_option("--pick-size", flags->pickSize,
                    "--pick's session size in cells, at the map's scale (default 256)");
    cmd->callback([flags] { map(*flags); });
}

} // namespace morphogen::cli
