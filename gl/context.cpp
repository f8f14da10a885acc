#include "gl/context.hpp"

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <glad/gl.h>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "gl/gl_checks.hpp"
#include "gl/glfw_context.hpp"

namespace morphogen::gl {

namespace {

const EnumName<ContextKind> kContextKinds[] = {
    {ContextKind::Egl, "egl"}, {ContextKind::OsMesa, "osmesa"}, {ContextKind::Glfw, "glfw"}};

const EnumAlias<ContextKind> kContextAliases[] = {{"os-mesa", ContextKind::OsMesa},
                                                  {"mesa", ContextKind::OsMesa}};

} // namespace

std::string toString(ContextKind kind) {
    return nameOf(kContextKinds, kind);
}

std::optional<ContextKind> parseContextKind(const std::string& text) {
    return valueNamed(kContextKinds, kContextAliases, text);
}

std::string contextKindNames() {
    return nameList(kContextKinds);
}

std::string Context::renderer() const {
    const GLubyte* s = glGetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string Context::vendor() const {
    const GLubyte* s = glGetString(GL_VENDOR);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string Context::version() const {
    const GLubyte* s = glGetString(GL_VERSION);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

bool Context::isSoftwareRenderer() const {
    return isSoftwareRendererName(renderer());
}

namespace {

std::unique_ptr<Context> createOne(ContextKind kind, const std::optional<DeviceRequest>& device) {
    switch (kind) {
    case ContextKind::Egl:
        return createEglContext(device);
    case ContextKind::OsMesa:
        return createOsMesaContext();
    case ContextKind::Glfw:
        return createGlfwContext(64, 64, "morphogen", false);
    }
    return nullptr;
}

} // namespace

std::unique_ptr<Context> createHeadlessContext(std::optional<ContextKind> requested,
                                               std::optional<int> gpuDevice) {
    if (!requested) {
        if (const char* env = std::getenv(kContextEnvVar); env && *env) {
            requested = parseContextKind(env);
            // Bad input like --context bogus: exit 2, not a fallback to the CPU.
            if (!requested)
                throw InputError(std::string(kContextEnvVar) + "='" + env +
                                 "' is not a context kind (accepted: " + contextKindNames() + ")" +
                                 didYouMean(env, splitNameList(contextKindNames())));
        }
    }
    std::optional<DeviceRequest> device;
    if (gpuDevice) {
        if (requested && *requested != ContextKind::Egl)
            throw InputError("--gpu-device picks an EGL display; it does not apply to the " +
                             toString(*requested) + " context (use --context egl or leave it out)");
        device = DeviceRequest{*gpuDevice, "--gpu-device"};
    } else if (const char* env = std::getenv(kGpuDeviceEnvVar);
               env && *env && (!requested || *requested == ContextKind::Egl)) {
        device = DeviceRequest{parseGpuDevice(env, kGpuDeviceEnvVar), kGpuDeviceEnvVar};
    }
    // A requested display means EGL only: falling back to OSMesa would ignore it.
    const std::vector<ContextKind> order =
        requested ? std::vector<ContextKind>{*requested}
        : device  ? std::vector<ContextKind>{ContextKind::Egl}
                  : std::vector<ContextKind>{ContextKind::Egl, ContextKind::OsMesa};
    std::string failures;
    for (ContextKind kind : order) {
        try {
            auto context = createOne(kind, device);
            verifyFloatRenderTargets();
            return context;
        } catch (const InputError&) {
            throw;
        } catch (const std::exception& e) {
            failures += "\n  " + toString(kind) + ": " + e.what();
        }
    }
    throw std::runtime_error("no OpenGL 3.3 core context could be created; tried:" + failures);
}

} // namespace morphogen::gl
