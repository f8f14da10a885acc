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

template <std::size_t N> void setVec4(GLint location, const std::array<float, N>& v) {
    static_assert(N >= 4);
    glUniform4f(location, finite(v[0]), finite(v[1]), finite(v[2]), finite(v[3]));
}

} // namespace

std::vector<ShaderPiece> stepFragmentPieces(const ReactionModel& model, const StepConstants& k) {
    // Parameters reach the reaction snippet as globals p_<name>, loaded per
    // fragment from a uniform u_<name> or, for mapped ones, from uParamMap.
    static const char* kComponents[] = {"x", "y", "z", "w"};
    std::string text = "// parameters of model " + model.name() + "\n";
    for (const ParamSpec& p : model.params())
        text += "uniform float u_" + p.name + ";\nfloat p_" + p.name + ";\n";
    if (k.hasParamMaps())
        text += "uniform sampler2D uParamMap;\n";
    text += "void loadParams(vec2 uv) {\n";
    if (k.hasParamMaps())
        text += "    vec4 mapped = texture(uParamMap, uv);\n";
    for (std::size_t i = 0; i < model.params().size(); ++i) {
        const std::string& name = model.params()[i].name;
        std::string source = "u_" + name;
        for (std::size_t m = 0; m < k.mappedParams.size(); ++m)
            if (k.mappedParams[m] == int(i))
                source = std::string("mapped.") + kComponents[m];
        text += "    p_" + name + " = " + source + ";\n";
    }
    text += "}\n// Per chemical: the cell's diffusion rate where it is mapped (the operator\n"
            "// was built at rate 1 for it), else 1.\nvec4 rateScale() {\n    return vec4(";
    for (int c = 0; c < 4; ++c) {
        const int m = k.mappedRate[std::size_t(c)];
        text += (c ? ", " : "") +
                (m < 0 ? std::string("1.0")
                       : "p_" + model.params()[std::size_t(k.mappedParams[std::size_t(m)])].name);
    }
    text += ");\n}\n";
    return {
        {"<parameters>", text}, embeddedShader(model.glslPath()), embeddedShader("glsl/step.frag")};
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
    : m_session(session), m_model(&session.reactionModel()),
      m_k(StepConstants::fromSession(session)),
      m_pingPong(session.width, session.height, stateFormat(m_k.chemicals),
                 session.edges == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE) {
    const DiffusionOperator& op = m_k.op;
    buildPrograms();
    if (m_k.integrator == Integrator::SemiImplicit) {
        m_rhs = Texture2D(session.width, session.height, stateFormat(m_k.chemicals));
        m_rhsFramebuffer = Framebuffer(m_rhs);
    }
    if (m_k.hasParamMaps()) {
        m_paramMap = Texture2D(session.width, session.height, GL_RGBA32F);
        m_paramMap.setWrap(session.edges == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        m_paramMap.uploadRgba(m_k.paramMaps.toRgba());
    }
    if (op.form == DiffusionOperator::Form::TensorMap) {
        m_map = Texture2D(session.width, session.height, GL_RGBA32F);
        m_map.setWrap(session.edges == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        m_map.uploadRgba(op.map.toRgba());
    }
}

void GpuSimulator::buildPrograms() {
    const bool semiImplicit = m_k.integrator == Integrator::SemiImplicit;
    m_program = buildProgram(semiImplicit ? "JACOBI_PASS" : nullptr);
    if (semiImplicit) {
        m_program.use();
        glUniform1i(m_program.uniform("uRhs"), 2);
        setVec4(m_program.uniform("uOmega"), m_k.omega);
        m_rhsProgram = buildProgram("RHS_PASS");
    }
}

void GpuSimulator::setFrozen(const std::vector<std::uint8_t>& frozen) {
    const bool hadMask = !m_frozenMask.empty();
    m_frozenMask = frozen;
    if (!frozen.empty()) {
        std::vector<float> rgba(frozen.size() * 4, 0.0f);
        for (std::size_t i = 0; i < frozen.size(); ++i)
            rgba[i * 4] = frozen[i] ? 1.0f : 0.0f;
        if (!m_frozen.id())
            m_frozen = Texture2D(m_k.domain.width(), m_k.domain.height(), GL_RGBA32F);
        m_frozen.uploadRgba(rgba);
    }
    if (hadMask != !frozen.empty())
        buildPrograms(); // the FROZEN variant comes and goes with the mask
}

Program GpuSimulator::buildProgram(const char* pass) const {
    const ReactionModel& model = *m_model;
    const Session& session = m_session;
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
    if (m_k.tiled())
        defines.push_back("TILES");
    if (pass)
        defines.push_back(pass);
    if (!m_frozenMask.empty())
        defines.push_back("FROZEN");
    Program program({embeddedShader("glsl/fullscreen.vert")}, stepFragmentPieces(model, m_k),
                    defines);

    program.use();
    glUniform1i(program.uniform("uState"), 0);
    glUniform2f(program.uniform("uInvSize"), 1.0f / float(session.width),
                1.0f / float(session.height));
    glUniform1f(program.uniform("uDt"), m_k.dt);
    setVec4(program.uniform("uDiffusion"), op.rates);
    setVec4(program.uniform("uClampMin"), m_k.clampMin);
    setVec4(program.uniform("uClampMax"), m_k.clampMax);
    for (std::size_t i = 0; i < model.params().size(); ++i)
        glUniform1f(program.uniform(("u_" + model.params()[i].name).c_str()), m_k.params[i]);
    glUniform1i(program.uniform("uParamMap"), 3);
    glUniform1i(program.uniform("uFrozen"), 4);
    if (m_k.tiled())
        glUniform2i(program.uniform("uTile"), m_k.tile[0], m_k.tile[1]);

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
    if (m_paramMap.id())
        m_paramMap.bind(3);
    if (m_frozen.id())
        m_frozen.bind(4);
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
