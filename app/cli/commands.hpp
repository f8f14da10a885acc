#pragma once

#include <CLI/CLI.hpp>

namespace morphogen::cli {

// Each subcommand registers its flags and a callback that does the work (the
// bench's is in app/bench, bench_command.hpp). The
// callbacks throw morphogen::InputError for bad input (exit 2) and other
// exceptions for everything else (exit 1).
void addRenderCommand(CLI::App& app);
void addPresetsCommand(CLI::App& app);
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
// `completion bash`: a completion script generated from `app`'s commands and
// flags (add it last, after the commands it lists).
void addCompletionCommand(CLI::App& app);
// Before anything else in main: for `morphogen design`, restarts the process
// once with OpenMP's spin-wait shortened (GOMP_SPINCOUNT, which libgomp reads
// only as it loads). The designer alternates bursts of simulation with
// drawing; after each burst libgomp's idle threads spin (300,000 turns by
// default) on the cores the drawing (a software rasterizer,
// the display server) needs. Measured under Xvfb on 2 cores: 6% more steps
// per second at the same frame rate. Keeps a GOMP_SPINCOUNT or
// OMP_WAIT_POLICY the user set; does nothing if the restart fails.
void tuneOpenMpForTheDesigner(int argc, char** argv);

} // namespace morphogen::cli
