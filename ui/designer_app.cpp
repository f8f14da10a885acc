#include "ui/designer_app.hpp"
#include "ui/crash_recovery.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <glad/gl.h>
// GLFW after glad: glad provides the GL declarations.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "core/output/frames.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_glb.hpp"
#include "ui/script.hpp"

namespace morphogen::ui {

namespace {

namespace fs = std::filesystem;
constexpr double kFrameBudget = 1.0 / 60.0; // seconds: the auto steps-per-frame target
constexpr const char* kDefaultPreset = "gs_coral";

} // namespace

void Designer::guarded(const char* what, const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        reportError(std::string(what) + ": " + e.what());
    }
}

namespace {

void removeStaleHistory(const std::string& stateDir) {
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(stateDir, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("history-", 0) != 0)
            continue;
        char* end = nullptr;
        const long pid = std::strtol(name.c_str() + 8, &end, 10);
        if (pid > 0 && *end == 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
            fs::remove_all(e.path(), ec);
    }
}

} // namespace

Designer::Designer(const DesignerOptions& options, const DesignerServices& services)
    : m_options(options), m_services(services),
      m_settings(Settings::load(options.configDir, options.stateDir)),
      m_doc([this](const Session& s) { return m_backend.makeSimulator(s); }) {
    m_window = gl::createGlfwContext(options.width > 0 ? options.width : m_settings.windowWidth,
                                     options.height > 0 ? options.height : m_settings.windowHeight,
                                     "Morphogen designer", true);
    m_backend = gl::makeBackend(gl::parseBackendChoice(options.backend), *m_window);
    std::fprintf(stderr, "morphogen design: %s\n", m_backend.reason.c_str());
    m_controlsWidth = m_settings.controlsWidth;
    m_sideWidth = m_settings.sideWidth;
    // Growth history past its memory budget goes to disk, one folder per
    // designer process (removed at exit), next to the autosave. A crashed
    // designer's folder is removed by the next one.
    removeStaleHistory(m_settings.stateDir);
    m_doc.setHistorySpill(
        (fs::path(m_settings.stateDir) / ("history-" + std::to_string(::getpid()))).string(),
        kHistoryDiskBudget);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    static std::string iniPath; // Dear ImGui keeps the pointer
    iniPath = m_settings.imguiIniPath();
    std::error_code ec;
    fs::create_directories(m_settings.configDir, ec);
    io.IniFilename = iniPath.c_str();
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0;
    ImGui_ImplGlfw_InitForOpenGL(m_window->window(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    // Software rasterizers redraw only what changed (partial_redraw.hpp);
    // MORPHOGEN_FULL_REDRAW=1 draws every frame whole, to compare.
    const char* full = std::getenv("MORPHOGEN_FULL_REDRAW");
    if (m_window->isSoftwareRenderer() && !(full && *full && std::string(full) != "0"))
        m_redraw = std::make_unique<PartialRedraw>(std::vector<std::string>{"Canvas", "Model"},
                                                   std::vector<std::string>{"Canvas"});

    // A crash (or a kill) leaves its autosave behind: kept aside before this
    // run autosaves anything, and offered back.
    m_recovered = keepCrashedAutosaves(m_settings.stateDir);
    m_offerRestore = options.script.empty() && !m_recovered.empty();

    // What to open: the command line's choice, else the session open at the
    // last exit, else the default preset.
    if (!options.session.empty())
        openSessionFile(options.session);
    else if (!options.preset.empty())
        openPreset(options.preset);
    else
        openRemembered();
    if (!m_doc.isOpen() && !m_job)
        openPreset(kDefaultPreset);

    std::vector<Session> presets = allPresets();
    m_thumbnails.start(std::move(presets), m_settings.cacheDir);
    m_lastFrame = m_lastRate = m_lastAutosave = Clock::now();
}

Designer::~Designer() {
    if (m_job && m_job->worker.joinable()) {
        m_job->cancel = true;
        m_job->worker.join();
    }
    m_display.reset();
    m_modelRenderer.reset(); // GL objects go while the context lives
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void Designer::reportError(const std::string& message) {
    m_lastError = message;
    m_status = message;
    ++m_errorCount;
    std::fprintf(stderr, "morphogen design: %s\n", message.c_str());
}

// --- actions --------------------------------------------------------------------

void Designer::openPreset(const std::string& name) {
    guarded("open preset", [&] { openPresetOrThrow(name); });
}

void Designer::openPresetOrThrow(const std::string& name) {
    Session preset = loadPreset(name);
    m_settings.lastPreset = name;
    if (preset.surface.active()) {
        openSurfaceSession(std::move(preset), "", 0);
        return;
    }
    m_doc.open(std::move(preset));
    m_surface.reset();
    m_replayTo = 0;
    m_settings.lastPreset = name;
    m_settings.lastSession.clear();
    m_viewFramed = false;
    m_displayChemical = -1;
    m_status = "opened preset " + name;
}

void Designer::openSessionFile(const std::string& path) {
    guarded("open", [&] { openSessionFileOrThrow(path); });
}

void Designer::openSessionFileOrThrow(const std::string& path) {
    Session session = loadSessionFile(path);
    const long long steps = session.steps;
    if (session.surface.active()) {
        openSurfaceSession(std::move(session), path, steps);
        return;
    }
    m_doc.open(std::move(session), path);
    m_surface.reset();
    m_replayTo = steps;
    m_settings.lastSession = fs::absolute(path).string();
    m_settings.lastFolder = fs::absolute(path).parent_path().string();
    m_viewFramed = false;
    m_displayChemical = -1;
    m_status = "opened " + path;
}

void Designer::saveSession(const std::string& path) {
    guarded("save", [&] {
        m_doc.save(path);
        m_settings.lastSession = fs::absolute(path).string();
        m_settings.lastFolder = fs::absolute(path).parent_path().string();
        m_status = "saved " + path + " (step " + std::to_string(m_doc.steps()) + ")";
    });
}

void Designer::exportImage(const std::string& path, int bitDepth) {
    guarded("export", [&] {
        RunResult result;
        result.state = m_doc.run().state();
        result.completed = m_doc.completed();
        result.stepsDone = int(m_doc.steps());
        const std::string sessionPath = fs::path(path).replace_extension(".json").string();
        m_services.writeImage(result, path, sessionPath, bitDepth);
        m_status = "exported " + path + " and " + sessionPath;
    });
}

void Designer::exportTextureSet(const std::string& dir) {
    guarded("export texture set", [&] {
        RunResult result;
        result.state = m_doc.run().state();
        result.completed = m_doc.completed();
        m_services.writeTextureSet(result, dir);
        m_status = "wrote the texture set in " + dir;
    });
}

void Designer::exportModel(const std::string& path) {
    guarded("export model", [&] {
        if (!m_surface)
            throw InputError("the open session grows on a flat canvas: a model (GLB) export "
                             "needs a session on a mesh");
        Session shown = m_doc.live();
        shown.colormap = m_doc.liveColormap();
        const SurfaceColours c = surfaceColours(m_doc.run().state(), shown, *shown.atlas);
        writeTexturedGlb(texturedSurface(m_surface->tiles, c), path);
        saveSessionFile(m_doc.completed(), fs::path(path).replace_extension(".json").string());
        m_status = "exported " + path;
    });
}

void Designer::recordFrames(const std::string& dir, int every) {
    guarded("record", [&] {
        if (dir.empty()) {
            if (!m_recordDir.empty())
                m_status =
                    "recorded " + std::to_string(m_recordIndex) + " frames in " + m_recordDir;
            m_recordDir.clear();
            return;
        }
        if (every < 1)
            throw InputError("frames every " + std::to_string(every) + " steps: give 1 or more");
        fs::create_directories(dir);
        m_recordDir = dir;
        m_recordEvery = every;
        m_recordIndex = 0;
        m_recordNext = m_doc.steps();
        m_status = "recording frames in " + dir;
    });
}

void Designer::writeRecordedFrame() {
    bool written = false;
    guarded("record", [&] {
        const State state = m_doc.run().state();
        const std::vector<float> rgb =
            applyColormap(state, m_doc.liveChemical(),
                          colormapOn(m_doc.liveColormap(), m_doc.live()), m_doc.live().edges);
        writeRgbImage(framePath(m_recordDir, m_recordIndex++), rgb, state.width(), state.height(),
                      8);
        written = true;
    });
    if (!written)
        m_recordDir.clear(); // a failing folder stops the recording, said once
}

void Designer::exportAtSize(const std::string& path, int width, int height, int bitDepth) {
    if (m_job) {
        reportError("an export is already running");
        return;
    }
    Session session = m_doc.completed();
    guarded("export", [&] {
        if (width < 1 || height < 1 || width > kMaxGridSide || height > kMaxGridSide)
            throw InputError("export size " + std::to_string(width) + " x " +
                             std::to_string(height) + " is outside 1.." +
                             std::to_string(kMaxGridSide));
        resizeSession(session, width, height);
        checkWritable(path);
        m_job = std::make_unique<BackgroundJob>();
    });
    if (!m_job)
        return;
    m_job->title = "Exporting " + fs::path(path).filename().string() + " at " +
                   std::to_string(width) + " x " + std::to_string(height);
    BackgroundJob* job = m_job.get();
    DesignerServices services = m_services;
    // The CPU backend on a worker thread: the window's GL context belongs to
    // the main thread, which keeps drawing (and the live run keeps going).
    job->worker = std::thread([job, services, session, path, bitDepth] {
        try {
            RunOptions options;
            options.cancel = &job->cancel;
            options.progress = [job](int done, int total) {
                job->done = done;
                job->total = std::max(total, 1);
            };
            const SimulatorFactory cpu = [](const Session& s) {
                return std::make_unique<CpuSimulator>(s);
            };
            const RunResult result = runSession(session, cpu, options);
            if (result.cancelled) {
                job->message = "export cancelled: nothing written";
            } else {
                const std::string sessionPath = fs::path(path).replace_extension(".json").string();
                services.writeImage(result, path, sessionPath, bitDepth);
                job->message = "exported " + path;
            }
        } catch (const std::exception& e) {
            job->message = std::string("export failed: ") + e.what();
        }
        job->finished = true;
    });
}

void Designer::openSurfaceSession(Session session, const std::string& path, long long replayTo) {
    if (m_job) {
        reportError("wait for the running job to finish (or cancel it)");
        return;
    }
    m_job = std::make_unique<BackgroundJob>();
    m_job->title = "Building the surface tiles of " + session.surface.mesh;
    m_job->total = 1000;
    BackgroundJob* job = m_job.get();
    auto prepared = std::make_shared<Session>(std::move(session));
    auto setup = std::make_shared<SurfaceSetup>();
    // GL-free (mesh, simplification, tiles, metric): a worker thread. Cancel
    // abandons the result; the worker finishes the phase it is in.
    job->worker = std::thread([job, prepared, setup] {
        try {
            *setup = setUpSurface(*prepared, [job](const std::string&, double fraction) {
                job->done = int(fraction * 1000);
            });
            job->message = "built " + std::to_string(setup->tiles.atlas->tileCount()) + " tiles";
        } catch (const std::exception& e) {
            job->message = std::string("could not build the surface: ") + e.what();
        }
        job->finished = true;
    });
    // `job` is gone when finish runs: it reads the message through the capture.
    job->finish = [this, prepared, setup, path, replayTo, message = &job->message] {
        if (!setup->tiles.atlas)
            throw InputError(*message);
        m_doc.open(*prepared, path);
        m_surface = setup;
        m_replayTo = replayTo;
        m_viewFramed = false;
        m_modelStale = true;
        m_displayChemical = -1;
        if (!path.empty()) {
            m_settings.lastSession = fs::absolute(path).string();
            m_settings.lastFolder = fs::absolute(path).parent_path().string();
        }
    };
}

void Designer::screenshot(const std::string& path) {
    m_pendingScreenshot = path;
}

void Designer::openRemembered() {
    // designer.json may name a session that has since been moved or broken,
    // or a preset this version lacks. That is no error of this run's: the
    // default opens instead, and the window says why (a script goes on).
    const std::string session = m_settings.lastSession;
    const std::string preset = m_settings.lastPreset;
    std::string why;
    try {
        if (!session.empty()) {
            if (!fs::exists(session))
                throw InputError(session + ": not found");
            openSessionFileOrThrow(session);
        } else if (!preset.empty()) {
            openPresetOrThrow(preset);
        } else {
            openPreset(kDefaultPreset);
        }
        return;
    } catch (const std::exception& e) {
        why = e.what();
    }
    m_settings.lastSession.clear();
    m_settings.lastPreset.clear();
    openPreset(kDefaultPreset);
    m_startupNotice = "could not reopen the last " +
                      std::string(session.empty() ? "preset" : "session") + " (" + why +
                      "); opened " + kDefaultPreset + " instead";
    m_status = m_startupNotice;
    std::fprintf(stderr, "morphogen design: %s\n", m_startupNotice.c_str());
}

void Designer::restoreAutosave() {
    if (m_recovered.empty()) {
        reportError("there is no crashed session to restore (none in " + m_settings.stateDir + ")");
        return;
    }
    guarded("restore", [&] {
        // Out of the offer first, so it is never offered (or lost) twice.
        const std::string restored = markRestored(m_recovered.front());
        m_recovered.erase(m_recovered.begin());
        openSessionFile(restored);
        if (m_doc.isOpen())
            m_status = "restored the crashed session (kept as " + restored + ")";
    });
}

void Designer::discardRecovered() {
    if (m_recovered.empty())
        return;
    std::error_code ec;
    fs::remove(m_recovered.front(), ec);
    m_recovered.erase(m_recovered.begin());
}

void Designer::stepOnce() {
    m_playing = false;
    guarded("step", [&] { advance(1); });
}

void Designer::reset() {
    guarded("reset", [&] {
        m_doc.reset();
        m_scrub.reset();
    });
}

void Designer::reseed() {
    guarded("reseed", [&] {
        m_doc.reseed(m_doc.session().seed + 1);
        m_scrub.reset();
    });
}

void Designer::undo() {
    if (m_doc.stroking())
        return;
    guarded("undo", [&] {
        m_status = "undid " + m_doc.undoLabel();
        m_doc.undo();
    });
}

void Designer::redo() {
    if (m_doc.stroking())
        return;
    guarded("redo", [&] {
        m_status = "redid " + m_doc.redoLabel();
        m_doc.redo();
    });
}

void Designer::changeParam(const std::string& name, float value) {
    guarded("parameter",
            [&] { m_doc.changeOnce("change " + name, [&] { m_doc.setParam(name, value); }); });
}

void Designer::setStepsPerFrame(int steps) {
    m_stepsPerFrame = std::max(0, steps);
}

// --- the frame ------------------------------------------------------------------

int Designer::run(ScriptPlayer* script) {
    while (!m_quit && !m_window->shouldClose()) {
        const Clock::time_point start = Clock::now();
        glfwPollEvents();
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        if (script)
            script->beforeFrame(*this);
        ImGui::NewFrame();
        const Clock::time_point built = Clock::now();
        m_frameTimes.events += seconds(built - start);
        frame(); // adds its simulate and display times
        ImGui::Render();
        const Clock::time_point rendered = Clock::now();
        m_frameTimes.interface += seconds(rendered - built);
        const auto [fw, fh] = m_window->framebufferSize();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, fw, fh);
        // The panels draw no background of their own (see beginPanel): the
        // clear gives it, as the window colour over the old clear colour.
        const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
        const std::array<float, 4> clear = {bg.x * bg.w + 0.09f * (1 - bg.w),
                                            bg.y * bg.w + 0.09f * (1 - bg.w),
                                            bg.z * bg.w + 0.1f * (1 - bg.w), 1.0f};
        if (m_redraw) {
            m_redraw->render(ImGui::GetDrawData(), clear, fw, fh, !m_pendingScreenshot.empty());
        } else {
            glClearColor(clear[0], clear[1], clear[2], clear[3]);
            glClear(GL_COLOR_BUFFER_BIT);
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        }
        if (!m_pendingScreenshot.empty())
            writeScreenshot();
        const Clock::time_point drawn = Clock::now();
        m_frameTimes.draw += seconds(drawn - rendered);
        if (script) {
            script->afterFrame(*this);
            if (script->failed())
                m_quit = true;
        }
        m_window->swapBuffers();
        m_frameTimes.present += seconds(Clock::now() - drawn);
        ++m_frameTimes.frames;
    }
    autosave(true);
    // A clean exit: the session goes to last-exit.json, the crash marker away.
    std::error_code ec;
    if (fs::exists(m_settings.autosavePath(), ec)) {
        fs::rename(m_settings.autosavePath(), m_settings.lastExitPath(), ec);
    }
    int w = 0, h = 0;
    glfwGetWindowSize(m_window->window(), &w, &h);
    if (w > 0 && h > 0) {
        m_settings.windowWidth = w;
        m_settings.windowHeight = h;
    }
    m_settings.controlsWidth = m_controlsWidth;
    m_settings.sideWidth = m_sideWidth;
    if (script == nullptr)
        m_settings.save();
    return script && script->failed() ? 1 : 0;
}

std::string Designer::backendName() {
    return m_doc.isOpen() && !m_doc.run().finished() ? m_doc.run().simulator().backendName() : "-";
}

void Designer::frame() {
    const Clock::time_point now = Clock::now();
    const double frameSeconds = seconds(now - m_lastFrame);
    m_lastFrame = now;
    ++m_framesSinceRate;
    if (seconds(now - m_lastRate) >= 0.5) {
        const double span = seconds(now - m_lastRate);
        m_fps = m_framesSinceRate / span;
        m_stepsPerSecond = double(m_stepsRun - m_stepsAtLastRate) / span;
        m_stepsAtLastRate = m_stepsRun;
        m_framesSinceRate = 0;
        m_lastRate = now;
    }
    (void)frameSeconds;

    // The interface's time is the frame's less these two (see run).
    const Clock::time_point start = Clock::now();
    simulate();
    const Clock::time_point simulated = Clock::now();
    handleShortcuts();
    refreshDisplay();
    const double display = seconds(Clock::now() - simulated);
    m_frameTimes.simulate += seconds(simulated - start);
    m_frameTimes.display += display;
    m_frameTimes.interface -= seconds(simulated - start) + display;

    const ImGuiIO& io = ImGui::GetIO();
    const float menuHeight = ImGui::GetFrameHeight();
    const float statusHeight = ImGui::GetFrameHeight() + 6;
    const float width = io.DisplaySize.x, height = io.DisplaySize.y;
    drawMenuBar();
    const float bodyTop = menuHeight, bodyHeight = height - menuHeight - statusHeight;
    m_controlsWidth = std::clamp(m_controlsWidth, 200.0f, std::max(200.0f, width * 0.45f));
    m_sideWidth = std::clamp(m_sideWidth, 150.0f, std::max(150.0f, width * 0.35f));
    drawControls(0, bodyTop, m_controlsWidth, bodyHeight);
    // A session on a mesh shows its atlas and the model side by side (or either alone).
    const float centreWidth = width - m_controlsWidth - m_sideWidth;
    if (m_surface && m_viewMode == 0) {
        drawCanvas(m_controlsWidth, bodyTop, centreWidth / 2, bodyHeight);
        drawModelView(m_controlsWidth + centreWidth / 2, bodyTop, centreWidth / 2, bodyHeight);
    } else if (m_surface && m_viewMode == 2) {
        drawModelView(m_controlsWidth, bodyTop, centreWidth, bodyHeight);
    } else {
        drawCanvas(m_controlsWidth, bodyTop, centreWidth, bodyHeight);
    }
    drawSidePanel(width - m_sideWidth, bodyTop, m_sideWidth, bodyHeight);
    drawStatusBar(height - statusHeight, statusHeight);
    drawPopups();
    drawJob();
    autosave(false);
}

void Designer::advance(int steps) {
    const long long before = m_doc.steps();
    m_doc.advance(steps); // a throw loses this call's count: the rates are a display figure
    m_stepsRun += std::max(0LL, m_doc.steps() - before);
}

void Designer::simulate() {
    if (!m_doc.isOpen() || m_doc.run().finished())
        return;
    if (m_replayTo > m_doc.steps()) {
        // As many steps as fit a frame's budget, then the next frame.
        const Clock::time_point start = Clock::now();
        bool failed = true;
        guarded("replay", [&] {
            while (m_replayTo > m_doc.steps() && seconds(Clock::now() - start) < kFrameBudget)
                advance(int(std::min<long long>(m_replayTo - m_doc.steps(), 50)));
            failed = false;
        });
        if (m_replayTo <= m_doc.steps() || failed) {
            m_replayTo = 0;
            m_playing = false; // the saved picture, until the artist plays on
        }
        return;
    }
    if (!m_playing || m_scrub)
        return;
    int steps = m_stepsPerFrame > 0 ? m_stepsPerFrame : m_autoSteps;
    const Clock::time_point start = Clock::now();
    try {
        advance(steps);
        // The run's own blow-up check is off (it reads the whole state back
        // every chunk); one check per second of frames is enough to stop.
        if (m_framesSinceRate == 0) {
            if (auto problem = m_doc.run().simulator().insaneValue(m_doc.live().reactionModel())) {
                m_playing = false;
                reportError("the simulation blew up (" + *problem +
                            "): lower dt, undo the last change, or reset");
            }
        }
    } catch (const std::exception& e) {
        m_playing = false;
        reportError(e.what());
    }
    m_simSeconds = seconds(Clock::now() - start);
    if (!m_recordDir.empty() && m_doc.steps() >= m_recordNext) {
        writeRecordedFrame();
        m_recordNext = m_doc.steps() + m_recordEvery;
    }
    if (m_stepsPerFrame == 0) {
        // Keep a frame within its budget: grow the steps while the
        // simulation takes less than ~70% of it, shrink them when it takes more.
        if (m_simSeconds < kFrameBudget * 0.5)
            m_autoSteps = std::min(m_autoSteps + std::max(1, m_autoSteps / 4), 4096);
        else if (m_simSeconds > kFrameBudget * 0.7)
            m_autoSteps = std::max(1, m_autoSteps * 3 / 4);
    }
    if (m_doc.steps() - (m_doc.history().empty() ? 0 : m_doc.history().lastStep()) >=
        m_snapshotEvery)
        m_doc.recordSnapshot();
}

void Designer::refreshDisplay() {
    if (!m_doc.isOpen())
        return;
    const Session& live = m_doc.live();
    if (!m_display || m_display->texture().width() != live.width ||
        m_display->texture().height() != live.height) {
        m_display = std::make_unique<gl::Display>(live.width, live.height);
        m_viewFramed = false;
    }
    const ReactionModel& model = live.reactionModel();
    const int chemical = m_displayChemical >= 0 && m_displayChemical < int(model.chemicals().size())
                             ? m_displayChemical
                             : m_doc.liveChemical();
    ColorMapSpec spec = m_doc.liveColormap();
    if (m_colormapDraft) {
        spec.edgeDarkening = m_colormapDraft->edgeDarkening;
        spec.edgeWidth = m_colormapDraft->edgeWidth;
    }
    spec = colormapOn(spec, live);
    guarded("display", [&] {
        if (m_scrub && *m_scrub < m_doc.history().size())
            m_display->upload(m_doc.history().state(*m_scrub), chemical, spec, live.edges);
        else
            m_display->update(m_doc.run().simulator(), chemical, spec, live.edges);
    });
}

void Designer::handleShortcuts() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput)
        return;
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Z, false))
        shift ? redo() : undo();
    else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_Y, false))
        redo();
    else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_S, false)) {
        if (!m_doc.path().empty() && !shift)
            saveSession(m_doc.path());
        else
            m_showSave = true;
    } else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_O, false))
        m_showOpen = true;
    else if (ctrl && ImGui::IsKeyPressed(GLFW_KEY_E, false))
        m_showExport = true;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_SPACE, false))
        m_playing = !m_playing;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_PERIOD, true))
        stepOnce();
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_R, false))
        shift ? reseed() : reset();
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_F, false))
        m_viewFramed = false;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_T, false))
        m_tiled = !m_tiled;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_LEFT_BRACKET, true))
        m_brush.radius = std::max(0.002f, m_brush.radius / 1.2f);
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_RIGHT_BRACKET, true))
        m_brush.radius = std::min(0.5f, m_brush.radius * 1.2f);
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_1, false))
        m_viewMode = 0;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_2, false))
        m_viewMode = 1;
    else if (!ctrl && ImGui::IsKeyPressed(GLFW_KEY_3, false))
        m_viewMode = 2;
    else if (ImGui::IsKeyPressed(GLFW_KEY_F1, false))
        m_showHelp = !m_showHelp;
}

