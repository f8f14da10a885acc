#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "core/surface/surface_setup.hpp"
#include "gl/backend.hpp"
#include "gl/display.hpp"
#include "gl/glfw_context.hpp"
#include "gl/surface_view.hpp"
#include "ui/canvas_view.hpp"
#include "ui/designer.hpp"
#include "ui/document.hpp"
#include "ui/partial_redraw.hpp"
#include "ui/settings.hpp"
#include "ui/thumbnails.hpp"

namespace morphogen::ui {

class ScriptPlayer;

// The brush panel's settings; a stroke copies them (StrokeSpec).
struct BrushSettings {
    BrushMode mode = BrushMode::Add;
    int chemical = -1; // -1: the model's display chemical
    std::string param; // paint
    float value = 0.5f;
    float radius = 0.03f; // fraction of the canvas width
    float falloff = 0.5f;
    std::uint64_t seed = 1;
    bool localized = true; // on a model: re-grow locally after a stroke (Lo's localized RD)
    // On a model: a left drag deforms instead of painting (Lo 5.5): the slab
    // at the drag's start, along the drag, half width the brush radius,
    // stretched by `stretch` (below 1 compresses); within the brush radius of
    // the drag's line (fading out beyond it, SlabStretch), or, `across`, the
    // whole slab across the model.
    bool deform = false;
    float stretch = 1.5f;
    bool across = false;
    // A model with water "w" and pigments (watercolour): a stroke lays water
    // and a pigment together (the session's "strokes" sugar, live).
    bool watercolour = true;
    float water = 1.0f;
    std::string pigment = "p1";
};

// A long job on a worker thread (an export at a large size): progress for
// the bar, a flag to cancel it, its message when it ends.
struct BackgroundJob {
    std::string title;
    std::thread worker;
    std::atomic<int> done{0}, total{1};
    std::atomic<bool> cancel{false}, finished{false};
    std::string message; // written by the worker before `finished`
    // Run on the main thread once the worker has finished (the worker's
    // result goes into the window's state there), unless it was cancelled.
    std::function<void()> finish;
};

// One axis of the parameter-map panel.
struct MapAxis {
    std::string param;
    float min = 0, max = 1;
};

// The designer's 3D view: an orbit camera round the model's bounding sphere.
struct Orbit {
    double azimuth = 30, elevation = 20;
    double distance = 0; // bounding-sphere radii; 0: framed
};

// The designer: one window, the document, the views and panels. Its member
// functions are the actions that the mouse, the keyboard and a script all
// go through (ui/script.hpp drives the same ones).
// Disk space the growth history may use once its memory budget is spent.
inline constexpr std::size_t kHistoryDiskBudget = std::size_t(4) << 30;

class Designer {
public:
    Designer(const DesignerOptions& options, const DesignerServices& services);
    ~Designer();
    Designer(const Designer&) = delete;
    Designer& operator=(const Designer&) = delete;

    int run(ScriptPlayer* script);

    // --- actions --------------------------------------------------------------
    void openPreset(const std::string& name);
    void openSessionFile(const std::string& path);
    void saveSession(const std::string& path);
    void exportImage(const std::string& path, int bitDepth);
    // Renders the session at width x height on a worker thread (progress bar,
    // cancellable) and writes it as exportImage does.
    void exportAtSize(const std::string& path, int width, int height, int bitDepth);
    void exportTextureSet(const std::string& dir);
    // A session on a mesh: the model re-textured with the pattern (GLB, with
    // a normal map), as `render --mesh ... --out model.glb` writes it.
    void exportModel(const std::string& path);
    // Growth animation: while on, every `every` steps the canvas is written
    // as the next numbered PNG in `dir` (frame_00000.png, ...), colour-mapped
    // as the export; empty dir: off.
    void recordFrames(const std::string& dir, int every);
    void screenshot(const std::string& path); // the whole window, after this frame
    // Opens the newest session a crashed designer left (the restore offer's
    // button); it is kept as restored-*.json in the state folder.
    void restoreAutosave();
    // Deletes the newest crashed session (the offer's Discard).
    void discardRecovered();
    // What the window said at start when designer.json's session or preset
    // could not be reopened ("" when it could).
    const std::string& startupNotice() const { return m_startupNotice; }
    void setPlaying(bool playing) { m_playing = playing; }
    bool playing() const { return m_playing; }
    void stepOnce();
    void reset();
    void reseed();
    void undo();
    void redo();
    void changeParam(const std::string& name, float value); // one undo step
    void setStepsPerFrame(int steps);                       // 0: automatic
    void quit() { m_quit = true; }
    // Brings a side panel tab to the front: 0 presets, 1 history, 2 map.
    void showTab(int tab) { m_requestTab = tab; }
    void renderMap(); // the map panel's button: on a worker thread, into the panel

