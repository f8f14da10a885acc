#pragma once

#include <string>

namespace morphogen::ui {

// What the designer remembers between runs (designer.json in the config
// folder) and where its files go. Reading never fails: a missing or broken
// file gives the defaults (a broken one with a warning on stderr).
struct Settings {
    std::string configDir; // settings, Dear ImGui's window state
    std::string stateDir;  // autosaves
    std::string cacheDir;  // preset thumbnails (safe to delete)
    std::string lastFolder;
    std::string lastSession; // the session open at the last exit ("" for a preset)
    std::string lastPreset;
    int windowWidth = 1600, windowHeight = 1000;
    float controlsWidth = 340, sideWidth = 300;

    // configDir/stateDir empty: $XDG_CONFIG_HOME/morphogen and
    // $XDG_STATE_HOME/morphogen, or ~/.config/morphogen and
    // ~/.local/state/morphogen. The cache is $XDG_CACHE_HOME/morphogen (or
    // ~/.cache/morphogen), or stateDir/cache when stateDir is given, so a
    // test's run keeps to its own folders.
    static Settings load(const std::string& configDir, const std::string& stateDir);
    // Best effort (a warning on stderr when it cannot write).
    void save() const;

    std::string settingsPath() const;
    std::string imguiIniPath() const;
    // This process's autosave (crash_recovery.hpp): written every minute
    // while there are unsaved changes and on exit; a clean exit renames it to
    // lastExitPath(). Found after its process ended, it means a crash.
    std::string autosavePath() const;
    std::string lastExitPath() const;
};

} // namespace morphogen::ui
