#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace morphogen::ui {

class Designer;

// A designer script: one command per line, '#' starts a comment. It drives
// the designer through the same actions and the same input path as a
// person: pointer and keys are set in Dear ImGui's input state before each
// frame, so a scripted stroke goes through the canvas' mouse handling.
//
//   preset NAME                 open a preset (the browser's click)
//   open FILE                   open a session file
//   play | pause                the transport buttons
//   steps-per-frame N           0: automatic
//   frames N                    let N frames pass
//   until-step N                let frames pass until the run reaches step N (plays)
//   param NAME VALUE            set a parameter (one undo step, as a typed value)
//   brush MODE [chemical NAME] [param NAME] [value V] [radius R] [falloff F] [localized 0|1]
//         [watercolour 0|1] [water W] [pigment NAME]   (value: the pigment's amount)
//   deform FACTOR|off [local|across]  the deform tool (drag-model stretches the model
//                               under the brush, or the slab across it) or painting
//   drag X0 Y0 X1 Y1 [FRAMES]   left-drag over the canvas, in canvas fractions (0..1)
//   hover X Y                   rest the pointer there (outside 0..1: off the canvas)
//   drag-model X0 Y0 X1 Y1 [FRAMES]  left-drag over the 3D view, in fractions of it
//   key COMBO                   e.g. space, ctrl+z, ctrl+shift+z, r, t, f
//   tab presets|history|map     bring a side panel to the front
//   render-map                  the map panel's button
//   wait-job                    let frames pass until a background job (map, export, tiles) ends
//   wait-thumbnails             let frames pass until the presets' thumbnails are made
//   rates                       print frames/s and steps/s averaged since the last `rates`
//                               (the first starts the clock)
//   restore-autosave            the crash-restore offer's button
//   crash                       end the process at once, as a crash would (recovery tests)
//   save FILE | export FILE [BITS] | screenshot FILE | export-model FILE.glb
//   record DIR EVERY | record-stop   growth frames: a PNG every EVERY steps
//   expect-steps N              fail unless the run is at step N
//   quit
struct ScriptCommand {
    int line = 0;
    std::string verb;
    std::vector<std::string> args;
};

// Reads and checks a script; throws InputError naming the file, line and
// what is accepted.
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& source);
std::vector<ScriptCommand> loadScript(const std::string& path);

class ScriptPlayer {
public:
    explicit ScriptPlayer(std::vector<ScriptCommand> commands);

    // Before Dear ImGui's frame: runs commands until one needs frames to
    // pass, and sets this frame's pointer and keys.
    void beforeFrame(Designer& designer);
    // After the frame was drawn (screenshots are taken then).
    void afterFrame(Designer& designer);
    bool failed() const { return m_failed; }
    bool done() const { return m_next >= m_commands.size() && m_wait == 0; }

private:
    void fail(int line, const std::string& message);
    // Fails on an error the designer reported since the last check.
    void checkErrors(const Designer& designer);
    // Starts a command; false when it needs frames (m_wait or a drag).
    bool start(Designer& designer, const ScriptCommand& c);
    void printRates(Designer& designer);

    std::vector<ScriptCommand> m_commands;
    std::size_t m_next = 0;
    int m_wait = 0; // frames left of a `frames` command
    long long m_untilStep = -1;
    bool m_waitJob = false;
    bool m_waitThumbnails = false;
    std::chrono::steady_clock::time_point m_ratesSince;
    long long m_ratesSteps = 0, m_ratesFrames = 0;
    // A drag in progress: canvas fractions, the frame it is on, its length.
    bool m_dragging = false;
    double m_from[2] = {0, 0}, m_to[2] = {0, 0};
    int m_dragFrame = 0, m_dragFrames = 0;
    // The script owns the pointer: where it rests (canvas fractions) once a
    // drag or hover put it somewhere; off the window before that.
    bool m_pointerSet = false;
    bool m_onModel = false; // the pointer's fractions are of the 3D view, not the canvas
    double m_pointer[2] = {0, 0};
    // A key combination held for one frame, released on the next.
    int m_key = -1;
    bool m_ctrl = false, m_shift = false, m_releaseKey = false;
    bool m_failed = false;
    int m_errors = 0; // the designer's error count when last checked
    int m_line = 0;   // the command running
};

} // namespace morphogen::ui
