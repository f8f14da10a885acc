#pragma once

#include <memory>
#include <optional>
#include <string>

namespace morphogen::gl {

enum class ContextKind {
    Egl,    // EGL surfaceless (Mesa) or an EGL device: the default headless context
    OsMesa, // Mesa's off-screen rasterizer (llvmpipe), for tests without EGL
    Glfw,   // a (hidden) GLFW window: the designer's context
};

std::string toString(ContextKind kind);
// "egl", "osmesa", "glfw"; nullopt for anything else.
std::optional<ContextKind> parseContextKind(const std::string& text);

// A current OpenGL 3.3 core context with the GL entry points loaded.
class Context {
public:
    virtual ~Context() = default;
    virtual ContextKind kind() const = 0;
    virtual void makeCurrent() = 0;

    // GL_RENDERER / GL_VERSION of the current context.
    std::string renderer() const;
    std::string version() const;
    // llvmpipe, softpipe, swrast: the GPU path is slower there than the CPU backend.
    bool isSoftwareRenderer() const;
};

// The environment variable that picks a headless context when no flag does.
constexpr const char* kContextEnvVar = "MORPHOGEN_CONTEXT";

// Creates a headless context, makes it current, loads GL and checks that float
// render targets work. Picks `requested`, else $MORPHOGEN_CONTEXT, else tries
// EGL then OSMesa. Throws std::runtime_error listing what was tried and why
// each failed.
std::unique_ptr<Context> createHeadlessContext(std::optional<ContextKind> requested = {});

// Backends (one file each). Each returns a current context with GL loaded or
// throws std::runtime_error saying why not.
std::unique_ptr<Context> createEglContext();
std::unique_ptr<Context> createOsMesaContext();
std::unique_ptr<Context> createGlfwContext(int width, int height, const std::string& title,
                                           bool visible);

} // namespace morphogen::gl
