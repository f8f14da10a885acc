// EGL headless context: Mesa's surfaceless platform first, then an EGL device
// (NVIDIA's headless path), then the default display.

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "gl/gl_loader.hpp"

namespace morphogen::gl {

namespace {

std::string eglErrorName(EGLint error) {
    switch (error) {
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    default:
        return "EGL error " + std::to_string(error);
    }
}

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context) : m_display(display), m_context(context) {}
    ~EglContext() override {
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(m_display, m_context);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    ContextKind kind() const override { return ContextKind::Egl; }
    void makeCurrent() override {
        if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
            throw std::runtime_error("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
    }

private:
    EGLDisplay m_display;
    EGLContext m_context;
};

bool hasExtension(const char* list, const std::string& name) {
    if (!list)
        return false;
    const std::string all = std::string(" ") + list + " ";
    return all.find(" " + name + " ") != std::string::npos;
}

std::vector<std::pair<std::string, EGLDisplay>> candidateDisplays() {
    std::vector<std::pair<std::string, EGLDisplay>> displays;
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY)
            displays.emplace_back("surfaceless", d);
    }
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (getPlatformDisplay && queryDevices &&
        hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (queryDevices(8, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY)
                    displays.emplace_back("device " + std::to_string(i), d);
            }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY)
        displays.emplace_back("default display", d);
    return displays;
}

} // namespace

std::unique_ptr<Context> createEglContext() {
    std::string failures;
    for (auto& [name, display] : candidateDisplays()) {
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display, &major, &minor)) {
            failures += " [" + name + ": eglInitialize: " + eglErrorName(eglGetError()) + "]";
            continue;
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            failures += " [" + name + ": no desktop OpenGL API]";
            continue;
        }
        // Surfaceless rendering into FBOs needs no config where EGL_KHR_no_config_context exists.
        EGLConfig config = nullptr;
        const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint configCount = 0;
        if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context") &&
            (!eglChooseConfig(display, configAttribs, &config, 1, &configCount) ||
             configCount == 0)) {
            failures += " [" + name + ": no OpenGL-capable config]";
            continue;
        }
        const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
        EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
        if (context == EGL_NO_CONTEXT) {
            failures +=
                " [" + name + ": eglCreateContext(3.3 core): " + eglErrorName(eglGetError()) + "]";
            continue;
        }
        auto result = std::make_unique<EglContext>(display, context);
        try {
            result->makeCurrent();
            loadGlFunctions(reinterpret_cast<ProcAddressFn>(&eglGetProcAddress), "EGL");
        } catch (const std::exception& e) {
            failures += " [" + name + ": " + e.what() + "]";
            continue;
        }
        return result;
    }
    if (failures.empty())
        failures = " no EGL display found";
    throw std::runtime_error("EGL:" + failures);
}

} // namespace morphogen::gl
