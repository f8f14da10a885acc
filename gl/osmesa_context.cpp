// OSMesa context: Mesa's off-screen rasterizer. The tests run every *_gltest
// under it as well as EGL. GL/osmesa.h pulls in GL/gl.h, so this file must not
// include glad's header.

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

#include "gl/context.hpp"
#include "gl/gl_loader.hpp"

namespace morphogen::gl {

namespace {

class OsMesaContext final : public Context {
public:
    explicit OsMesaContext(OSMesaContext context) : m_context(context), m_buffer(16 * 16 * 4) {}
    ~OsMesaContext() override { OSMesaDestroyContext(m_context); }
    OsMesaContext(const OsMesaContext&) = delete;
    OsMesaContext& operator=(const OsMesaContext&) = delete;

    ContextKind kind() const override { return ContextKind::OsMesa; }
    void makeCurrent() override {
        // All rendering goes to FBOs; the default framebuffer is a small dummy.
        if (!OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, 16, 16))
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
    OSMesaContext raw = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!raw)
        throw std::runtime_error("OSMesaCreateContextAttribs(3.3 core) failed");
    auto context = std::make_unique<OsMesaContext>(raw);
    context->makeCurrent();
    loadGlFunctions(reinterpret_cast<ProcAddressFn>(&OSMesaGetProcAddress), "OSMesa");
    return context;
}

} // namespace morphogen::gl
