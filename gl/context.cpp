#include "gl/context.hpp"

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <glad/gl.h>

#include "gl/gl_checks.hpp"

namespace morphogen::gl {

std::string toString(ContextKind kind) {
    switch (kind) {
    case ContextKind::Egl:
        return "egl";
    case ContextKind::OsMesa:
        return "osmesa";
    case ContextKind::Glfw:
        return "glfw";
    }
    return "egl";
}

std::optional<ContextKind> parseContextKind(const std::string& text) {
    if (text == "egl")
        return ContextKind::Egl;
    if (text == "osmesa")
        return ContextKind::OsMesa;
    if (text == "glfw")
        return ContextKind::Glfw;
    return std::nullopt;
}

std::string Context::renderer() const {
    const GLubyte* s = glGetString(GL_RENDERER);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

std::string Context::version() const {
    const GLubyte* s = glGetString(GL_VERSION);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

bool Context::isSoftwareRenderer() const {
    const std::string r = renderer();
    for (const char* name : {"llvmpipe", "softpipe", "swrast"})
        if (r.find(name) != std::string::npos)
            return true;
    return false;
}

namespace {
std::unique_ptr<Context> createOne(ContextKind kind) {
    switch (kind) {
    case ContextKind::Egl:
        return createEglContext();
    case ContextKind::OsMesa:
        return createOsMesaContext();
    case ContextKind::Glfw:
        return createGlfwContext(64, 64, "morphogen", false);
    }
    return nullptr;
}
} // namespace

std::unique_ptr<Context> createHeadlessContext(std::optional<ContextKind> requested) {
    if (!requested) {
        if (const char* env = std::getenv(kContextEnvVar); env && *env) {
            requested = parseContextKind(env);
            if (!requested)
                throw std::runtime_error(std::string(kContextEnvVar) + "='" + env +
                                         "' is not a context kind (accepted: egl, osmesa, glfw)");
        }
    }
    const std::vector<ContextKind> order =
        requested ? std::vector<ContextKind>{*requested}
                  : std::vector<ContextKind>{ContextKind::Egl, ContextKind::OsMesa};
    std::string failures;
    for (ContextKind kind : order) {
        try {
            auto context = createOne(kind);
            verifyFloatRenderTargets();
            return context;
        } catch (const std::exception& e) {
            failures += "\n  " + toString(kind) + ": " + e.what();
        }
    }
    throw std::runtime_error("no OpenGL 3.3 core context could be created; tried:" + failures);
}

} // namespace morphogen::gl
