#include "ui/settings.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/io/output_files.hpp"
#include "ui/crash_recovery.hpp"

#include <unistd.h>

namespace morphogen::ui {

namespace {

namespace fs = std::filesystem;

std::string xdgDir(const char* variable, const char* fallback) {
    if (const char* v = std::getenv(variable); v && *v)
        return (fs::path(v) / "morphogen").string();
    const char* home = std::getenv("HOME");
    return (fs::path(home && *home ? home : ".") / fallback / "morphogen").string();
}

} // namespace

Settings Settings::load(const std::string& configDir, const std::string& stateDir) {
    Settings s;
    s.configDir = configDir.empty() ? xdgDir("XDG_CONFIG_HOME", ".config") : configDir;
    s.stateDir = stateDir.empty() ? xdgDir("XDG_STATE_HOME", ".local/state") : stateDir;
    s.cacheDir = stateDir.empty() ? xdgDir("XDG_CACHE_HOME", ".cache")
                                  : (std::filesystem::path(stateDir) / "cache").string();
    std::ifstream in(s.settingsPath());
    if (!in)
        return s;
    try {
        std::stringstream text;
        text << in.rdbuf();
        const nlohmann::json j = nlohmann::json::parse(text.str());
        s.lastFolder = j.value("last_folder", s.lastFolder);
        s.lastSession = j.value("last_session", s.lastSession);
        s.lastPreset = j.value("last_preset", s.lastPreset);
        s.windowWidth = std::clamp(j.value("window_width", s.windowWidth), 640, 16384);
        s.windowHeight = std::clamp(j.value("window_height", s.windowHeight), 480, 16384);
        s.controlsWidth = std::clamp(j.value("controls_width", s.controlsWidth), 200.0f, 1200.0f);
        s.sideWidth = std::clamp(j.value("side_width", s.sideWidth), 150.0f, 1200.0f);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "morphogen design: ignoring %s (%s); using the defaults\n",
                     s.settingsPath().c_str(), e.what());
        Settings defaults;
        defaults.configDir = s.configDir;
        defaults.stateDir = s.stateDir;
        defaults.cacheDir = s.cacheDir;
        return defaults;
    }
    return s;
}

void Settings::save() const {
    nlohmann::json j;
    j["last_folder"] = lastFolder;
    j["last_session"] = lastSession;
    j["last_preset"] = lastPreset;
    j["window_width"] = windowWidth;
    j["window_height"] = windowHeight;
    j["controls_width"] = controlsWidth;
    j["side_width"] = sideWidth;
    try {
        fs::create_directories(configDir);
        writeTextAtomically(settingsPath(), j.dump(2) + "\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "morphogen design: could not save the settings: %s\n", e.what());
    }
}

std::string Settings::settingsPath() const {
    return (fs::path(configDir) / "designer.json").string();
}

std::string Settings::imguiIniPath() const {
    return (fs::path(configDir) / "designer-windows.ini").string();
}

std::string Settings::autosavePath() const {
    return autosavePathFor(stateDir, long(::getpid()));
}

std::string Settings::lastExitPath() const {
    return (fs::path(stateDir) / "last-exit.json").string();
}

} // namespace morphogen::ui
