#pragma once

#include <memory>
#include <optional>
#include <string>

#include "gl/display_choice.hpp"

namespace morphogen::gl {

enum class ContextKind {
    Egl,    // EGL surfaceless (Mesa) or an EGL device: the default headless context
    OsMesa, // Mesa's off-screen rasterizer (llvmpipe), for tests without EGL
    Glfw,   // a GLFW window: the designer's context (gl/glfw_context.hpp)
};

std::string toString(ContextKind kind);
// "egl", "osmesa", "glfw"; nullopt for anything else.
std::optional<ContextKind> parseContextKind(const std::string& text);
std::string contextKindNames(); // "egl, osmesa, glfw"

// A current OpenGL 3.3 core context with the GL entry points loaded.
class Context {
public:
    virtual ~Context() = default;
    virtual ContextKind kind() const = 0;
    virtual void makeCurrent() = 0;

    // Which context this is, for the backend report: the kind, and for EGL
    // the display candidate chosen ("egl device 1 /dev/dri/renderD128").
    virtual std::string description() const { return toString(kind()); }

    // GL_RENDERER / GL_VENDOR / GL_VERSION of the current context.
    std::string renderer() const;
    std::string vendor() const;
    std::string version() const;
    // llvmpipe, softpipe, swrast: the GPU path is slower there than the CPU backend.
    bool isSoftwareRenderer() const;
};

// The environment variable that picks a headless context when no flag does.
constexpr const char* kContextEnvVar = "MORPHOGEN_CONTEXT";

// Creates a headless context, makes it current, loads GL and checks that float
// render targets work. Picks `requested`, else $MORPHOGEN_CONTEXT, else tries
// EGL then OSMesa. `gpuDevice` (else $MORPHOGEN_GPU_DEVICE) picks EGL's display
// candidate by number; without one EGL prefers a hardware renderer (see
// gl/display_choice.hpp). A requested device means EGL only: with no context
// kind given OSMesa is not tried, and with --context osmesa or glfw the flag
// is an InputError (the environment variable is ignored there). Throws
// InputError for bad requests, std::runtime_error listing what was tried and
// why each failed when nothing works.
std::unique_ptr<Context> createHeadlessContext(std::optional<ContextKind> requested = {},
                                               std::optional<int> gpuDevice = {});

// Backends (one file each; GLFW's is in gl/glfw_context.hpp). Each returns a
// current context with GL loaded or throws std::runtime_error saying why not.
// EGL tries every display candidate; `request` picks one by number (InputError
// when out of range or failed, listing the candidates).
std::unique_ptr<Context> createEglContext(const std::optional<DeviceRequest>& request);
std::unique_ptr<Context> createOsMesaContext();

} // namespace morphogen::gl
