#include "gl/gpu_simulator.hpp"

#include <cfloat>
#include <cmath>

namespace morphogen::gl {

namespace {

// GLSL clamp() with infinite bounds is fine in practice, but finite bounds
// avoid relying on drivers passing infinities through uniforms.
float finite(float v) {
    return std::isinf(v) ? std::copysign(FLT_MAX, v) : v;
}

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

GLenum stateFormat(int chemicals) {
    return chemicals <= 2 ? GL_RG32F : GL_RGBA32F;
}

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
    const DiffusionOperator& op = m_k.op;
    const bool semiImplicit = m_k.integrator == Integrator::SemiImplicit;
    m_program = buildProgram(session, semiImplicit ? "JACOBI_PASS" : nullptr);
    if (semiImplicit) {
        m_program.use();
        glUniform1i(m_program.uniform("uRhs"), 2);
        setVec4(m_program.uniform("uOmega"), m_k.omega);
        m_rhsProgram = buildProgram(session, "RHS_PASS");
        m_rhs = Texture2D(session.width, session.height, stateFormat(m_k.chemicals));
        m_rhsFramebuffer = Framebuffer(m_rhs);
    }
    if (op.form == DiffusionOperator::Form::TensorMap) {
        m_map = Texture2D(session.width, session.height, GL_RGBA32F);
        m_map.setWrap(session.edges == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        m_map.uploadRgba(op.map.toRgba());
    }
}

Program GpuSimulator::buildProgram(const Session& session, const char* pass) const {
    const ReactionModel& model = session.reactionModel();
    using Form = DiffusionOperator::Form;
    const DiffusionOperator& op = m_k.op;
    std::vector<std::string> defines;
    switch (op.form) {
    case Form::Laplacian5:
        break;
    case Form::Laplacian9:
        defines.push_back("STENCIL_9");
        break;
    case Form::Kernel3:
        defines.push_back("KERNEL_3");
        break;
    case Form::Kernel5:
        defines.push_back("KERNEL_5");
        break;
    case Form::TensorMap:
        defines.push_back("TENSOR_MAP");
        break;
    }
    if (pass)
        defines.push_back(pass);
    Program program({embeddedShader("glsl/fullscreen.vert")}, stepFragmentPieces(model), defines);

    program.use();
    glUniform1i(program.uniform("uState"), 0);
    glUniform2f(program.uniform("uInvSize"), 1.0f / float(session.width),
                1.0f / float(session.height));
    glUniform1f(program.uniform("uDt"), m_k.dt);
    setVec4(program.uniform("uDiffusion"), op.rates);
    setVec4(program.uniform("uClampMin"), m_k.clampMin);
    setVec4(program.uniform("uClampMax"), m_k.clampMax);
    for (std::size_t i = 0; i < model.params().size(); ++i)
        glUniform1f(program.uniform(("p_" + model.params()[i].name).c_str()), m_k.params[i]);

    if (op.form == Form::Kernel3 || op.form == Form::Kernel5) {
        // One vec4 per tap, one component per chemical.
        std::vector<float> weights(25 * 4, 0.0f);
        for (std::size_t tap = 0; tap < 25; ++tap)
            for (int c = 0; c < op.chemicals; ++c)
                weights[tap * 4 + std::size_t(c)] = float(op.kernels[std::size_t(c)].w[tap]);
        glUniform4fv(program.uniform("uKernel"), 25, weights.data());
    }
    if (op.form == Form::TensorMap) {
        glUniform1i(program.uniform("uMap"), 1);
        std::array<float, 4> m{}, dc{}, ds{};
        for (int c = 0; c < op.chemicals; ++c) {
            m[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][0];
            dc[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][1];
            ds[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][2];
        }
        setVec4(program.uniform("uMapM"), m);
        setVec4(program.uniform("uMapDc"), dc);
        setVec4(program.uniform("uMapDs"), ds);
    }
    return program;
}

void GpuSimulator::bindAuxiliaryTextures() const {
    if (m_map.id())
        m_map.bind(1);
    if (m_rhs.id())
        m_rhs.bind(2);
}

void GpuSimulator::setState(const State& state) {
    m_pingPong.current().uploadRgba(state.toRgba());
}

State GpuSimulator::state() const {
    return State::fromRgba(m_pingPong.current().downloadRgba(), m_k.domain.width(),
                           m_k.domain.height(), m_k.chemicals);
}

void GpuSimulator::run(int steps) {
    bindAuxiliaryTextures();
    if (m_k.integrator == Integrator::ExplicitEuler) {
        m_pingPong.run(m_program, steps);
        return;
    }
    for (int i = 0; i < steps; ++i) {
        // rhs = c + dt f(c), then Jacobi sweeps from x0 = c.
        m_rhsProgram.use();
        m_pingPong.vertexArray().bind();
        m_rhsFramebuffer.bind();
        m_pingPong.current().bind(0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        m_pingPong.run(m_program, m_k.jacobiSweeps);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

CopyPass::CopyPass(int width, int height, GLenum internalFormat)
    : m_pingPong(width, height, internalFormat, GL_REPEAT) {
    m_program =
        Program({embeddedShader("glsl/fullscreen.vert")}, {embeddedShader("glsl/copy.frag")}, {});
    m_program.use();
    glUniform1i(m_program.uniform("uState"), 0);
    glUniform2f(m_program.uniform("uInvSize"), 1.0f / float(width), 1.0f / float(height));
}

} // namespace morphogen::gl
