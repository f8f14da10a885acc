#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "core/sim/runner.hpp"
#include "core/surface/surface_setup.hpp"

namespace morphogen::cli {

// render --perturb X,Y,Z,R: after a run on a mesh, randomise the pattern in
// the ball of radius R (mesh units) round (X, Y, Z) and grow it back with
// localized reaction-diffusion (Lo et al. sections 4 and 5.3). An action on
// the finished run, like --frames: the written session records the run, not
// the perturbation.
struct PerturbFlags {
    std::string ball; // "X,Y,Z,R"; empty: none
};

void addPerturbFlags(CLI::App& command, PerturbFlags& flags);

// Checks the flag before the run: four finite numbers, R > 0, and a mesh to
// perturb. Throws InputError naming --perturb.
void checkPerturbFlags(const PerturbFlags& flags, bool surface);
// Once the tiles are built, before the run: the ball must reach a texel of
// the surface (the run's minutes are not spent on a ball that misses).
void checkPerturbBall(const PerturbFlags& flags, const Session& session, const SurfaceSetup& setup);

// Applies the perturbation to result.state on a simulator of `session` and
// relaxes it locally; result.state becomes the relaxed state. Prints the
// phases (iterations per second and tiles of A1, A2, ...) to stderr.
void applyPerturbation(const PerturbFlags& flags, const Session& session, const SurfaceSetup& setup,
                       const SimulatorFactory& make, RunResult& result);

} // namespace morphogen::cli
