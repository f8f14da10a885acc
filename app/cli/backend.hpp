#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/simulator.hpp"
#include "gl/context.hpp"

namespace morphogen::cli {

enum class BackendChoice { Auto, Gpu, Cpu };

// A simulator plus the context it lives in (null for the CPU backend).
struct Backend {
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<Simulator> simulator;
    std::string reason; // why this backend, printed to stderr
};

BackendChoice parseBackendChoice(const std::string& text); // throws InputError

// Auto uses the GPU unless there is no context or the GL renderer is a
// software rasterizer (llvmpipe, softpipe, swrast), where the CPU backend is
// faster; the reason says which and why.
Backend makeBackend(const Session& session, BackendChoice choice,
                    std::optional<gl::ContextKind> context);

// Reads --context's value (or nullopt when empty); throws InputError.
std::optional<gl::ContextKind> parseContextFlag(const std::string& text);

} // namespace morphogen::cli