    Document& document() { return m_doc; }
    BrushSettings& brush() { return m_brush; }
    // The canvas' last screen rectangle and view (the script aims with them).
    std::array<float, 4> canvasRect() const { return m_canvasRect; }
    std::array<float, 4> modelRect() const { return m_modelRect; } // the 3D view's
    bool hasModel() const { return m_surface != nullptr; }
    bool jobRunning() const { return m_job != nullptr; }
    bool thumbnailsDone() const { return m_thumbnails.rendered() >= m_thumbnails.total(); }
    double fps() const { return m_fps; }
    double stepsPerSecond() const { return m_stepsPerSecond; }
    // Steps the simulation has run in this process (replays included): the
    // rates' count, which a preset, a reset or a history branch does not move
    // the way it moves the run's step number.
    long long stepsRun() const { return m_stepsRun; }
    // Seconds spent in each part of the frames since the last takeFrameTimes.
    struct FrameTimes {
        long long frames = 0;
        double events = 0, simulate = 0, display = 0, interface = 0, draw = 0, present = 0;
    };
    FrameTimes takeFrameTimes() { return std::exchange(m_frameTimes, FrameTimes{}); }
    std::string backendName(); // the status line's: the live run's backend, or "-"
    const CanvasView& canvasView() const { return m_view; }
    // Shows an error in the status line and on stderr; the script fails on it.
    void reportError(const std::string& message);
    const std::string& lastError() const { return m_lastError; }
    int errorCount() const { return m_errorCount; }

private:
    using Clock = std::chrono::steady_clock;
    static double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
    void frame();
    void simulate();
    void advance(int steps); // m_doc.advance, counted in m_stepsRun
    void refreshDisplay();
    void handleShortcuts();
    void drawMenuBar();
    void drawControls(float x, float y, float w, float h);
    void drawModelSection();
    void drawDirectionControls(const Session& base);
    void drawGravityControls(const Session& base);
    void drawParamsSection();
    void drawBrushSection();
    void drawCascadeSection();
    void drawDisplaySection();
    void drawWatercolourEdges();
    void drawCanvas(float x, float y, float w, float h);
    void drawModelView(float x, float y, float w, float h);
    void renderModelView(int width, int height);
    // The 3D view follows the live session's surface (deformations).
    void syncSurface();
    // The deform tool's drag on the 3D view (the point under the cursor).
    void deformDrag(const std::optional<Eigen::Vector3f>& hit, double worldRadius);
    // Washes the localized re-growth's active tiles towards orange.
    void tintActiveTiles(std::vector<std::array<std::uint8_t, 4>>& colours,
                         const Atlas& atlas) const;
    // The brush settings as a stroke (chemical and parameter names resolved).
    StrokeSpec strokeFromBrush() const;
    // The watercolour brush's pigment, laid with the water of strokeFromBrush.
    std::optional<StrokeSpec> companionFromBrush() const;
    bool watercolourBrush() const;
    // Opens a session that grows on a mesh: its tiles are built on a worker
    // thread (a progress bar; cancel abandons it), then it opens.
    void openSurfaceSession(Session session, const std::string& path, long long replayTo);
    void drawSidePanel(float x, float y, float w, float h);
    void drawPresets();
    void drawHistory();
    void drawMapPanel();
    // Sets the map's axes to the current model's first two parameters when
    // the model changed; whether they can be rendered.
    bool syncMapAxes();
    void drawStatusBar(float y, float h);
    void drawPopups();
    void drawJob();
    void autosave(bool force);
    // designer.json's session or preset, else the default with a notice.
    void openRemembered();
    // The two openers' work; the public ones report a throw as an error.
    void openPresetOrThrow(const std::string& name);
    void openSessionFileOrThrow(const std::string& path);
    void writeScreenshot();
    void writeRecordedFrame();
    // Runs `f`, reporting an exception as an error instead of leaving the frame.
    void guarded(const char* what, const std::function<void()>& f);

