#include "gl/backend.hpp"

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/gl_checks.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::gl {

namespace {

const EnumName<BackendChoice> kBackends[] = {
    {BackendChoice::Auto, "auto"}, {BackendChoice::Gpu, "gpu"}, {BackendChoice::Cpu, "cpu"}};

const EnumAlias<BackendChoice> kBackendAliases[] = {{"opengl", BackendChoice::Gpu},
                                                    {"gl", BackendChoice::Gpu}};

} // namespace

BackendChoice parseBackendChoice(const std::string& text) {
    if (const std::optional<BackendChoice> choice = valueNamed(kBackends, kBackendAliases, text))
        return *choice;
    throw InputError("--backend '" + text + "' is unknown (accepted: " + nameList(kBackends) + ")" +
                     didYouMean(text, splitNameList(nameList(kBackends))));
}

std::optional<ContextKind> parseContextFlag(const std::string& text) {
    if (text.empty())
        return std::nullopt;
    auto kind = parseContextKind(text);
    if (!kind)
        throw InputError("--context '" + text + "' is unknown (accepted: " + contextKindNames() +
                         ")" + didYouMean(text, splitNameList(contextKindNames())));
    return kind;
}

std::optional<int> parseGpuDeviceFlag(const std::string& text) {
    if (text.empty())
        return std::nullopt;
    return parseGpuDevice(text, "--gpu-device");
}

namespace {

std::unique_ptr<Simulator> makeCpu(const Session& s) {
    return std::make_unique<CpuSimulator>(s);
}

Backend cpuBackend(std::string reason) {
    Backend backend;
    backend.makeSimulator = makeCpu;
    backend.reason = std::move(reason);
    return backend;
}

// The choice once a context is current: `owned` is moved into the Backend
// when the GPU is used.
Backend chooseOn(BackendChoice choice, Context& context, std::unique_ptr<Context> owned) {
    const std::string renderer = context.renderer();
    const std::string where = context.description() + ", " + renderer;
    if (choice == BackendChoice::Auto && context.isSoftwareRenderer())
        return cpuBackend("cpu backend (auto: the GL renderer (" + context.description() +
                          ") is the software rasterizer " + renderer +
                          ", slower than the CPU backend; --backend gpu forces it)");
    Backend backend;
    backend.context = std::move(owned);
    backend.makeSimulator = [](const Session& s) -> std::unique_ptr<Simulator> {
        return std::make_unique<GpuSimulator>(s);
    };
    backend.usesGpu = true;
    backend.reason = std::string("gpu backend (") +
                     (choice == BackendChoice::Gpu ? "requested" : "auto") + ": " + where + ")";
    return backend;
}

} // namespace

Backend makeBackend(BackendChoice choice, std::optional<ContextKind> contextKind,
                    std::optional<int> gpuDevice) {
    if (choice == BackendChoice::Cpu)
        return cpuBackend("cpu backend (requested)");
    std::unique_ptr<Context> context;
    try {
        context = createHeadlessContext(contextKind, gpuDevice);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        if (choice == BackendChoice::Gpu)
            throw;
        return cpuBackend(std::string("cpu backend (auto: no GL context: ") + e.what() + ")");
    }
    Context& current = *context;
    return chooseOn(choice, current, std::move(context));
}

Backend makeBackend(BackendChoice choice, Context& existing) {
    if (choice == BackendChoice::Cpu)
        return cpuBackend("cpu backend (requested)");
    existing.makeCurrent();
    try {
        verifyFloatRenderTargets();
    } catch (const std::exception& e) {
        if (choice == BackendChoice::Gpu)
            throw std::runtime_error(existing.description() + " context: " + e.what());
        return cpuBackend("cpu backend (auto: " + existing.description() + " context: " + e.what() +
                          ")");
    }
    return chooseOn(choice, existing, nullptr);
}

} // namespace morphogen::gl
