#include "cli/backend.hpp"

#include "core/sim/cpu_simulator.hpp"
#include "core/base/errors.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::cli {

BackendChoice parseBackendChoice(const std::string& text) {
    if (text == "auto")
        return BackendChoice::Auto;
    if (text == "gpu")
        return BackendChoice::Gpu;
    if (text == "cpu")
        return BackendChoice::Cpu;
    throw InputError("--backend '" + text + "' is unknown (accepted: auto, gpu, cpu)");
}

std::optional<gl::ContextKind> parseContextFlag(const std::string& text) {
    if (text.empty())
        return std::nullopt;
    auto kind = gl::parseContextKind(text);
    if (!kind)
        throw InputError("--context '" + text + "' is unknown (accepted: egl, osmesa, glfw)");
    return kind;
}

Backend makeBackend(BackendChoice choice, std::optional<gl::ContextKind> contextKind) {
    auto cpu = [](const Session& s) -> std::unique_ptr<Simulator> {
        return std::make_unique<CpuSimulator>(s);
    };
    Backend backend;
    if (choice == BackendChoice::Cpu) {
        backend.makeSimulator = cpu;
        backend.reason = "cpu backend (requested)";
        return backend;
    }
    try {
        backend.context = gl::createHeadlessContext(contextKind);
    } catch (const std::exception& e) {
        if (choice == BackendChoice::Gpu)
            throw;
        backend.makeSimulator = cpu;
        backend.reason = std::string("cpu backend (auto: no GL context: ") + e.what() + ")";
        return backend;
    }
    const std::string renderer = backend.context->renderer();
    const std::string where = gl::toString(backend.context->kind()) + ", " + renderer;
    if (choice == BackendChoice::Auto && backend.context->isSoftwareRenderer()) {
        backend.context.reset();
        backend.makeSimulator = cpu;
        backend.reason = "cpu backend (auto: the GL renderer is the software rasterizer " +
                         renderer + ", slower than the CPU backend; --backend gpu forces it)";
        return backend;
    }
    backend.makeSimulator = [](const Session& s) -> std::unique_ptr<Simulator> {
        return std::make_unique<gl::GpuSimulator>(s);
    };
    backend.reason = std::string("gpu backend (") +
                     (choice == BackendChoice::Gpu ? "requested" : "auto") + ": " + where + ")";
    return backend;
}

} // namespace morphogen::cli
