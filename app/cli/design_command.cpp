#include <cstdlib>
#include <memory>
#include <string>

#include <unistd.h>

#include "cli/commands.hpp"
#include "cli/render_output.hpp"
#include "core/base/errors.hpp"
#include "core/io/output_files.hpp"
#include "core/output/texture_set.hpp"
#include "gl/backend.hpp"
#include "ui/designer.hpp"

namespace morphogen::cli {

namespace {

// The render command's writers, so that an export from the designer is the
// file `render` writes for the same session.
ui::DesignerServices renderWriters() {
    ui::DesignerServices services;
    services.writeImage = [](const RunResult& result, const std::string& image,
                             const std::string& session, int bitDepth) {
        requireFinite(result);
        OutputFiles files;
        writeRenderOutput(result, image, session, bitDepth, files);
        files.commit();
    };
    services.writeTextureSet = [](const RunResult& result, const std::string& dir) {
        requireFinite(result);
        prepareTextureSetDir(dir);
        OutputFiles files;
        writeTextureSet(dir, result.state, result.completed, files);
        files.commit();
    };
    return services;
}

} // namespace

void tuneOpenMpForTheDesigner(int argc, char** argv) {
    if (argc < 2 || std::string(argv[1]) != "design" || std::getenv("GOMP_SPINCOUNT") ||
        std::getenv("OMP_WAIT_POLICY"))
        return;
    // About 3,000 spins: the waits between a step's parallel loops stay
    // spins (they are a few microseconds), the wait for the next frame sleeps.
    if (::setenv("GOMP_SPINCOUNT", "3000", 1) != 0)
        return;
    ::execv("/proc/self/exe", argv);
    ::unsetenv("GOMP_SPINCOUNT"); // the restart failed: go on as started
}

void addDesignCommand(CLI::App& app) {
    auto options = std::make_shared<ui::DesignerOptions>();
    CLI::App* cmd = app.add_subcommand(
        "design", "The interactive designer: grow, steer and paint patterns in a window");
    cmd->add_option("--preset", options->preset, "Preset to open (default: the last session)");
    cmd->add_option("--session", options->session, "Session file to open");
    cmd->add_option("--backend", options->backend,
                    "auto, gpu or cpu (auto: the GPU unless the "
                    "GL renderer is a software rasterizer)");
    cmd->add_option("--script", options->script,
                    "Drive the designer from a script (tests, demos); see README");
    cmd->add_option("--window", options->width,
                    "Window width in screen units (default: as it was last closed, else 1600)");
    cmd->add_option("--window-height", options->height,
                    "Window height in screen units (default: as last closed, else 1000)");
    cmd->add_option("--config-dir", options->configDir,
                    "Settings folder (default $XDG_CONFIG_HOME/morphogen)");
    cmd->add_option("--state-dir", options->stateDir,
                    "Autosave folder (default $XDG_STATE_HOME/morphogen)");
    cmd->add_option("--autosave-seconds", options->autosaveSeconds,
                    "Seconds between autosaves while there are unsaved changes (default 60)")
        ->check(CLI::Range(0.0, 86400.0));
    cmd->callback([options] {
        (void)gl::parseBackendChoice(options->backend); // bad input: exit 2 before a window
        // 0 (the default): the size remembered from the last run.
        if ((options->width != 0 && (options->width < 320 || options->width > 16384)) ||
            (options->height != 0 && (options->height < 240 || options->height > 16384)))
            throw InputError("--window " + std::to_string(options->width) + " x " +
                             std::to_string(options->height) +
                             " is outside 320..16384 x 240..16384");
        const int code = ui::runDesigner(*options, renderWriters());
        if (code != 0)
            throw std::runtime_error("the designer's script failed (see above)");
    });
}

} // namespace morphogen::cli
