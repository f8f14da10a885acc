#pragma once

// Which simulator backend runs a session, shared by the CLI and the designer:
// the GPU simulator on a GL context, or the CPU backend where the only GL is a
// software rasterizer (or there is none).

#include <memory>
#include <optional>
#include <string>

#include "core/sim/runner.hpp"
#include "gl/context.hpp"

namespace morphogen::gl {

enum class BackendChoice { Auto, Gpu, Cpu };

// A way to make simulators plus the context they live in (null for the CPU
// backend, and when the backend was made on a context the caller owns). The
// context must outlive every simulator the factory makes.
struct Backend {
    std::unique_ptr<Context> context;
    SimulatorFactory makeSimulator;
    std::string reason;   // why this backend, printed to stderr
    bool usesGpu = false; // the simulators are GpuSimulators (state in textures)
};

BackendChoice parseBackendChoice(const std::string& text); // throws InputError

// Auto uses the GPU unless there is no context or the GL renderer is a
// software rasterizer (llvmpipe, softpipe, swrast), where the CPU backend is
// faster; the reason says which and why, naming the context (for EGL the
// display candidate) and renderer. `context` and `gpuDevice` are
// createHeadlessContext's. Bad requests (an unknown or failing --gpu-device)
// are InputErrors even for auto: the user asked for something specific.
Backend makeBackend(BackendChoice choice, std::optional<ContextKind> context,
                    std::optional<int> gpuDevice = {});

// The same choice on a context the caller owns and keeps (the designer's
// window): makes it current, and the Backend does not own it. Gpu throws
// std::runtime_error when float render targets do not work there; auto then
// falls back to the CPU backend.
Backend makeBackend(BackendChoice choice, Context& existing);

// Reads --context's value (or nullopt when empty); throws InputError.
std::optional<ContextKind> parseContextFlag(const std::string& text);

// Reads --gpu-device's value (or nullopt when empty); throws InputError.
std::optional<int> parseGpuDeviceFlag(const std::string& text);

} // namespace morphogen::gl
