#include "gl/gpu_simulator.hpp"

#include <cfloat>
#include <cmath>

namespace morphogen::gl {

namespace {

// GLSL clamp() with infinite bounds is fine in practice, but finite bounds
// avoid relying on drivers passing infinities through uniforms.
float finite(float v) { return std::isinf(v) ? std::copysign(FLT_MAX, v) : v; }

void setVec4(GLint location, const std::array<float, 4>& v) {
    glUniform4f(location, finite(v[0]), finite(v[1]), finite(v[2]), finite(v[3]));
}

} // namespace

std::vector<ShaderPiece> stepFragmentPieces(const ReactionModel& model) {
    std::string uniforms = "// parameters of model " + model.name() + "\n";
    for (const ParamSpec& p : model.params())
        uniforms += "uniform float p_" + p.name + ";\n";
    return {{"<parameter uniforms>", uniforms},
            embeddedShader(model.glslPath()),
            embeddedShader("glsl/step.frag")};
}

GLenum stateFormat(int chemicals) { return chemicals <= 2 ? GL_RG32F : GL_RGBA32F; }

PingPong::PingPong(int width, int height, GLenum internalFormat, GLenum wrap) {
    for (std::size_t i = 0; i < 2; ++i) {
        m_textures[i] = Texture2D(width, height, internalFormat);
        m_textures[i].setWrap(wrap);
        m_framebuffers[i] = Framebuffer(m_textures[i]);
    }
}

void PingPong::run(const Program& program, int passes) {
    program.use();
    m_vao.bind();
    for (int i = 0; i < passes; ++i) {
        const int next = 1 - m_current;
        m_framebuffers[std::size_t(next)].bind();
        m_textures[std::size_t(m_current)].bind(0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        m_current = next;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

GpuSimulator::GpuSimulator(const Session& session)
    : m_k(StepConstants::fromSession(session)),
      m_pingPong(session.width, session.height, stateFormat(m_k.chemicals),
                 session.edges == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE) {
    const ReactionModel& model = session.reactionModel();
    std::vector<std::string> defines;
    if (m_k.stencil == Stencil::NinePoint)
        defines.push_back("STENCIL_9");
    m_program = Program({embeddedShader("glsl/fullscreen.vert")}, stepFragmentPieces(model),
                        defines);

    m_program.use();
    glUniform1i(m_program.uniform("uState"), 0);
    glUniform2f(m_program.uniform("uInvSize"), 1.0f / float(session.width),
                1.0f / float(session.height));
    glUniform1f(m_program.uniform("uDt"), m_k.dt);
    setVec4(m_program.uniform("uDiffusion"), m_k.diffusion);
    setVec4(m_program.uniform("uClampMin"), m_k.clampMin);
    setVec4(m_program.uniform("uClampMax"), m_k.clampMax);
    for (std::size_t i = 0; i < model.params().size(); ++i)
        glUniform1f(m_program.uniform(("p_" + model.params()[i].name).c_str()), m_k.params[i]);
}

void GpuSimulator::setState(const State& state) { m_pingPong.current().uploadRgba(state.toRgba()); }

State GpuSimulator::state() const {
    return State::fromRgba(m_pingPong.current().downloadRgba(), m_k.domain.width(),
                           m_k.domain.height(), m_k.chemicals);
}

void GpuSimulator::run(int steps) { m_pingPong.run(m_program, steps); }

CopyPass::CopyPass(int width, int height, GLenum internalFormat)
    : m_pingPong(width, height, internalFormat, GL_REPEAT) {
    m_program = Program({embeddedShader("glsl/fullscreen.vert")},
                        {embeddedShader("glsl/copy.frag")}, {});
    m_program.use();
    glUniform1i(m_program.uniform("uState"), 0);
    glUniform2f(m_program.uniform("uInvSize"), 1.0f / float(width), 1.0f / float(height));
}

} // namespace morphogen::gl
