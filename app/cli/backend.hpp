#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/sim/runner.hpp"
#include "gl/context.hpp"

namespace morphogen::cli {

enum class BackendChoice { Auto, Gpu, Cpu };

// A way to make simulators plus the context they live in (null for the CPU
// backend). The context must outlive every simulator the factory makes.
struct Backend {
    std::unique_ptr<gl::Context> context;
    SimulatorFactory makeSimulator;
    std::string reason; // why this backend, printed to stderr
};

BackendChoice parseBackendChoice(const std::string& text); // throws InputError

// Auto uses the GPU unless there is no context or the GL renderer is a
// software rasterizer (llvmpipe, softpipe, swrast), where the CPU backend is
// faster; the reason says which and why.
Backend makeBackend(BackendChoice choice, std::optional<gl::ContextKind> context);

// Reads --context's value (or nullopt when empty); throws InputError.
std::optional<gl::ContextKind> parseContextFlag(const std::string& text);

} // namespace morphogen::cli
