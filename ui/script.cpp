#include "ui/script.hpp"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "core/base/errors.hpp"
#include "ui/designer_app.hpp" // glad's GL declarations before GLFW's

#include <GLFW/glfw3.h>
#include <imgui.h>

namespace morphogen::ui {

namespace {

// Each verb's argument count: minimum and maximum.
const std::map<std::string, std::pair<int, int>> kVerbs = {
    {"preset", {1, 1}},
    {"open", {1, 1}},
    {"play", {0, 0}},
    {"pause", {0, 0}},
    {"steps-per-frame", {1, 1}},
    {"frames", {1, 1}},
    {"until-step", {1, 1}},
    {"param", {2, 2}},
    {"brush", {1, 17}},
    {"drag", {4, 5}},
    {"hover", {2, 2}},
    {"drag-model", {4, 5}},
    {"deform", {1, 2}},
    {"tab", {1, 1}},
    {"restore-autosave", {0, 0}},
    {"crash", {0, 0}},
    {"export-model", {1, 1}},
    {"record", {2, 2}},
    {"record-stop", {0, 0}},
    {"render-map", {0, 0}},
    {"wait-job", {0, 0}},
    {"wait-thumbnails", {0, 0}},
    {"rates", {0, 0}},
    {"key", {1, 1}},
    {"save", {1, 1}},
    {"export", {1, 2}},
    {"screenshot", {1, 1}},
    {"expect-steps", {1, 1}},
    {"quit", {0, 0}},
};

const std::map<std::string, int> kKeys = {
    {"space", GLFW_KEY_SPACE}, {"period", GLFW_KEY_PERIOD},  {".", GLFW_KEY_PERIOD},
    {"f1", GLFW_KEY_F1},       {"[", GLFW_KEY_LEFT_BRACKET}, {"]", GLFW_KEY_RIGHT_BRACKET},
};

double number(const ScriptCommand& c, const std::string& text) {
    try {
        std::size_t used = 0;
        const double v = std::stod(text, &used);
        if (used == text.size() && std::isfinite(v))
            return v;
    } catch (const std::exception&) {
    }
    throw InputError("line " + std::to_string(c.line) + ": '" + text + "' is not a number");
}

// "ctrl+shift+z" -> key and modifiers; throws InputError.
void parseCombo(const std::string& combo, int line, int& key, bool& ctrl, bool& shift) {
    ctrl = shift = false;
    key = -1;
    std::stringstream parts(combo);
    std::string part;
    while (std::getline(parts, part, '+')) {
        if (part == "ctrl")
            ctrl = true;
        else if (part == "shift")
            shift = true;
        else if (auto it = kKeys.find(part); it != kKeys.end())
            key = it->second;
        else if (part.size() == 1 && part[0] >= 'a' && part[0] <= 'z')
            key = GLFW_KEY_A + (part[0] - 'a');
        else
            throw InputError("line " + std::to_string(line) + ": key '" + combo +
                             "' is not accepted (a letter, space, period, [, ], f1, with "
                             "ctrl+ and shift+)");
    }
    if (key < 0)
        throw InputError("line " + std::to_string(line) + ": key '" + combo + "' names no key");
}

} // namespace

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& source) {
    std::vector<ScriptCommand> commands;
    std::stringstream lines(text);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
        if (const std::size_t hash = line.find('#'); hash != std::string::npos)
            line.erase(hash);
        std::stringstream words(line);
        ScriptCommand c;
        c.line = n;
        if (!(words >> c.verb))
            continue;
        for (std::string w; words >> w;)
            c.args.push_back(w);
        const auto verb = kVerbs.find(c.verb);
        try {
            if (verb == kVerbs.end()) {
                std::string known;
                for (const auto& [name, counts] : kVerbs)
                    known += (known.empty() ? "" : ", ") + name;
                throw InputError("line " + std::to_string(n) + ": unknown command '" + c.verb +
                                 "' (accepted: " + known + ")");
            }
            const int count = int(c.args.size());
            if (count < verb->second.first || count > verb->second.second)
                throw InputError("line " + std::to_string(n) + ": '" + c.verb + "' takes " +
                                 std::to_string(verb->second.first) + ".." +
                                 std::to_string(verb->second.second) + " arguments, got " +
                                 std::to_string(count));
            if (c.verb == "drag" || c.verb == "hover" || c.verb == "drag-model")
                for (const std::string& a : c.args)
                    (void)number(c, a);
            if (c.verb == "frames" || c.verb == "until-step" || c.verb == "steps-per-frame" ||
                c.verb == "expect-steps")
                if (number(c, c.args[0]) < 0)
                    throw InputError("line " + std::to_string(n) + ": " + c.verb +
                                     " needs a count >= 0");
            if (c.verb == "key") {
                int key;
                bool ctrl, shift;
                parseCombo(c.args[0], n, key, ctrl, shift);
            }
        } catch (const InputError& e) {
            throw InputError(source + ": " + e.what());
        }
        commands.push_back(std::move(c));
    }
    return commands;
}

