#include "gl/gl_checks.hpp"

#include <stdexcept>
#include <string>

#include "gl/objects.hpp"

namespace morphogen::gl {

void verifyFloatRenderTargets() {
    // Values a half-float or unorm target would not keep exactly.
    const float probe[4] = {1.5f, -2.25f, 1.0e6f + 0.5f, 0.1f};
    for (GLenum format : {GLenum(GL_RGBA32F), GLenum(GL_RG32F)}) {
        const char* name = format == GL_RGBA32F ? "RGBA32F" : "RG32F";
        Texture2D texture(4, 4, format);
        Framebuffer framebuffer(texture);
        framebuffer.bind();
        glClearBufferfv(GL_COLOR, 0, probe);
        const std::vector<float> back = texture.downloadRgba();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        const int channels = format == GL_RGBA32F ? 4 : 2;
        for (int c = 0; c < channels; ++c)
            if (back[std::size_t(c)] != probe[c])
                throw std::runtime_error(std::string("float render target ") + name +
                                         " does not hold values exactly (wrote " +
                                         std::to_string(probe[c]) + ", read " +
                                         std::to_string(back[std::size_t(c)]) + ")");
    }
}

} // namespace morphogen::gl
