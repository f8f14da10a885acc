#include <cstdio>

#include "cli/commands.hpp"
#include "core/session/session.hpp"

namespace morphogen::cli {

void addPresetsCommand(CLI::App& app) {
    CLI::App* cmd =
        app.add_subcommand("presets", "List the built-in presets: name, model, description");
    cmd->callback([] {
        for (const Session& s : allPresets())
            std::printf("%-24s %-14s %s\n", s.name.c_str(), s.model.c_str(), s.description.c_str());
    });
}

} // namespace morphogen::cli
