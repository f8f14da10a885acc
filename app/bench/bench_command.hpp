#pragma once

#include <CLI/CLI.hpp>

namespace morphogen::bench {

// `morphogen bench`: the throughput, domain, convergence, memory, resolution,
// surface and designer rows, printed and written as JSON (docs/testing.md).
// The benchmarks live apart from the commands that make images (their own
// folder and library, morphogen_bench) and only this entry point is shared.
void addBenchCommand(CLI::App& app);

} // namespace morphogen::bench
