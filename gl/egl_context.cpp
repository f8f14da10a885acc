// EGL headless context. Every display candidate is tried (each EGL device,
// Mesa's surfaceless platform, the default display) and the choice among the
// ones that work is gl/display_choice's: hardware before software, whichever is
// listed first, so that a GPU server's vendor driver wins over llvmpipe.

#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/errors.hpp"
#include "gl/context.hpp"
#include "gl/display_choice.hpp"
#include "gl/gl_checks.hpp"
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

// Displays that hold a live EglContext, with their context counts: a later
// search must not terminate them (EGL hands out the same display handle again,
// and eglTerminate would pull it from under the earlier context).
std::map<EGLDisplay, int> g_liveDisplays;

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context, std::string description)
        : m_display(display), m_context(context), m_description(std::move(description)) {
        ++g_liveDisplays[m_display];
    }
    ~EglContext() override {
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(m_display, m_context);
        if (--g_liveDisplays[m_display] == 0)
            g_liveDisplays.erase(m_display);
    }
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    ContextKind kind() const override { return ContextKind::Egl; }
    std::string description() const override { return m_description; }
    void makeCurrent() override {
        if (!eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, m_context))
            throw std::runtime_error("eglMakeCurrent failed: " + eglErrorName(eglGetError()));
    }

private:
    EGLDisplay m_display;
    EGLContext m_context;
    std::string m_description;
};

bool hasExtension(const char* list, const std::string& name) {
    if (!list)
        return false;
    const std::string all = std::string(" ") + list + " ";
    return all.find(" " + name + " ") != std::string::npos;
}

// A display to try, and what EGL says about it before any context exists.
struct Display {
    std::string name;
    EGLDisplay display = EGL_NO_DISPLAY;
    bool device = false;
    bool softwareDevice = false;
};

// The device's DRM file, render node first (what headless rendering opens).
std::string drmFile(PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString, EGLDeviceEXT device) {
    if (!queryDeviceString)
        return "";
    const char* extensions = queryDeviceString(device, EGL_EXTENSIONS);
    const char* file = nullptr;
    if (hasExtension(extensions, "EGL_EXT_device_drm_render_node"))
        file = queryDeviceString(device, EGL_DRM_RENDER_NODE_FILE_EXT);
    if (!file && hasExtension(extensions, "EGL_EXT_device_drm"))
        file = queryDeviceString(device, EGL_DRM_DEVICE_FILE_EXT);
    return file ? file : "";
}

// Every EGL device, then Mesa's surfaceless platform, then the default
// display; a display handle met twice (Mesa may hand out the same one) is
// listed once.
std::vector<Display> candidateDisplays() {
    std::vector<Display> displays;
    auto add = [&displays](Display d) {
        if (d.display == EGL_NO_DISPLAY)
            return;
        for (const Display& known : displays)
            if (known.display == d.display)
                return;
        displays.push_back(std::move(d));
    };
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLint count = 0;
    if (getPlatformDisplay && queryDevices &&
        hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
        queryDevices(0, nullptr, &count) && count > 0) {
        std::vector<EGLDeviceEXT> devices(std::size_t(count), nullptr);
        if (!queryDevices(count, devices.data(), &count))
            count = 0;
        for (EGLint i = 0; i < count; ++i) {
            const EGLDeviceEXT device = devices[std::size_t(i)];
            Display d;
            d.name = "device " + std::to_string(i);
            d.device = true;
            if (const std::string file = drmFile(queryDeviceString, device); !file.empty())
                d.name += " " + file;
            d.softwareDevice =
                queryDeviceString &&
                hasExtension(queryDeviceString(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
            d.display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
            add(std::move(d));
        }
    }
    if (getPlatformDisplay && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless"))
        add({"surfaceless",
             getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)});
    add({"default display", eglGetDisplay(EGL_DEFAULT_DISPLAY)});
    return displays;
}

// A 3.3 core context on `display`, made current with GL loaded, or a
// std::runtime_error saying which step failed.
EGLContext createOn(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor))
        throw std::runtime_error("eglInitialize: " + eglErrorName(eglGetError()));
    if (!eglBindAPI(EGL_OPENGL_API))
        throw std::runtime_error("no desktop OpenGL API");
    // Surfaceless rendering into FBOs needs no config where EGL_KHR_no_config_context exists.
    // Elsewhere ask for a pbuffer-capable config: EGL_SURFACE_TYPE defaults to
    // EGL_WINDOW_BIT, which a device display (no window system) never offers.
    EGLConfig config = nullptr;
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                    EGL_OPENGL_BIT, EGL_NONE};
    EGLint configCount = 0;
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_no_config_context") &&
        (!eglChooseConfig(display, configAttribs, &config, 1, &configCount) || configCount == 0))
        throw std::runtime_error("no OpenGL-capable config");
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     3,
                                     EGL_CONTEXT_MINOR_VERSION,
                                     3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT)
        throw std::runtime_error("eglCreateContext(3.3 core): " + eglErrorName(eglGetError()));
    try {
        if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
            throw std::runtime_error("eglMakeCurrent: " + eglErrorName(eglGetError()));
        loadGlFunctions(reinterpret_cast<ProcAddressFn>(&eglGetProcAddress), "EGL");
        verifyFloatRenderTargets();
    } catch (...) {
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        throw;
    }
    return context;
}

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "unknown";
}

} // namespace

std::unique_ptr<Context> createEglContext(const std::optional<DeviceRequest>& request) {
    std::vector<Display> displays = candidateDisplays();
    std::vector<DisplayCandidate> candidates;
    std::vector<EGLContext> contexts;
    for (const Display& d : displays) {
        DisplayCandidate c;
        c.name = d.name;
        c.device = d.device;
        c.softwareDevice = d.softwareDevice;
        EGLContext context = EGL_NO_CONTEXT;
        try {
            context = createOn(d.display);
            c.renderer = glString(GL_RENDERER);
            c.vendor = glString(GL_VENDOR);
            eglMakeCurrent(d.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        } catch (const std::exception& e) {
            c.error = e.what();
        }
        candidates.push_back(std::move(c));
        contexts.push_back(context);
    }
    // Whatever the outcome, only the chosen context and its display stay.
    auto release = [&](std::size_t keep) {
        for (std::size_t i = 0; i < displays.size(); ++i) {
            if (i == keep)
                continue;
            if (contexts[i] != EGL_NO_CONTEXT)
                eglDestroyContext(displays[i].display, contexts[i]);
            if (g_liveDisplays.count(displays[i].display) == 0)
                eglTerminate(displays[i].display);
        }
    };
    DisplayChoice choice;
    try {
        choice = chooseDisplay(candidates, request);
    } catch (const InputError&) {
        release(displays.size());
        throw;
    } catch (const std::exception& e) {
        release(displays.size());
        throw std::runtime_error(std::string("EGL: ") + e.what());
    }
    release(choice.index);
    std::string description = "egl " + candidates[choice.index].name;
    if (!choice.note.empty())
        description += "; " + choice.note;
    auto result = std::make_unique<EglContext>(displays[choice.index].display,
                                               contexts[choice.index], description);
    // The GL entry points last loaded belong to the last candidate tried;
    // under glvnd another vendor's differ.
    result->makeCurrent();
    loadGlFunctions(reinterpret_cast<ProcAddressFn>(&eglGetProcAddress), "EGL");
    return result;
}

} // namespace morphogen::gl