std::vector<ScriptCommand> loadScript(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        throw InputError(path + ": cannot read the script");
    std::stringstream text;
    text << in.rdbuf();
    return parseScript(text.str(), path);
}

ScriptPlayer::ScriptPlayer(std::vector<ScriptCommand> commands) : m_commands(std::move(commands)) {}

void ScriptPlayer::fail(int line, const std::string& message) {
    std::fprintf(stderr, "morphogen design: script line %d failed: %s\n", line, message.c_str());
    m_failed = true;
}

void ScriptPlayer::checkErrors(const Designer& d) {
    if (d.errorCount() != m_errors) {
        m_errors = d.errorCount();
        fail(m_line, d.lastError());
    }
}

bool ScriptPlayer::start(Designer& d, const ScriptCommand& c) {
    m_line = c.line;
    const std::vector<std::string>& a = c.args;
    try {
        if (c.verb == "preset")
            d.openPreset(a[0]);
        else if (c.verb == "open")
            d.openSessionFile(a[0]);
        else if (c.verb == "play")
            d.setPlaying(true);
        else if (c.verb == "pause")
            d.setPlaying(false);
        else if (c.verb == "steps-per-frame")
            d.setStepsPerFrame(int(number(c, a[0])));
        else if (c.verb == "frames") {
            m_wait = int(number(c, a[0]));
            return m_wait == 0;
        } else if (c.verb == "until-step") {
            m_untilStep = (long long)number(c, a[0]);
            d.setPlaying(true);
            return false;
        } else if (c.verb == "param")
            d.changeParam(a[0], float(number(c, a[1])));
        else if (c.verb == "brush") {
            BrushSettings& b = d.brush();
            const auto mode = parseBrushMode(a[0]);
            if (!mode)
                throw InputError("brush mode '" + a[0] + "' (accepted: " + brushModeNames() + ")");
            b.mode = *mode;
            for (std::size_t i = 1; i + 1 < a.size(); i += 2) {
                const std::string& key = a[i];
                if (key == "chemical") {
                    const ReactionModel& m = d.document().live().reactionModel();
                    b.chemical = m.chemicalIndex(a[i + 1]);
                    if (b.chemical < 0)
                        throw InputError("chemical '" + a[i + 1] +
                                         "' (accepted: " + m.chemicalNames() + ")");
                } else if (key == "param")
                    b.param = a[i + 1];
                else if (key == "value")
                    b.value = float(number(c, a[i + 1]));
                else if (key == "radius")
                    b.radius = float(number(c, a[i + 1]));
                else if (key == "falloff")
                    b.falloff = float(number(c, a[i + 1]));
                else if (key == "localized")
                    b.localized = number(c, a[i + 1]) != 0;
                else if (key == "watercolour")
                    b.watercolour = number(c, a[i + 1]) != 0;
                else if (key == "water")
                    b.water = float(number(c, a[i + 1]));
                else if (key == "pigment")
                    b.pigment = a[i + 1];
                else
                    throw InputError("brush setting '" + key +
                                     "' (accepted: chemical, param, value, radius, falloff, "
                                     "localized, watercolour, water, pigment)");
            }
        } else if (c.verb == "deform") {
            // The brush panel's deform tool: on with a stretch factor, or off.
            BrushSettings& b = d.brush();
            b.deform = a[0] != "off";
            if (b.deform) {
                const double f = number(c, a[0]);
                if (f < kMinDeformFactor || f > kMaxDeformFactor)
                    throw InputError("deform " + a[0] + ": a stretch factor in " +
                                     std::to_string(kMinDeformFactor) + ".." +
                                     std::to_string(kMaxDeformFactor) + ", or off");
                b.stretch = float(f);
            }
            if (a.size() > 1 && a[1] != "across" && a[1] != "local")
                throw InputError("deform " + a[0] + " " + a[1] +
                                 ": the second word is 'across' (the whole slab) or 'local'");
            b.across = a.size() > 1 && a[1] == "across";
        } else if (c.verb == "drag" || c.verb == "drag-model") {
            if (c.verb == "drag-model" && !d.hasModel())
                throw InputError("drag-model needs a session on a mesh (a 3D view)");
            m_onModel = c.verb == "drag-model";
            m_from[0] = number(c, a[0]);
            m_from[1] = number(c, a[1]);
            m_to[0] = number(c, a[2]);
            m_to[1] = number(c, a[3]);
            m_dragFrames = a.size() > 4 ? std::max(2, int(number(c, a[4]))) : 10;
            m_dragFrame = 0;
            m_dragging = true;
            return false;
        } else if (c.verb == "hover") {
            m_onModel = false;
            // A drag of one position without the button: the pointer rests there.
            m_from[0] = m_to[0] = number(c, a[0]);
            m_from[1] = m_to[1] = number(c, a[1]);
            m_dragFrames = 0;
            m_dragFrame = 0;
            m_dragging = true;
            return false;
        } else if (c.verb == "key") {
            parseCombo(a[0], c.line, m_key, m_ctrl, m_shift);
            m_releaseKey = false;
            return false;
        } else if (c.verb == "tab") {
            const std::vector<std::string> tabs = {"presets", "history", "map"};
            const auto it = std::find(tabs.begin(), tabs.end(), a[0]);
            if (it == tabs.end())
                throw InputError("tab '" + a[0] + "' (accepted: presets, history, map)");
            d.showTab(int(it - tabs.begin()));
        } else if (c.verb == "restore-autosave")
            d.restoreAutosave();
        else if (c.verb == "crash") {
            // Tests of crash recovery: ends the process as a crash would,
            // without the clean exit's saves.
            std::fprintf(stderr, "morphogen design: script line %d: crashing on purpose\n", c.line);
            std::_Exit(134);
        } else if (c.verb == "export-model")
            d.exportModel(a[0]);
        else if (c.verb == "record")
            d.recordFrames(a[0], int(number(c, a[1])));
        else if (c.verb == "record-stop")
            d.recordFrames("", 1);
        else if (c.verb == "render-map")
            d.renderMap();
        else if (c.verb == "wait-job") {
            m_waitJob = true;
            return false;
        } else if (c.verb == "wait-thumbnails") {
            m_waitThumbnails = true;
            return false;
        } else if (c.verb == "rates")
            printRates(d);
        else if (c.verb == "save")
            d.saveSession(a[0]);
        else if (c.verb == "export")
            d.exportImage(a[0], a.size() > 1 ? int(number(c, a[1])) : 8);
        else if (c.verb == "screenshot") {
            d.screenshot(a[0]);
            m_wait = 1; // taken after this frame is drawn
            return false;
        } else if (c.verb == "expect-steps") {
            const long long want = (long long)number(c, a[0]);
            if (d.document().steps() != want)
                throw InputError("the run is at step " + std::to_string(d.document().steps()) +
                                 ", expected " + std::to_string(want));
        } else if (c.verb == "quit")
            d.quit();
    } catch (const std::exception& e) {
        fail(c.line, e.what());
        return false;
    }
    checkErrors(d);
    return !m_failed;
}