    DesignerOptions m_options;
    DesignerServices m_services;
    Settings m_settings;
    std::unique_ptr<gl::GlfwContext> m_window;
    std::unique_ptr<PartialRedraw> m_redraw; // on a software rasterizer only
    gl::Backend m_backend;
    Document m_doc;
    std::unique_ptr<gl::Display> m_display;
    int m_displayChemical = -1; // -1: the colour map's
    CanvasView m_view;
    bool m_viewFramed = false;
    bool m_nearest = true, m_tiled = false;
    // The colour map while a slider of it is dragged: shown, and committed to
    // the document (one undo step) when the drag ends.
    std::optional<ColorMapSpec> m_colormapDraft;
    bool m_showActiveTiles = true; // the localized re-growth's tiles, on the canvas and the model
    std::array<float, 4> m_canvasRect{}, m_modelRect{};
    BrushSettings m_brush;
    bool m_playing = true, m_quit = false;
    int m_stepsPerFrame = 0; // 0: automatic
    int m_autoSteps = 1;
    double m_simSeconds = 0;
    FrameTimes m_frameTimes;
    double m_fps = 0, m_stepsPerSecond = 0;
    std::chrono::steady_clock::time_point m_lastFrame, m_lastRate, m_lastAutosave;
    long long m_stepsRun = 0, m_stepsAtLastRate = 0;
    int m_framesSinceRate = 0;
    long long m_snapshotEvery = 500;
    // An opened session file runs to its steps (its strokes replayed) before
    // the artist takes over: the canvas shows what was saved.
    long long m_replayTo = 0;
    std::optional<std::size_t> m_scrub; // a history snapshot shown instead of the run
    std::string m_status, m_lastError;
    int m_errorCount = 0;
    std::string m_pendingScreenshot;
    bool m_showHelp = false, m_showOpen = false, m_showSave = false, m_showExport = false;
    bool m_offerRestore = false;
    std::vector<std::string> m_recovered; // crashed designers' sessions, newest first
    std::string m_startupNotice;
    char m_pathBuffer[1024] = {};
    int m_exportSize[2] = {1024, 1024};
    int m_exportBits = 8;
    std::unique_ptr<BackgroundJob> m_job;
    Thumbnails m_thumbnails;
    std::shared_ptr<const SurfaceSetup> m_surface; // the open session's mesh and tiles, or null
    std::shared_ptr<const SurfaceGeometry> m_shownGeometry;  // the live surface m_surface is
    std::optional<Eigen::Vector3f> m_deformFrom, m_deformTo; // a deform drag on the model
    std::array<float, 2> m_deformStartScreen{};              // screen pixels
    Orbit m_orbit;
    gl::Texture2D m_modelImage;
    std::unique_ptr<gl::SurfaceRenderer> m_modelRenderer;   // of m_modelRendererFor's mesh
    std::shared_ptr<const SurfaceSetup> m_modelRendererFor; // held: identity stays unique
    gl::ViewOptions m_modelView; // the last 3D picture's camera (picking aims with it)
    BoundingSphere m_modelBounds;
    bool m_modelStale = true;
    std::chrono::steady_clock::time_point m_lastModelRender;
    std::string m_mapModel; // the model the axes were chosen for
    std::array<MapAxis, 2> m_mapAxes, m_mapRendered;
    gl::Texture2D m_mapImage;
    std::string m_recordDir;
    int m_recordEvery = 100, m_recordIndex = 0;
    long long m_recordNext = 0;
    int m_viewMode = 0;
    int m_requestTab = -1;
    // The stability report and the settings it was computed for.
    std::pair<std::uint64_t, int> m_stabilityKey{~std::uint64_t(0), -1};
    std::string m_stabilityText;
    bool m_stabilityWarning = false;
    std::map<std::size_t, std::string>
        m_stageText; // the cascade editor's JSON being edited // 0: canvas and model side by side,
                     // 1: canvas, 2: model
    std::vector<Session> m_presets;
    State m_readout; // the state under the cursor's readout, refreshed ten times a second
    std::chrono::steady_clock::time_point m_lastReadout;
    std::string m_presetFilter;
    // The preset the list last scrolled to: a preset opened from the menu,
    // the command line or a script is brought into view once.
    std::string m_presetRevealed;
    float m_controlsWidth = 340, m_sideWidth = 300;
};

} // namespace morphogen::ui
