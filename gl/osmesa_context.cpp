// OSMesa context: Mesa's off-screen rasterizer. The tests run every *_gltest
// under it as well as EGL. GL/osmesa.h pulls in GL/gl.h, so this file must not
// include glad's header.

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gl/context.hpp"
#include "gl/gl_loader.hpp"

namespace morphogen::gl {

namespace {

// libOSMesa is opened on first use, not linked: it links LLVM (llvmpipe), and
// a linked library is mapped and relocated at every start, ~47 MB resident
// in every command (a CPU render, --help) that never makes a context.
struct OsMesaApi {
    decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

template <class Fn> void bind(void* library, const char* name, Fn& fn) {
    fn = reinterpret_cast<Fn>(dlsym(library, name));
    if (!fn)
        throw std::runtime_error(std::string("libOSMesa has no ") + name);
}

// Throws std::runtime_error when the library is not installed (then the
// next call tries again). Never closed: Mesa does not expect to be unloaded.
const OsMesaApi& osMesa() {
    static const OsMesaApi api = [] {
        void* library = nullptr;
        std::string why;
        for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"}) {
            library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
            if (library)
                break;
            const char* error = dlerror();
            why += std::string(why.empty() ? "" : "; ") + (error ? error : name);
        }
        if (!library)
            throw std::runtime_error("cannot load libOSMesa (" + why + ")");
        OsMesaApi loaded;
        bind(library, "OSMesaCreateContextAttribs", loaded.createContextAttribs);
        bind(library, "OSMesaMakeCurrent", loaded.makeCurrent);
        bind(library, "OSMesaDestroyContext", loaded.destroyContext);
        bind(library, "OSMesaGetProcAddress", loaded.getProcAddress);
        return loaded;
    }();
    return api;
}

class OsMesaContext final : public Context {
public:
    explicit OsMesaContext(OSMesaContext context) : m_context(context), m_buffer(16 * 16 * 4) {}
    ~OsMesaContext() override { osMesa().destroyContext(m_context); }
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    ContextKind kind() const override { return ContextKind::OsMesa; }
    void makeCurrent() override {
        // All rendering goes to FBOs; the default framebuffer is a small dummy.
        if (!osMesa().makeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, 16, 16))
            throw std::runtime_error("OSMesaMakeCurrent failed");
    }

private:
    OSMesaContext m_context;
    std::vector<unsigned char> m_buffer;
};

} // namespace

std::unique_ptr<Context> createOsMesaContext() {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_ACCUM_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    const OsMesaApi& api = osMesa();
    OSMesaContext raw = api.createContextAttribs(attribs, nullptr);
    if (!raw)
        throw std::runtime_error("OSMesaCreateContextAttribs(3.3 core) failed");
    auto context = std::make_unique<OsMesaContext>(raw);
    context->makeCurrent();
    loadGlFunctions(reinterpret_cast<ProcAddressFn>(api.getProcAddress), "OSMesa");
    return context;
}

} // namespace morphogen::gl