void ScriptPlayer::beforeFrame(Designer& d) {
    ImGuiIO& io = ImGui::GetIO();
    // Release a key pressed on the last frame; this frame runs no command, so
    // that the next press is a new one.
    const bool released = m_key >= 0 && m_releaseKey;
    if (released) {
        io.KeysDown[m_key] = false;
        io.KeyCtrl = io.KeyShift = false;
        m_key = -1;
    }
    checkErrors(d);
    if (m_untilStep >= 0 && d.document().steps() >= m_untilStep)
        m_untilStep = -1;
    else if (m_untilStep >= 0)
        d.setPlaying(true); // an opened session pauses when its replay ends
    if (m_waitJob && !d.jobRunning())
        m_waitJob = false;
    if (m_waitThumbnails && d.thumbnailsDone())
        m_waitThumbnails = false;
    while (!m_waitJob && !m_waitThumbnails && !released && !m_failed && m_wait == 0 &&
           m_untilStep < 0 && !m_dragging && m_key < 0 && m_next < m_commands.size()) {
        if (!start(d, m_commands[m_next++]))
            break;
    }
    if (m_key >= 0 && !m_releaseKey) {
        io.KeysDown[m_key] = true;
        io.KeyCtrl = m_ctrl;
        io.KeyShift = m_shift;
        m_releaseKey = true;
    }
    // The pointer is the script's alone (a virtual X server's real pointer
    // would sit over the canvas and hover there).
    io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
    io.MouseDown[0] = false;
    if (m_dragging) {
        // Frame 0 moves there, 1 presses, then moves; the last frame releases.
        const double t = m_dragFrame <= 1 || m_dragFrames < 3
                             ? 0.0
                             : std::min(1.0, double(m_dragFrame - 1) / double(m_dragFrames - 2));
        m_pointer[0] = m_from[0] + (m_to[0] - m_from[0]) * t;
        m_pointer[1] = m_from[1] + (m_to[1] - m_from[1]) * t;
        m_pointerSet = true;
        io.MouseDown[0] = m_dragFrames > 0 && m_dragFrame >= 1 && m_dragFrame < m_dragFrames;
        if (++m_dragFrame > m_dragFrames)
            m_dragging = false;
    }
    if (m_pointerSet && m_onModel) {
        const std::array<float, 4> r = d.modelRect();
        io.MousePos = ImVec2(r[0] + float(m_pointer[0]) * r[2], r[1] + float(m_pointer[1]) * r[3]);
    } else if (m_pointerSet) {
        const std::array<float, 4> r = d.canvasRect();
        const auto& live = d.document().live();
        const auto screen = d.canvasView().toScreen(
            {m_pointer[0] * live.width, m_pointer[1] * live.height}, r[2], r[3]);
        io.MousePos = ImVec2(r[0] + float(screen[0]), r[1] + float(screen[1]));
    }
}

