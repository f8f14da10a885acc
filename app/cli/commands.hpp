#pragma once

#include <CLI/CLI.hpp>

namespace morphogen::cli {

// Each subcommand registers its flags and a callback that does the work. The
// callbacks throw morphogen::InputError for bad input (exit 2) and other
// exceptions for everything else (exit 1).
void addRenderCommand(CLI::App& app);
void addPresetsCommand(CLI::App& app);
void addBenchCommand(CLI::App& app);
void addPropagatorCommand(CLI::App& app);
void addGalleryCommand(CLI::App& app);
void addMapCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);
void addColourCommand(CLI::App& app);
// mesh-info, and the hidden mesh-gen that writes the sample meshes.
void addMeshCommands(CLI::App& app);
// The hidden tile-stats: per-texel weight sums and their culprits (development).
void addTileStatsCommand(CLI::App& app);
// The interactive designer (ui/): a window.
void addDesignCommand(CLI::App& app);

} // namespace morphogen::cli
