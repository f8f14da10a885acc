#include "bench/bench_copy_pass.hpp"

#include <string>

namespace morphogen::bench {

CopyPass::CopyPass(int width, int height, int chemicals)
    : m_pingPong(width, height, gl::stateFormat(chemicals), GL_REPEAT,
                 gl::stateTextures(chemicals)) {
    const int textures = gl::stateTextures(chemicals);
    m_program = gl::Program({gl::embeddedShader("glsl/fullscreen.vert")},
                            {gl::embeddedShader("glsl/copy.frag")},
                            {"STATE_TEXTURES " + std::to_string(textures)});
    m_program.use();
    for (int t = 0; t < textures; ++t)
        glUniform1i(m_program.uniform(("uState" + std::to_string(t)).c_str()), gl::kStateUnits[t]);
    glUniform2f(m_program.uniform("uInvSize"), 1.0f / float(width), 1.0f / float(height));
}

} // namespace morphogen::bench
