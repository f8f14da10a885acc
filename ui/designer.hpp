#pragma once

#include <functional>
#include <string>

#include "core/sim/runner.hpp"

namespace morphogen::ui {

// `morphogen design`'s options.
struct DesignerOptions {
    std::string preset;  // opened at start; empty with no session: the last session or the default
    std::string session; // a session file to open at start
    std::string script;  // a script that drives the designer (ui/script.hpp); empty: none
    std::string backend = "auto";
    // The window, in screen units; 0: the size it had when last closed
    // (designer.json), 1600 x 1000 the first time.
    int width = 0, height = 0;
    // Where settings and autosaves live; empty: $XDG_CONFIG_HOME/morphogen and
    // $XDG_STATE_HOME/morphogen (or ~/.config, ~/.local/state).
    std::string configDir, stateDir;
    double autosaveSeconds = 60; // while there are unsaved changes
};

// The CLI's writers, handed in by the design command so that the designer's
// files are written by the same code as `morphogen render`'s (ui/ does not
// depend on app/cli).
struct DesignerServices {
    // Writes result.state as an image (.png/.tif colour-mapped at bitDepth, .exr
    // raw) and result.completed as the session next to it (empty path: none).
    std::function<void(const RunResult& result, const std::string& image,
                       const std::string& session, int bitDepth)>
        writeImage;
    // Writes the texture set (height, normal, mask maps) into a folder.
    std::function<void(const RunResult& result, const std::string& dir)> writeTextureSet;
};

// Opens the window and runs until it is closed or the script quits. Returns
// the exit code: 0, 1 when a script step failed (the message on stderr).
// Throws std::runtime_error when there is no window (no display, no GL 3.3).
int runDesigner(const DesignerOptions& options, const DesignerServices& services);

} // namespace morphogen::ui