void Designer::drawMenuBar() {
    if (!ImGui::BeginMainMenuBar())
        return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open session...", "Ctrl+O"))
            m_showOpen = true;
        if (ImGui::MenuItem("Save session", "Ctrl+S", false, !m_doc.path().empty()))
            saveSession(m_doc.path());
        if (ImGui::MenuItem("Save session as...", "Ctrl+Shift+S"))
            m_showSave = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Export...", "Ctrl+E"))
            m_showExport = true;
        ImGui::Separator();
        if (ImGui::MenuItem("Quit"))
            m_quit = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem(("Undo " + m_doc.undoLabel()).c_str(), "Ctrl+Z", false,
                            m_doc.canUndo()))
            undo();
        if (ImGui::MenuItem(("Redo " + m_doc.redoLabel()).c_str(), "Ctrl+Shift+Z", false,
                            m_doc.canRedo()))
            redo();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Simulation")) {
        if (ImGui::MenuItem(m_playing ? "Pause" : "Play", "Space"))
            m_playing = !m_playing;
        if (ImGui::MenuItem("Single step", "."))
            stepOnce();
        if (ImGui::MenuItem("Reset", "R"))
            reset();
        if (ImGui::MenuItem("Reseed", "Shift+R"))
            reseed();
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        if (ImGui::MenuItem("Frame canvas", "F"))
            m_viewFramed = false;
        ImGui::MenuItem("Tiled 3x3 preview", "T", &m_tiled);
        ImGui::MenuItem("Nearest texels when zoomed in", nullptr, &m_nearest);
        ImGui::Separator();
        if (ImGui::MenuItem("Canvas and model", "1", m_viewMode == 0, m_surface != nullptr))
            m_viewMode = 0;
        if (ImGui::MenuItem("Canvas only", "2", m_viewMode == 1, m_surface != nullptr))
            m_viewMode = 1;
        if (ImGui::MenuItem("Model only", "3", m_viewMode == 2, m_surface != nullptr))
            m_viewMode = 2;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Help")) {
        if (ImGui::MenuItem("Keyboard shortcuts", "F1"))
            m_showHelp = true;
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void Designer::drawStatusBar(float y, float h) {
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, y));
    ImGui::SetNextWindowSize(ImVec2(io.DisplaySize.x, h));
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
    const std::string backend = backendName();
    ImGui::Text("%s | step %lld | %.0f fps | %.0f steps/s | %d steps/frame%s | backend %s%s",
                m_playing ? "running" : "paused", m_doc.isOpen() ? m_doc.steps() : 0LL, m_fps,
                m_stepsPerSecond, m_stepsPerFrame > 0 ? m_stepsPerFrame : m_autoSteps,
                m_stepsPerFrame > 0 ? "" : " (auto)", backend.c_str(),
                m_doc.dirty() ? " | unsaved changes" : "");
    if (!m_recordDir.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1, 0.3f, 0.3f, 1), "| REC %d frames", m_recordIndex);
    }
    if (const LocalRegrowth* r =
            m_doc.isOpen() && !m_doc.run().finished() ? m_doc.run().regrowth() : nullptr) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(1, 0.62f, 0.25f, 1), "| re-growing A%d: %d of %d tiles",
                           r->phase(), int(r->tiles().size()), r->tileCount());
    }
    if (!m_status.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(m_status == m_lastError ? ImVec4(1, 0.45f, 0.4f, 1)
                                                   : ImVec4(0.6f, 0.8f, 1, 1),
                           " | %s", m_status.c_str());
    }
    ImGui::End();
}

