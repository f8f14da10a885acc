#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string_view>

#include "cli/colour_flags.hpp"
#include "cli/commands.hpp"
#include "cli/flag_values.hpp"
#include "cli/interrupt.hpp"
#include "cli/knob_flags.hpp"
#include "cli/peak_memory.hpp"
#include "cli/perturb_flags.hpp"
#include "cli/progress.hpp"
#include "cli/render_frames.hpp"
#include "cli/render_output.hpp"
#include "cli/render_surface.hpp"
#include "cli/settle_flags.hpp"
#include "cli/surface_flags.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/models/initial_condition.hpp"
#include "core/output/colormap.hpp"
#include "core/output/frames.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/segments.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/backend.hpp"

namespace morphogen::cli {

namespace {

constexpr const char* kDefaultPreset = "gs_coral";

struct RenderFlags {
    std::string preset;
    std::string sessionFile;
    std::string out;
    std::string sessionOut;
    std::string size;
    std::string steps; // numbers with a range are text until flag_values.hpp checks them
    std::string seed;
    std::string dt;
    std::vector<std::string> params;
    std::string edges;
    std::string stencil;
    std::string integrator;
    std::string relaxationPasses;
    std::string schedule;
    std::string backend = "auto";
    std::string context;
    std::string gpuDevice;
    std::string colormap;
    std::string chemical;
    std::string levels;
    double scale = 1.0;
    bool noCoarseToFine = false;
    int bitDepth = 8;
    int bakeSize = 1024;
    KnobFlags knobs;
    GradientFlags gradient;
    TextureSetFlags textureSet;
    FrameFlags frames;
    SettleFlags settle;
    SurfaceFlags surface;
    PerturbFlags perturb;
};

// An enumeration's name given to `flag`; throws InputError listing `accepted`.
template <class E>
E parseFlag(const std::string& flag, const std::string& text,
            std::optional<E> (*parse)(std::string_view), const std::string& accepted) {
    const std::optional<E> value = parse(text);
    if (!value)
        throw InputError(flag + " '" + text + "' is unknown (accepted: " + accepted + ")" +
                         didYouMean(text, splitNameList(accepted)));
    return *value;
}

// "N" or "WxH" with sides in 1..kMaxGridSide; `source` names the flag (and
// the schedule level) in the message.
std::pair<int, int> parseSizeText(const std::string& source, const std::string& text) {
    long long w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(text);
    bool ok = false;
    if (text.find('x') != std::string::npos)
        ok = bool(in >> w >> x >> h) && x == 'x' && !(in >> extra);
    else {
        ok = bool(in >> w) && !(in >> extra);
        h = w;
    }
    if (!ok || w < 1 || h < 1 || w > kMaxGridSide || h > kMaxGridSide)
        throw InputError(source + " '" + text + "': expected N or WxH with sides in 1.." +
                         std::to_string(kMaxGridSide));
    return {int(w), int(h)};
}

// "128:4000,256:2000" (size:steps, size N or WxH), coarsest first.
std::vector<ScheduleLevel> parseSchedule(const std::string& text) {
    std::vector<ScheduleLevel> levels;
    std::stringstream in(text);
    std::string item;
    long long total = 0;
    while (std::getline(in, item, ',')) {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
            throw InputError("--schedule '" + text + "': '" + item +
                             "' is not size:steps (e.g. 128:4000,256:2000)");
        if (levels.size() == std::size_t(kMaxScheduleLevels))
            throw InputError("--schedule '" + text + "': more than " +
                             std::to_string(kMaxScheduleLevels) + " levels");
        const std::string level = "--schedule level " + std::to_string(levels.size() + 1);
        const auto [w, h] = parseSizeText(level + " size", item.substr(0, colon));
        const long long steps = integerFlag(level + " steps", item.substr(colon + 1), 0, kMaxSteps);
        total += steps;
        levels.push_back({w, h, int(steps)});
    }
    if (levels.empty())
        throw InputError("--schedule is empty");
    for (std::size_t i = 1; i < levels.size(); ++i)
        if (levels[i].width < levels[i - 1].width || levels[i].height < levels[i - 1].height)
            throw InputError("--schedule '" + text + "': levels must go from coarse to fine");
    if (total > kMaxSteps)
        throw InputError("--schedule '" + text + "': " + std::to_string(total) +
                         " steps in all; accepted are up to " + std::to_string(kMaxSteps));
    return levels;
}

void parseSize(const std::string& text, Session& s) {
    const auto [w, h] = parseSizeText("--size", text);
    resizeSession(s, w, h);
}

Session buildSession(const RenderFlags& f) {
    if (!f.preset.empty() && !f.sessionFile.empty())
        throw InputError("--preset and --session are exclusive: give one");
    Session s = !f.sessionFile.empty() ? loadSessionFile(f.sessionFile)
                                       : loadPreset(f.preset.empty() ? kDefaultPreset : f.preset);
    if (s.length <= 0 && !s.tiles.active()) {
        // Written before sessions had a length: its rates are per cell at its own size.
        s.length = s.width;
        std::fprintf(stderr,
                     "morphogen: %s has no \"length\": read as written for its own size, %d "
                     "units wide (one per cell); other sizes keep that pattern\n",
                     f.sessionFile.c_str(), s.width);
    }
    applySurfaceFlags(f.surface, s);
    if (s.surface.active()) {
        // The tiles set the resolution (--tile-size, --tiles); --scale still sets the pattern's.
        if (!f.size.empty() || !f.schedule.empty())
            throw InputError(std::string(f.size.empty() ? "--schedule" : "--size") +
                             " does not apply on a mesh: the tiles set the resolution (use "
                             "--tile-size and --tiles; --scale sets the pattern's scale)");
        if (!s.schedule.empty() || s.tiles.active())
            throw InputError("a session on a mesh (\"surface\") cannot also have a " +
                             std::string(s.tiles.active() ? "\"tiles\" sweep" : "\"schedule\""));
    }
    if (!f.schedule.empty()) {
        if (!f.size.empty() || !f.steps.empty())
            throw InputError("--schedule sets the sizes and steps: drop --size and --steps");
        // The runner has no coarse-to-fine path through a cascade; refusing keeps the written
        // session a record of what ran.
        if (!s.stages.empty())
            throw InputError("--schedule does not combine with cascade \"stages\" (" +
                             std::to_string(s.stages.size()) +
                             " stages of their own steps): drop --schedule, or use --size");
        applySchedule(s, parseSchedule(f.schedule));
    } else if (!s.schedule.empty() && (!f.size.empty() || !f.steps.empty())) {
        throw InputError("--size and --steps do not apply to a session with a coarse-to-fine "
                         "\"schedule\": edit its levels or use --schedule");
    }
    if (!f.size.empty())
        parseSize(f.size, s);
    if (!f.steps.empty())
        applySteps(s, int(integerFlag("--steps", f.steps, 0, kMaxSteps)), "--steps");
    if (!(f.scale > 0 && f.scale <= 1000))
        throw InputError("--scale " + std::to_string(f.scale) +
                         ": accepted are numbers in (0, 1000] (2: features twice as large)");
    s.length /= f.scale;
    if (f.noCoarseToFine)
        s.coarseToFine = false;
    if (!f.integrator.empty()) {
        s.integrator = parseFlag("--integrator", f.integrator, parseIntegrator, integratorNames());
        s.integratorGiven = true;
    }
    if (!f.relaxationPasses.empty())
        s.relaxationPasses =
            int(integerFlag("--relaxation-passes", f.relaxationPasses, 1, kMaxRelaxationPasses));
    // The ranges are the session reader's, so that what is written reads back.
    if (!f.seed.empty())
        s.seed = std::uint64_t(integerFlag("--seed", f.seed, 0, kMaxSeed));
    if (!f.dt.empty())
        s.dt = float(numberFlag("--dt", f.dt, kMinDt, kMaxDt));
    for (const std::string& p : f.params)
        applyParamOverride(s, p);
    for (const std::string& note : applyKnobFlags(f.knobs, s))
        std::fprintf(stderr, "morphogen: %s\n", note.c_str());
    if (!f.edges.empty())
        s.edges = parseFlag("--edges", f.edges, parseEdgeMode, edgeModeNames());
    if (!f.stencil.empty()) {
        if (s.diffusion.type != DiffusionType::Isotropic)
            throw InputError("--stencil applies to isotropic diffusion only; this session's is " +
                             toString(s.diffusion.type));
        // The flag also takes the short "5" and "9"; sessions spell them out.
        const std::string stencil =
            f.stencil == "5" || f.stencil == "9" ? f.stencil + "-point" : f.stencil;
        s.diffusion.stencil = parseFlag("--stencil", stencil, parseStencil, stencilNames());
    }
    if (!f.colormap.empty())
        s.colormap.name = f.colormap;
    if (!f.chemical.empty())
        s.colormap.chemical = f.chemical;
    if (!f.levels.empty()) {
        const std::size_t colon = f.levels.find(':');
        char* end0 = nullptr;
        char* end1 = nullptr;
        const std::string a = f.levels.substr(0, colon);
        const std::string b = colon == std::string::npos ? "" : f.levels.substr(colon + 1);
        const float low = std::strtof(a.c_str(), &end0), high = std::strtof(b.c_str(), &end1);
        if (colon == std::string::npos || a.empty() || b.empty() || *end0 || *end1 ||
            !(low >= 0.0f && low < high && high <= 1.0f))
            throw InputError("--levels '" + f.levels +
                             "' is not LOW:HIGH with 0 <= LOW < HIGH <= 1 (e.g. 0.3:0.5)");
        s.colormap.levels = {low, high};
    }
    applyGradientFlags(f.gradient, f.colormap, s.colormap);
    colormapChemical(s.colormap, s.outputModel());
    validateSession(s, f.sessionFile.empty() ? "preset " + s.name : f.sessionFile);
    for (const std::string& image : sessionImages(s))
        checkImageFile(image); // headers only: the run reads them again
    return s;
}

// Whether two paths name the same file: "./a.json" and "a.json", or a path
// through a link, are the same even when the file does not exist yet.
bool samePath(const std::string& a, const std::string& b) {
    namespace fs = std::filesystem;
    std::error_code ea, eb;
    // Absolute first: weakly_canonical leaves a relative path whose first
    // part does not exist yet ("a.json") relative.
    const fs::path absoluteA = fs::absolute(a, ea), absoluteB = fs::absolute(b, eb);
    if (ea || eb)
        return fs::path(a).lexically_normal() == fs::path(b).lexically_normal();
    const fs::path pa = fs::weakly_canonical(absoluteA, ea);
    const fs::path pb = fs::weakly_canonical(absoluteB, eb);
    if (ea || eb)
        return absoluteA.lexically_normal() == absoluteB.lexically_normal();
    return pa == pb;
}

std::string defaultSessionOut(const std::string& out) {
    std::filesystem::path p(out);
    return p.replace_extension(".json").string();
}

void render(const RenderFlags& flags) {
    RenderFlags f = flags; // prepareFrames resolves the frame folder
    Session session = buildSession(f);
    if (f.out.empty() && f.textureSet.dir.empty())
        throw InputError("render needs --out FILE or --texture-set DIR (or both)");
    applyTextureSetFlags(f.textureSet, session);
    const bool image = !f.out.empty(); // without --out, only the texture set is written
    const bool surface = session.surface.active();
    if (surface) {
        if (f.frames.wanted() && (isModelOutput(f.out) || session.surface.view.turntable > 0))
            throw InputError("--frames on a mesh draws screenshots from the session's view: give "
                             "--out a .png and no --turntable");
        if (image)
            checkSurfaceOutput(f.out);
        checkBakeSize(f.bakeSize);
    } else if (image) {
        imageFormatForPath(f.out); // an unsupported extension is bad input, found before the run
    }
    checkPerturbFlags(f.perturb, surface);
    if (f.bitDepth != 8 && f.bitDepth != 16)
        throw InputError("--bit-depth " + std::to_string(f.bitDepth) +
                         " is not supported (accepted: 8, 16)");
    const std::string sessionOut =
        f.sessionOut.empty() && image ? defaultSessionOut(f.out) : f.sessionOut;
    if (image && samePath(sessionOut, f.out))
        throw InputError("--session-out " + sessionOut + " is the image --out " + f.out +
                         ": give them different paths");
    // Fail before a long run, not after it.
    if (image)
        checkWritable(f.out);
    if (!sessionOut.empty())
        checkWritable(sessionOut);
    if (f.frames.wanted())
        prepareFrames(f.frames, f.out, session);

    std::optional<SurfaceSetup> surfaceSetup;
    if (surface) {
        Progress tiling("mesh to tiles", 100);
        surfaceSetup = setUpSurface(session, [&](const std::string&, double fraction) {
            tiling.update(int(fraction * 100));
        });
        tiling.finish("done");
        std::fprintf(stderr, "morphogen: %s\n", surfaceSetup->describe().c_str());
        checkPerturbBall(f.perturb, session, *surfaceSetup);
    }
    SettleRun settle(f.settle, session, f.sessionFile.empty(), !f.steps.empty());
    checkStability(session);
    const std::string plan = describePlan(session);
    if (!plan.empty())
        std::fprintf(stderr, "morphogen: %s\n", plan.c_str());
    if (!surface && session.cellSize() > 2.0)
        std::fprintf(stderr,
                     "morphogen: warning: a cell is %.3g units wide: features designed a few "
                     "units across are under-resolved; use a larger --size\n",
                     session.cellSize());
    gl::Backend backend =
        gl::makeBackend(gl::parseBackendChoice(f.backend), gl::parseContextFlag(f.context),
                        gl::parseGpuDeviceFlag(f.gpuDevice));
    std::fprintf(stderr, "morphogen: %s\n", backend.reason.c_str());

    Progress progress("render " + (session.name.empty() ? std::string("session") : session.name),
                      sessionTotalSteps(session));
    // Ctrl-C stops the run after the current chunk; the guard stays through the writing, so a
    // Ctrl-C then lets the files finish. Every file goes to a temporary first and is renamed into
    // place only once all are written (core/io/output_files.hpp): frames, then the texture set,
    // the image and last the session, the record of what the others show. A failure or a fatal
    // signal before that removes the temporaries and leaves the previous files untouched.
    InterruptGuard interrupt(
        "\nmorphogen: interrupted: stopping after the current chunk, then writing what is "
        "finished (Ctrl-C again, a second or more later, quits at once and writes nothing)\n");
    std::optional<StagedSequence> frames;
    if (f.frames.wanted())
        frames.emplace(f.frames.dir, "frame_", ".png");
    RunResult result;
    {
        RunOptions options;
        options.progress = [&](int done, int) { progress.update(done); };
        options.cancel = interrupt.flag();
        options.chunk = runChunk(session);
        settle.attach(options, progress);
        std::optional<SurfaceFrames> surfaceFrames;
        FrameDrawer draw;
        if (frames && surface) {
            surfaceFrames.emplace(*surfaceSetup, backend.context.get(),
                                  gl::parseContextFlag(f.context));
            draw = [&](const std::string& path, const RunResult& sofar,
                       const FrameColouring& colouring) {
                surfaceFrames->draw(path, sofar, colouring);
            };
        }
        result =
            frames ? renderFrames(session, backend.makeSimulator, options, f.frames, *frames, draw)
                   : runSession(session, backend.makeSimulator, options);
    }
    const bool cancelled = result.cancelled;
    interrupt.setNotice("\nmorphogen: interrupted while writing: finishing the files (Ctrl-C "
                        "again, a second or more later, quits and keeps the previous files)\n");

    if (cancelled) {
        progress.finish("interrupted after " + std::to_string(result.stepsDone) +
                        " steps; writing what is finished");
    } else {
        progress.finish("done: " + std::to_string(result.stepsDone) + " steps");
    }
    bool warning = false;
    const std::string settled = settle.summary(result, warning);
    if (!settled.empty())
        std::fprintf(stderr, "morphogen: %s%s\n", warning ? "warning: " : "", settled.c_str());
    requireFinite(result);
    warnIfFlat(result);

    OutputFiles files;
    if (surface) {
        if (!cancelled)
            applyPerturbation(f.perturb, session, *surfaceSetup, backend.makeSimulator, result);
        std::fprintf(stderr, "morphogen: %s\n",
                     describeSurfaceResult(result, *surfaceSetup).c_str());
        const std::vector<std::string> written = writeSurfaceOutput(
            result, *surfaceSetup, {f.out, sessionOut, f.textureSet.dir, f.bakeSize},
            backend.context.get(), gl::parseContextFlag(f.context), files);
        if (frames)
            frames->commit();
        files.commit();
        for (const std::string& path : written)
            std::printf("%s\n", path.c_str());
        if (frames && !cancelled)
            encodeVideo(f.frames);
        if (cancelled)
            throw std::runtime_error("interrupted; wrote the state after " +
                                     std::to_string(result.stepsDone) + " steps");
        return;
    }
    writeTextureSetOutput(result, f.textureSet, files);
    if (image)
        writeRenderOutput(result, f.out, sessionOut, f.bitDepth, files);
    else if (!sessionOut.empty())
        saveSessionFile(result.completed, files.stage(sessionOut));
    if (frames)
        frames->commit();
    files.commit();
    if (image)
        std::printf("%s\n", f.out.c_str());
    if (!sessionOut.empty())
        std::printf("%s\n", sessionOut.c_str());
    if (!f.textureSet.dir.empty())
        std::printf(
            "%s\n",
            (std::filesystem::path(f.textureSet.dir) / "texture_set.json").string().c_str());
    if (frames && !cancelled)
        encodeVideo(f.frames);
    if (cancelled)
        throw std::runtime_error("interrupted; wrote the state after " +
                                 std::to_string(result.stepsDone) + " steps");
    if (interrupt.cancelled())
        std::fprintf(stderr, "morphogen: the run had finished; its files are complete\n");
}

} // namespace

void addRenderCommand(CLI::App& app) {
    auto flags = std::make_shared<RenderFlags>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Run a preset or session headlessly and write an image plus the session JSON "
                  "that reproduces it");
    cmd->add_option("--preset", flags->preset,
                    std::string("built-in preset name (default ") + kDefaultPreset + ")");
    cmd->add_option("--session", flags->sessionFile, "session JSON file");
    cmd->add_option("--out", flags->out,
                    "output image: .png/.tif (colour-mapped) or .exr (raw float chemicals); "
                    "needed unless --texture-set is given");
    cmd->add_option("--session-out", flags->sessionOut,
                    "where to write the session JSON (default: --out with .json)");
    cmd->add_option("--size", flags->size,
                    "resolution N or WxH (sides 1.." + std::to_string(kMaxGridSide) +
                        "): the pattern stays the same, with more or less detail")
        ->type_name("N|WxH");
    cmd->add_option("--scale", flags->scale,
                    "make every feature this many times larger in the image (default 1)");
    cmd->add_flag("--no-coarse-to-fine", flags->noCoarseToFine,
                  "run every step at the full size (default: a size over twice the session's "
                  "length runs its steps near one cell per unit, then refines)");
    cmd->add_option("--steps", flags->steps,
                    "number of steps, 0.." + std::to_string(kMaxSteps) +
                        " (a schedule's or a cascade's in all)")
        ->type_name("N");
    cmd->add_option("--seed", flags->seed,
                    "random seed of the initial condition, 0..2^53 (" + std::to_string(kMaxSeed) +
                        ")")
        ->type_name("N");
    std::ostringstream dtHelp;
    dtHelp << "time step, " << kMinDt << ".." << kMaxDt;
    cmd->add_option("--dt", flags->dt, dtHelp.str())->type_name("DT");
    cmd->add_option("--param", flags->params,
                    "override a model parameter: name=value (repeatable)");
    cmd->add_option("--edges", flags->edges, "periodic (seamless) or clamped");
    cmd->add_option("--stencil", flags->stencil, "Laplacian: 5-point or 9-point");
    cmd->add_option("--integrator", flags->integrator, "explicit_euler or semi_implicit");
    cmd->add_option("--relaxation-passes,--sweeps", flags->relaxationPasses,
                    "relaxation passes per semi-implicit step, 1.." +
                        std::to_string(kMaxRelaxationPasses) + " (--sweeps: the old name)")
        ->type_name("N");
    cmd->add_option("--schedule", flags->schedule,
                    "coarse-to-fine levels size:steps, coarsest first (e.g. 128:4000,256:2000); "
                    "up to " +
                        std::to_string(kMaxScheduleLevels) + " levels")
        ->type_name("SIZE:STEPS,...");
    cmd->add_option("--backend", flags->backend, "auto, gpu or cpu (default auto)");
    cmd->add_option(
        "--context", flags->context,
        "GL context: egl or osmesa (default: $MORPHOGEN_CONTEXT, else egl then osmesa)");
    cmd->add_option(
        "--gpu-device", flags->gpuDevice,
        "EGL display number (default: $MORPHOGEN_GPU_DEVICE, else the first hardware renderer)");
    cmd->add_option("--colormap", flags->colormap, joinNames(colormapNames()));
    cmd->add_option("--chemical", flags->chemical, "chemical to show (default: the model's)");
    cmd->add_option("--levels", flags->levels,
                    "LOW:HIGH window on the min-max normalised value (default 0:1)");
    cmd->add_option("--bit-depth", flags->bitDepth, "8 or 16 bits per channel for PNG/TIFF");
    addKnobFlags(*cmd, flags->knobs);
    addGradientFlags(*cmd, flags->gradient);
    addTextureSetFlags(*cmd, flags->textureSet);
    cmd->add_option("--bake-size", flags->bakeSize,
                    "on a model with texture coordinates: texels per side of the textures baked "
                    "into its UVs (the .glb and the texture set; 16..8192, default 1024)");
    addFrameFlags(*cmd, flags->frames);
    addSettleFlags(*cmd, flags->settle);
    addSurfaceFlags(*cmd, flags->surface);
    addPerturbFlags(*cmd, flags->perturb);
    cmd->callback([flags] {
        writePeakMemoryAtExit(); // for `bench`'s memory rows, when they ask
        render(*flags);
    });
}

} // namespace morphogen::cli