void ScriptPlayer::printRates(Designer& d) {
    // Averages since the last `rates` (the first one only starts the clock):
    // the status line's figures are over half a second, too short to quote.
    const auto now = std::chrono::steady_clock::now();
    const long long steps = d.stepsRun();
    if (m_ratesFrames > 0 && m_ratesSince != std::chrono::steady_clock::time_point{}) {
        const double span = std::chrono::duration<double>(now - m_ratesSince).count();
        std::printf("rates: %lld frames, %lld steps in %.2f s: %.1f fps, %.0f steps/s "
                    "(status line: %.0f fps, %.0f steps/s, backend %s)\n",
                    m_ratesFrames, steps - m_ratesSteps, span, double(m_ratesFrames) / span,
                    double(steps - m_ratesSteps) / span, d.fps(), d.stepsPerSecond(),
                    d.backendName().c_str());
        // Where a frame's time went: the interface is ImGui's frame less the
        // simulation and the display update; draw submits the frame's GL
        // commands, and a software renderer rasterizes them in present (the
        // swap flushes them) before it copies the frame out.
        const Designer::FrameTimes t = d.takeFrameTimes();
        const double ms = t.frames > 0 ? 1e3 / double(t.frames) : 0;
        std::printf("frame: %.2f ms events, %.2f simulate, %.2f display, %.2f interface, "
                    "%.2f draw, %.2f present (means over %lld frames)\n",
                    t.events * ms, t.simulate * ms, t.display * ms, t.interface * ms, t.draw * ms,
                    t.present * ms, t.frames);
        std::fflush(stdout);
    } else
        d.takeFrameTimes(); // the clock starts here for these too
    m_ratesSince = now;
    m_ratesSteps = steps;
    m_ratesFrames = 0;
}

void ScriptPlayer::afterFrame(Designer& d) {
    ++m_ratesFrames;
    checkErrors(d);
    if (m_wait > 0)
        --m_wait;
}

} // namespace morphogen::ui