void Designer::drawJob() {
    if (m_replayTo > 0) {
        const ImGuiIO& io = ImGui::GetIO();
        ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x / 2, io.DisplaySize.y / 2),
                                ImGuiCond_Always, ImVec2(0.5f, 0.5f));
        ImGui::Begin("Replaying", nullptr,
                     ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize);
        ImGui::Text("Replaying the saved session to step %lld", m_replayTo);
        ImGui::ProgressBar(float(m_doc.steps()) / float(m_replayTo), ImVec2(360, 0));
        if (ImGui::Button("Stop here"))
            m_replayTo = 0;
        ImGui::End();
    }
    if (!m_job)
        return;
    if (m_job->finished) {
        m_job->worker.join();
        m_status = m_job->message;
        std::unique_ptr<BackgroundJob> job = std::move(m_job);
        if (job->finish && !job->cancel)
            guarded("open", job->finish);
        return;
    }
    ImGui::OpenPopup("Working");
    if (ImGui::BeginPopupModal("Working", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(m_job->title.c_str());
        const float fraction = float(m_job->done.load()) / float(std::max(1, m_job->total.load()));
        ImGui::ProgressBar(fraction, ImVec2(360, 0));
        if (ImGui::Button("Cancel"))
            m_job->cancel = true;
        ImGui::EndPopup();
    }
}

