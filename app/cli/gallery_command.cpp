#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>
#include <unistd.h>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "cli/render_output.hpp"
#include "core/base/errors.hpp"
#include "core/base/names.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"
#include "gl/backend.hpp"

namespace morphogen::cli {

namespace {

namespace fs = std::filesystem;

struct GalleryFlags {
    std::string dir;
    int size = -1;
    double stepsScale = 1.0;
    std::string backend = "auto";
    std::string context;
    std::string gpuDevice;
    std::string only;
};

// One preset's outcome, as the page and the summary show it.
struct Entry {
    Session session; // as run (after --size/--steps-scale); the completed one on success
    double seconds = 0;
    std::string error; // empty on success
};

// Steps times --steps-scale, at least 1; InputError past kMaxSteps (in
// double, so a large scale cannot wrap an int into a small count).
int scaledSteps(int steps, double scale, const std::string& preset) {
    const double scaled = std::round(double(steps) * scale);
    if (scaled > double(kMaxSteps))
        throw InputError("--steps-scale: preset " + preset + "'s " + std::to_string(steps) +
                         " steps scale to more than " + std::to_string(kMaxSteps) +
                         ", the most a run accepts");
    return std::max(1, int(scaled));
}

// --size and --steps-scale applied to a preset. A coarse-to-fine schedule keeps
// its shape: every level is scaled by the same factor so the finest is --size,
// and the pattern's size relative to the image stays what the preset designed.
void applyOverrides(Session& s, const GalleryFlags& f) {
    const long long before = s.steps;
    if (!s.schedule.empty()) {
        std::vector<ScheduleLevel> levels = s.schedule;
        const ScheduleLevel finest = levels.back();
        for (ScheduleLevel& level : levels) {
            if (f.size > 0) {
                level.width =
                    std::max(1, int(std::lround(double(level.width) * f.size / finest.width)));
                level.height =
                    std::max(1, int(std::lround(double(level.height) * f.size / finest.height)));
            }
            level.steps = scaledSteps(level.steps, f.stepsScale, s.name);
        }
        applySchedule(s, std::move(levels));
    } else {
        if (f.size > 0)
            s.width = s.height = f.size;
        s.steps = scaledSteps(s.steps, f.stepsScale, s.name);
        // A cascade's steps are its stages' total: scale each stage instead
        // (a stage of 0 steps only freezes or resets, and stays so).
        if (!s.stages.empty()) {
            long long total = 0;
            for (Stage& stage : s.stages) {
                if (stage.steps > 0)
                    stage.steps = scaledSteps(stage.steps, f.stepsScale, s.name);
                total += stage.steps;
            }
            if (total > kMaxSteps)
                throw InputError("--steps-scale: preset " + s.name + "'s stages scale to " +
                                 std::to_string(total) + " steps in all, more than " +
                                 std::to_string(kMaxSteps));
            s.steps = int(total);
        }
    }
    // Strokes and other edits keep their place in the run: a stroke 80% of
    // the way through stays there (and one at the end stays at the end).
    if (before > 0 && s.steps != before)
        for (LiveEdit& e : s.edits)
            e.step = std::min<long long>(
                s.steps, std::llround(double(e.step) * double(s.steps) / double(before)));
    validateSession(s, "preset " + s.name);
}

// The presets --only names, in the built-in order; InputError naming every
// unknown name.
std::vector<Session> selectPresets(const std::string& only) {
    std::vector<Session> presets = allPresets();
    if (only.empty())
        return presets;
    std::vector<std::string> wanted, unknown;
    std::stringstream in(only);
    std::string item;
    while (std::getline(in, item, ',')) {
        const auto first = item.find_first_not_of(" \t");
        if (first == std::string::npos)
            continue;
        item = item.substr(first, item.find_last_not_of(" \t") - first + 1);
        const auto known = std::find_if(presets.begin(), presets.end(), [&](const Session& s) {
            return sameSpelling(s.name, item);
        });
        if (known != presets.end())
            wanted.push_back(known->name);
        else
            unknown.push_back(item);
    }
    if (!unknown.empty()) {
        std::vector<std::string> presetNames;
        for (const Session& s : presets)
            presetNames.push_back(s.name);
        std::string names;
        for (const std::string& u : unknown)
            names += (names.empty() ? "'" : ", '") + u + "'" + didYouMean(u, presetNames);
        throw InputError("--only: unknown preset " + names +
                         " (`morphogen presets` lists the built-in names)");
    }
    if (wanted.empty())
        throw InputError("--only '" + only + "' names no preset");
    presets.erase(std::remove_if(presets.begin(), presets.end(),
                                 [&](const Session& s) {
                                     return std::find(wanted.begin(), wanted.end(), s.name) ==
                                            wanted.end();
                                 }),
                  presets.end());
    return presets;
}

// Creates DIR if missing; InputError when it cannot be created or written.
void prepareDir(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw InputError("gallery folder '" + dir + "' cannot be created" +
                         (ec ? ": " + ec.message() : std::string(": not a folder")));
    checkWritable((fs::path(dir) / "index.html").string());
}

// "256x256, 10000 steps" or, coarse to fine, "256x256 -> 512x512, 16000 steps".
std::string sizeText(const Session& s, const char* arrow) {
    auto side = [](int w, int h) { return std::to_string(w) + "x" + std::to_string(h); };
    std::string text;
    for (const ScheduleLevel& level : s.schedule)
        text += (text.empty() ? "" : arrow) + side(level.width, level.height);
    if (text.empty())
        text = side(s.width, s.height);
    return text + ", " + std::to_string(s.steps) + " steps";
}

std::string seconds(double s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, s < 10 ? "%.2f s" : "%.1f s", s);
    return buffer;
}

std::string escapeHtml(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

// Self-contained: inline CSS, and the images and sessions are the files next
// to it, so the folder can be copied or served as it is.
void writeIndex(const std::string& dir, const std::vector<Entry>& entries, int total,
                const std::string& backend, const GalleryFlags& f) {
    std::ostringstream html;
    html << R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Morphogen gallery</title>
<style>
body { font-family: system-ui, sans-serif; margin: 1.5em; background: #111; color: #ddd; }
h1 { margin: 0 0 0.2em; }
.meta { color: #999; margin: 0.2em 0; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(220px, 1fr));
        gap: 1em; margin-top: 1.2em; }
figure { margin: 0; background: #1c1c1c; border-radius: 6px; padding: 0.6em; }
figure img { width: 100%; aspect-ratio: 1; object-fit: contain; display: block;
             background: #000; }
figcaption { font-size: 0.85em; margin-top: 0.5em; line-height: 1.35; }
figcaption b { font-size: 1.1em; color: #fff; }
.failed { border: 1px solid #a33; }
.error { color: #f77; white-space: pre-wrap; word-break: break-word; font-size: 0.95em; }
a { color: #8cf; }
</style>
</head>
<body>
<h1>Morphogen gallery</h1>
)";
    int failed = 0;
    for (const Entry& e : entries)
        failed += e.error.empty() ? 0 : 1;
    html << "<p class=\"meta\">Backend: " << escapeHtml(backend) << "</p>\n";
    std::string options;
    if (f.size > 0)
        options += " --size " + std::to_string(f.size);
    if (f.stepsScale != 1.0) {
        std::ostringstream os;
        os << f.stepsScale;
        options += " --steps-scale " + os.str();
    }
    html << "<p class=\"meta\">" << entries.size() << " presets rendered";
    if (failed)
        html << ", " << failed << " failed";
    if (int(entries.size()) < total)
        html << "; interrupted, " << total - int(entries.size()) << " not run";
    html << (options.empty() ? std::string(" at the presets' own sizes and steps")
                             : "; options:" + escapeHtml(options))
         << ". Each session JSON reproduces its image with <code>morphogen render --session "
            "NAME.json</code>.</p>\n<div class=\"grid\">\n";
    for (const Entry& e : entries) {
        const Session& s = e.session;
        const std::string name = escapeHtml(s.name);
        html << (e.error.empty() ? "<figure>\n" : "<figure class=\"failed\">\n");
        if (e.error.empty())
            html << "<a href=\"" << name << ".png\"><img src=\"" << name << ".png\" alt=\"" << name
                 << "\" loading=\"lazy\"></a>\n";
        html << "<figcaption><b>" << name << "</b> &middot; " << escapeHtml(s.model) << "<br>\n"
             << escapeHtml(s.description) << "<br>\n"
             << escapeHtml(sizeText(s, " \xe2\x86\x92 ")) << " &middot; " << seconds(e.seconds);
        if (e.error.empty())
            html << " &middot; <a href=\"" << name << ".json\">session</a>";
        else
            html << "\n<div class=\"error\">failed: " << escapeHtml(e.error) << "</div>";
        html << "</figcaption>\n</figure>\n";
    }
    html << "</div>\n</body>\n</html>\n";

    // Temporary file and rename: an interrupted write never leaves half a page.
    writeTextAtomically((fs::path(dir) / "index.html").string(), html.str());
}

// Runs one preset and writes its image and session; a failure is recorded in
// the entry, not thrown, so the other presets still run.
Entry runPreset(const Session& preset, const GalleryFlags& f, const gl::Backend& backend,
                const std::string& label, bool tty) {
    Entry entry;
    entry.session = preset;
    const auto start = std::chrono::steady_clock::now();
    std::optional<Progress> progress;
    try {
        applyOverrides(entry.session, f);
        checkStability(entry.session, false);
        // A redrawn progress line only where it helps: a terminal, and a
        // run long enough (~1e9 cell updates) to wait for.
        if (tty && double(entry.session.width) * entry.session.height * entry.session.steps >= 1e9)
            progress.emplace(label, entry.session.steps);
        RunOptions options;
        options.chunk = runChunk(entry.session);
        if (progress)
            options.progress = [&](int done, int) { progress->update(done); };
        // No cancel: Ctrl-C lets the current preset finish, so every
        // image on the page is the preset's full run.
        RunResult result = runSession(entry.session, backend.makeSimulator, options);
        entry.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const fs::path base = fs::path(f.dir) / entry.session.name;
        OutputFiles files; // the image and its session replace the previous pair together
        writeRenderOutput(result, base.string() + ".png", base.string() + ".json", 8, files);
        files.commit();
        entry.session = result.completed;
    } catch (const std::exception& e) {
        entry.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        entry.error = e.what();
    }
    const std::string summary =
        sizeText(entry.session, " -> ") + " ... " +
        (entry.error.empty() ? seconds(entry.seconds) : "FAILED: " + entry.error);
    if (progress)
        progress->finish(summary);
    else
        std::fprintf(stderr, "%s %s\n", label.c_str(), summary.c_str());
    return entry;
}

void gallery(const GalleryFlags& f) {
    if (f.size != -1 && (f.size < 1 || f.size > kMaxGridSide))
        throw InputError("--size " + std::to_string(f.size) + ": accepted are 1.." +
                         std::to_string(kMaxGridSide));
    if (!(f.stepsScale > 0) || !std::isfinite(f.stepsScale))
        throw InputError("--steps-scale must be a positive number");
    std::vector<Session> presets = selectPresets(f.only);
    // The gallery's pictures are flat; strokes placed on a model have nowhere to go there.
    for (auto it = presets.begin(); it != presets.end();)
        if (editsNeedTheModel(it->edits)) {
            std::fprintf(stderr,
                         "morphogen: gallery leaves out %s: its strokes are on its model (render "
                         "it with: morphogen render --preset %s --out %s.png)\n",
                         it->name.c_str(), it->name.c_str(), it->name.c_str());
            it = presets.erase(it);
        } else {
            ++it;
        }
    // Every preset's overrides are checked before the first one runs: when
    // none takes them, the flags are wrong (exit 2, nothing written); a
    // preset that alone refuses them is run as failed, listed on the page.
    std::string firstRefusal;
    int refused = 0;
    for (const Session& preset : presets) {
        Session s = preset;
        try {
            applyOverrides(s, f);
        } catch (const InputError& e) {
            if (refused++ == 0)
                firstRefusal = e.what();
        }
    }
    if (!presets.empty() && refused == int(presets.size()))
        throw InputError(refused == 1
                             ? firstRefusal
                             : "no preset takes these options; the first: " + firstRefusal);
    const gl::BackendChoice choice = gl::parseBackendChoice(f.backend);
    const auto contextKind = gl::parseContextFlag(f.context);
    const auto gpuDevice = gl::parseGpuDeviceFlag(f.gpuDevice);
    prepareDir(f.dir);

    gl::Backend backend = gl::makeBackend(choice, contextKind, gpuDevice);
    std::fprintf(stderr, "morphogen: %s\n", backend.reason.c_str());

    const bool tty = isatty(STDERR_FILENO) != 0;
    const int total = int(presets.size());
    std::vector<Entry> entries;
    {
        const InterruptGuard interrupt(
            "\nmorphogen: interrupted: finishing the current preset, then writing index.html "
            "(Ctrl-C again, a second or more later, to quit now)\n");
        for (int i = 0; i < total && !interrupt.cancelled(); ++i) {
            const std::string label = "gallery " + std::to_string(i + 1) + "/" +
                                      std::to_string(total) + " " + presets[std::size_t(i)].name;
            entries.push_back(runPreset(presets[std::size_t(i)], f, backend, label, tty));
        }
    }

    writeIndex(f.dir, entries, total, backend.reason, f);
    const std::string index = (fs::path(f.dir) / "index.html").string();
    std::printf("%s\n", index.c_str());

    std::string failedNames;
    int failed = 0;
    for (const Entry& e : entries)
        if (!e.error.empty()) {
            failedNames += (failed++ ? ", " : "") + e.session.name;
        }
    if (int(entries.size()) < total)
        throw std::runtime_error("interrupted after " + std::to_string(entries.size()) + " of " +
                                 std::to_string(total) + " presets; " + index +
                                 " lists the finished ones");
    if (failed)
        throw std::runtime_error(std::to_string(failed) + " of " + std::to_string(total) +
                                 " presets failed (" + failedNames + "); " + index +
                                 " lists their errors");
}

} // namespace

void addGalleryCommand(CLI::App& app) {
    auto flags = std::make_shared<GalleryFlags>();
    CLI::App* cmd = app.add_subcommand(
        "gallery", "Render every built-in preset into DIR (NAME.png + NAME.json, the session that "
                   "reproduces it) and write DIR/index.html, a page of thumbnails");
    cmd->add_option("DIR", flags->dir, "output folder (created if missing)")->required();
    // The range check also refuses -1, the value that stands for "not given".
    cmd->add_option("--size", flags->size,
                    "grid size N, 1.." + std::to_string(kMaxGridSide) +
                        ", for every preset (coarse-to-fine schedules are scaled so the finest "
                        "level is N)")
        ->check(CLI::Range(1, kMaxGridSide));
    cmd->add_option("--steps-scale", flags->stepsScale,
                    "multiply every preset's steps (at least 1 per level, at most " +
                        std::to_string(kMaxSteps) + " in all; default 1)");
    cmd->add_option("--backend", flags->backend, "auto, gpu or cpu (default auto)");
    cmd->add_option(
        "--context", flags->context,
        "GL context: egl or osmesa (default: $MORPHOGEN_CONTEXT, else egl then osmesa)");
    cmd->add_option(
        "--gpu-device", flags->gpuDevice,
        "EGL display number (default: $MORPHOGEN_GPU_DEVICE, else the first hardware renderer)");
    cmd->add_option("--only", flags->only, "comma-separated preset names (default: all)");
    cmd->callback([flags] { gallery(*flags); });
}

} // namespace morphogen::cli