void Designer::autosave(bool force) {
    if (!m_doc.isOpen() || !m_doc.dirty())
        return;
    const Clock::time_point now = Clock::now();
    if (!force && seconds(now - m_lastAutosave) < m_options.autosaveSeconds)
        return;
    m_lastAutosave = now;
    try {
        fs::create_directories(m_settings.stateDir);
        saveSessionFile(m_doc.completed(), m_settings.autosavePath());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "morphogen design: autosave failed: %s\n", e.what());
    }
}

void Designer::writeScreenshot() {
    const std::string path = std::exchange(m_pendingScreenshot, "");
    guarded("screenshot", [&] {
        const auto [w, h] = m_window->framebufferSize();
        std::vector<unsigned char> rgba(std::size_t(w) * h * 4);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        std::vector<float> rgb(std::size_t(w) * h * 3);
        for (int y = 0; y < h; ++y) // GL's rows run bottom up
            for (int x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    rgb[(std::size_t(y) * w + x) * 3 + c] =
                        rgba[(std::size_t(h - 1 - y) * w + x) * 4 + c] / 255.0f;
        writeRgbImage(path, rgb, w, h, 8);
        m_status = "screenshot " + path;
    });
}

int runDesigner(const DesignerOptions& options, const DesignerServices& services) {
    std::unique_ptr<ScriptPlayer> script;
    if (!options.script.empty())
        script = std::make_unique<ScriptPlayer>(loadScript(options.script));
    Designer designer(options, services);
    return designer.run(script.get());
}

} // namespace morphogen::ui
