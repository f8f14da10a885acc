#include "gl/gpu_simulator.hpp"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <iterator>
#include <string>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_diagonals.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/operators/stability.hpp"

namespace morphogen::gl {

namespace {

// GLSL clamp() with infinite bounds is fine in practice, but finite bounds
// avoid relying on drivers passing infinities through uniforms.
float finite(float v) {
    return std::isinf(v) ? std::copysign(FLT_MAX, v) : v;
}

// One vec4 per state texture from a per-chemical array.
template <class T, std::size_t N>
void setChemicalVec4s(GLint location, const std::array<T, N>& v, int textures) {
    std::vector<float> packed(std::size_t(textures) * 4);
    for (std::size_t i = 0; i < packed.size(); ++i)
        packed[i] = finite(float(v[i]));
    glUniform4fv(location, textures, packed.data());
}

// The sampler's wrap mode is the grid's edge rule: textureOffset then reads
// neighbours with no index arithmetic (the fast path). Tiled grids fetch
// inside the tile and do not depend on it.
GLenum wrapMode(const Domain& domain) {
    return domain.edges() == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE;
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
    text +=
        "}\n// Per chemical: the cell's diffusion rate where it is mapped (the operator\n"
        "// was built at rate 1 for it), else 1.\nvoid rateScale(out vec4 scale[STATE_TEXTURES]) "
        "{\n";
    for (int t = 0; t < stateTextures(k.chemicals); ++t) {
        text += "    scale[" + std::to_string(t) + "] = vec4(";
        for (int c = 4 * t; c < 4 * t + 4; ++c) {
            const int m = c < k.chemicals ? k.mappedRate[std::size_t(c)] : -1;
            text +=
                (c > 4 * t ? ", " : "") +
                (m < 0 ? std::string("1.0")
                       : "p_" + model.params()[std::size_t(k.mappedParams[std::size_t(m)])].name);
        }
        text += ");\n";
    }
    text += "}\n";
    std::string modelDefines;
    for (const std::string& define : model.glslDefines())
        modelDefines += "#define " + define + "\n";
    return {{"<parameters>", text},
            {"<model defines>", modelDefines},
            embeddedShader(model.glslPath()),
            embeddedShader("glsl/step.frag")};
}

GLenum stateFormat(int chemicals) {
    return chemicals <= 2 ? GL_RG32F : GL_RGBA32F;
}

int stateTextures(int chemicals) {
    return (chemicals + 3) / 4;
}

PingPong::PingPong(int width, int height, GLenum internalFormat, GLenum wrap, int count)
    : m_width(width), m_height(height) {
    assert(count >= 1 && count <= int(std::size(kStateUnits)));
    for (std::size_t i = 0; i < 2; ++i) {
        std::vector<const Texture2D*> colours;
        m_textures[i].resize(std::size_t(count));
        for (Texture2D& texture : m_textures[i]) {
            texture = Texture2D(width, height, internalFormat);
            texture.setWrap(wrap);
            colours.push_back(&texture);
        }
        m_framebuffers[i] = Framebuffer(colours);
    }
}

void PingPong::bindCurrent() const {
    for (int t = 0; t < count(); ++t)
        current(t).bind(kStateUnits[t]);
}

void PingPong::runRects(const Program& program, int passes, const std::vector<CellRect>& rects) {
    if (!m_otherMatches) {
        // The other set becomes a copy of the current one, attachment by attachment.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffers[std::size_t(m_current)].id());
        for (int t = 0; t < count(); ++t) {
            glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + t));
            m_textures[std::size_t(1 - m_current)][std::size_t(t)].bind(kStateUnits[0]);
            glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, m_width, m_height);
        }
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        m_otherMatches = true;
    }
    program.use();
    m_vao.bind();
    glEnable(GL_SCISSOR_TEST);
    for (int i = 0; i < passes; ++i) {
        const int next = 1 - m_current;
        m_framebuffers[std::size_t(next)].bind();
        bindCurrent();
        for (const CellRect& r : rects) {
            glViewport(r.x, r.y, r.width, r.height);
            glScissor(r.x, r.y, r.width, r.height);
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        m_current = next;
    }
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, m_width, m_height);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PingPong::run(const Program& program, int passes) {
    if (passes > 0)
        m_otherMatches = false;
    program.use();
    m_vao.bind();
    for (int i = 0; i < passes; ++i) {
        const int next = 1 - m_current;
        m_framebuffers[std::size_t(next)].bind();
        bindCurrent();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        m_current = next;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

GpuSimulator::GpuSimulator(const Session& session)
    : m_session(session), m_model(&session.reactionModel()),
      m_k(StepConstants::fromSession(session)),
      m_pingPong(session.width, session.height, stateFormat(m_k.chemicals),
                 wrapMode(session.domain()), stateTextures(m_k.chemicals)) {
    const DiffusionOperator& op = m_k.op;
    buildPrograms();
    if (m_k.integrator == Integrator::SemiImplicit) {
        std::vector<const Texture2D*> colours;
        m_rhs.resize(std::size_t(m_pingPong.count()));
        for (Texture2D& texture : m_rhs) {
            texture = Texture2D(session.width, session.height, stateFormat(m_k.chemicals));
            colours.push_back(&texture);
        }
        m_rhsFramebuffer = Framebuffer(colours);
    }
    if (m_k.hasParamMaps()) {
        m_paramMap = Texture2D(session.width, session.height, GL_RGBA32F);
        m_paramMap.setWrap(wrapMode(session.domain()));
        m_paramMap.uploadRgba(m_k.paramMaps.toRgba());
    }
    if (const Atlas* atlas = m_k.domain.atlasMap()) {
        m_connectivity = Texture2D(atlas->width(), atlas->height(), GL_RGBA32UI);
        m_connectivity.uploadRgbaUint(atlas->connectivityMap());
        if (const AtlasWeights* weights = m_k.domain.atlasWeights()) {
            m_weights = Texture2D(atlas->width(), atlas->height(), GL_RGBA32F);
            m_weights.uploadRgba(coefficientTexels(*weights));
            if (weights->hasDiagonals()) {
                m_cross = Texture2D(atlas->width(), atlas->height(), GL_RGBA32F);
                m_cross.uploadRgba(diagonalTexels(*weights));
            }
            if (m_k.drifting()) {
                m_drift[0] = Texture2D(atlas->width(), atlas->height(), GL_RGBA32F);
                m_drift[0].uploadRgba(driftInflowTexels(*weights));
                m_drift[1] = Texture2D(atlas->width(), atlas->height(), GL_R32F);
                const std::vector<float> outflow = driftOutflowTexels(*weights);
                m_drift[1].uploadRows(0, atlas->height(), outflow.data());
            }
            if (m_k.tensorWeighted()) {
                const std::array<std::vector<float>, 4> texels = tensorTexels(*weights->tensor);
                for (std::size_t i = 0; i < 4; ++i) {
                    m_tensor[i] = Texture2D(atlas->width(), atlas->height(), GL_RGBA32F);
                    m_tensor[i].uploadRgba(texels[i]);
                }
            }
        }
        if (op.form == DiffusionOperator::Form::Laplacian9 || m_k.crossWeighted() ||
            m_k.tensorWeighted()) {
            // The weights' diagonals are non-zero only where both orders agree:
            // the cross term reads order 0 alone.
            const auto diagonals = atlasDiagonals(*atlas);
            const int orders = op.form == DiffusionOperator::Form::Laplacian9 ? 2 : 1;
            for (int order = 0; order < orders; ++order) {
                m_diagonals[order] = Texture2D(atlas->width(), atlas->height(), GL_RGBA32UI);
                m_diagonals[order].uploadRgbaUint(packedDiagonals(*atlas, diagonals, order));
            }
        }
    }
    if (op.form == DiffusionOperator::Form::TensorMap) {
        m_map = Texture2D(session.width, session.height, GL_RGBA32F);
        m_map.setWrap(wrapMode(session.domain()));
        m_map.uploadRgba(op.map.toRgba());
    }
}

void GpuSimulator::buildPrograms() {
    const bool semiImplicit = m_k.integrator == Integrator::SemiImplicit;
    m_program = buildProgram(semiImplicit ? "JACOBI_PASS" : nullptr);
    if (semiImplicit) {
        m_program.use();
        for (int t = 0; t < m_pingPong.count(); ++t)
            glUniform1i(m_program.uniform(("uRhs" + std::to_string(t)).c_str()), kRhsUnits[t]);
        setChemicalVec4s(m_program.uniform("uOmega"), m_k.omega, m_pingPong.count());
        std::array<float, kMaxChemicals> all;
        all.fill(1.0f);
        setChemicalVec4s(m_program.uniform("uRelaxing"), all, m_pingPong.count());
        m_rhsProgram = buildProgram("RHS_PASS");
    }
}

void GpuSimulator::setFrozen(const std::vector<std::uint8_t>& frozen) {
    const bool hadMask = !m_frozenMask.empty();
    m_frozenMask = frozen;
    if (!frozen.empty()) {
        // One byte per cell (255 reads as 1.0): a big cascade's mask costs
        // a sixteenth of an RGBA float texture, and no float copy to upload.
        std::vector<std::uint8_t> bytes(frozen.size());
        for (std::size_t i = 0; i < frozen.size(); ++i)
            bytes[i] = frozen[i] ? 255 : 0;
        const int w = m_k.domain.width(), h = m_k.domain.height();
        if (!m_frozen.id())
            m_frozen = Texture2D(w, h, GL_R8);
        m_frozen.uploadBytesRect(0, 0, w, h, bytes.data());
    }
    if (hadMask != !frozen.empty())
        buildPrograms(); // the FROZEN variant comes and goes with the mask
}

int stillTextures(const StepConstants& k) {
    using Form = DiffusionOperator::Form;
    // The 3x3 and 5x5 kernels and the tensor operators carry their rates in
    // their own uniforms: only the Laplacians' term is known to vanish with
    // a rate of 0.
    if ((k.op.form != Form::Laplacian5 && k.op.form != Form::Laplacian9) || k.tensorWeighted())
        return 0;
    int mask = 0;
    for (int t = 0; t < stateTextures(k.chemicals); ++t) {
        bool still = true;
        for (int c = 4 * t; c < std::min(4 * t + 4, k.chemicals); ++c)
            still = still && k.op.rates[std::size_t(c)] == 0.0f &&
                    (!k.drifting() || k.drifts[std::size_t(c)] == 0.0f);
        mask |= still ? 1 << t : 0;
    }
    return mask;
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
    if (m_k.domain.kind() == DomainKind::Atlas)
        defines.push_back("ATLAS");
    if (m_k.weighted())
        defines.push_back("ATLAS_WEIGHTS");
    if (m_k.crossWeighted())
        defines.push_back("ATLAS_CROSS");
    if (m_k.tensorWeighted())
        defines.push_back("ATLAS_TENSOR");
    if (m_k.drifting())
        defines.push_back("ATLAS_DRIFT");
    if (m_k.drifting() && m_k.driftCarrier >= 0)
        defines.push_back("DRIFT_CARRIER");
    if (pass)
        defines.push_back(pass);
    if (!m_frozenMask.empty())
        defines.push_back("FROZEN");
    const int textures = stateTextures(m_k.chemicals);
    defines.push_back("STATE_TEXTURES " + std::to_string(textures));
    if (const int still = stillTextures(m_k); still != 0)
        defines.push_back("STILL_TEXTURES " + std::to_string(still));
    Program program({embeddedShader("glsl/fullscreen.vert")}, stepFragmentPieces(model, m_k),
                    defines);

    program.use();
    for (int t = 0; t < textures; ++t)
        glUniform1i(program.uniform(("uState" + std::to_string(t)).c_str()), kStateUnits[t]);
    glUniform2f(program.uniform("uInvSize"), 1.0f / float(session.width),
                1.0f / float(session.height));
    glUniform1i(program.uniform("uParamMap"), kParamMapUnit);
    glUniform1i(program.uniform("uFrozen"), kFrozenUnit);
    if (m_k.tiled())
        glUniform2i(program.uniform("uTile"), m_k.domain.tileWidth(), m_k.domain.tileHeight());
    if (const Atlas* atlas = m_k.domain.atlasMap()) {
        glUniform1i(program.uniform("uConnectivity"), kConnectivityUnit);
        glUniform1i(program.uniform("uDiagonals0"), kDiagonalUnits[0]);
        glUniform1i(program.uniform("uDiagonals1"), kDiagonalUnits[1]);
        glUniform1i(program.uniform("uWeights"), kWeightsUnit);
        glUniform1i(program.uniform("uCross"), kCrossUnit);
        for (int i = 0; i < 4; ++i)
            glUniform1i(program.uniform(("uTensor" + std::to_string(i)).c_str()), kTensorUnits[i]);
        glUniform1i(program.uniform("uDriftIn"), kDriftUnits[0]);
        glUniform1i(program.uniform("uDriftOut"), kDriftUnits[1]);
        glUniform3i(program.uniform("uAtlas"), atlas->tileSize(), atlas->tilesPerRow(),
                    atlas->tileCount());
    }
    if (op.form == Form::TensorMap)
        glUniform1i(program.uniform("uMap"), kMapUnit);
    setLiveUniforms(program);
    ++m_programBuilds;
    return program;
}

void GpuSimulator::bindAuxiliaryTextures() const {
    if (m_map.id())
        m_map.bind(kMapUnit);
    for (std::size_t t = 0; t < m_rhs.size(); ++t)
        m_rhs[t].bind(kRhsUnits[t]);
    if (m_paramMap.id())
        m_paramMap.bind(kParamMapUnit);
    if (m_frozen.id())
        m_frozen.bind(kFrozenUnit);
    if (m_connectivity.id())
        m_connectivity.bind(kConnectivityUnit);
    if (m_weights.id())
        m_weights.bind(kWeightsUnit);
    if (m_cross.id())
        m_cross.bind(kCrossUnit);
    for (int i = 0; i < 4; ++i)
        if (m_tensor[i].id())
            m_tensor[i].bind(kTensorUnits[i]);
    for (int i = 0; i < 2; ++i)
        if (m_drift[i].id())
            m_drift[i].bind(kDriftUnits[i]);
    for (int order = 0; order < 2; ++order)
        if (m_diagonals[order].id())
            m_diagonals[order].bind(kDiagonalUnits[order]);
}

namespace {

// Rows per band of a state transfer: about 256k texels, a few MB of scratch.
int bandRows(int width) {
    return std::max(1, (1 << 18) / std::max(1, width));
}

} // namespace

void GpuSimulator::setState(const State& state) {
    assert(state.channels() == m_k.chemicals);
    const int w = state.width(), h = state.height();
    std::vector<float> texels;
    for (int y0 = 0; y0 < h; y0 += bandRows(w)) {
        const int rows = std::min(bandRows(w), h - y0);
        const std::size_t cells = std::size_t(w) * std::size_t(rows);
        const std::size_t offset = std::size_t(y0) * std::size_t(w);
        for (int t = 0; t < m_pingPong.count(); ++t) {
            Texture2D& texture = m_pingPong.current(t);
            const int n = texture.components();
            texels.assign(cells * std::size_t(n), 0.0f); // chemicals past the last are 0
            for (int k = 0; k < n && 4 * t + k < state.channels(); ++k) {
                const float* plane = state.plane(4 * t + k) + offset;
                for (std::size_t i = 0; i < cells; ++i)
                    texels[i * std::size_t(n) + std::size_t(k)] = plane[i];
            }
            texture.uploadRows(y0, rows, texels.data());
        }
    }
    m_pingPong.currentChanged();
}

void GpuSimulator::readBand(int y0, State& band, std::vector<float>& texels) const {
    const std::size_t cells = band.cellCount();
    for (int t = 0; t < m_pingPong.count(); ++t) {
        const Texture2D& texture = m_pingPong.current(t);
        const int n = texture.components();
        texels.resize(cells * std::size_t(n));
        texture.downloadRows(y0, band.height(), texels.data());
        for (int k = 0; k < n && 4 * t + k < band.channels(); ++k) {
            float* plane = band.plane(4 * t + k);
            for (std::size_t i = 0; i < cells; ++i)
                plane[i] = texels[i * std::size_t(n) + std::size_t(k)];
        }
    }
}

template <class Fn> void GpuSimulator::forEachBand(const Fn& fn) const {
    const int w = m_k.domain.width(), h = m_k.domain.height();
    std::vector<float> texels;
    State band;
    for (int y0 = 0; y0 < h; y0 += bandRows(w)) {
        const int rows = std::min(bandRows(w), h - y0);
        if (band.height() != rows)
            band = State(w, rows, m_k.chemicals);
        readBand(y0, band, texels);
        fn(y0, band);
    }
}

State GpuSimulator::state() const {
    State state(m_k.domain.width(), m_k.domain.height(), m_k.chemicals);
    forEachBand([&](int y0, const State& band) {
        const std::size_t offset = std::size_t(y0) * std::size_t(band.width());
        for (int c = 0; c < band.channels(); ++c)
            std::copy_n(band.plane(c), band.cellCount(), state.plane(c) + offset);
    });
    return state;
}

std::optional<std::string> GpuSimulator::insaneValue(const ReactionModel& model) const {
    InsaneValueScan scan(model);
    forEachBand([&](int y0, const State& band) { scan.scanRows(band, y0); });
    return scan.result();
}

void GpuSimulator::setActiveTiles(const std::vector<int>& tiles) {
    const std::vector<int> sorted = checkActiveTiles(m_k.domain, tiles);
    // A tile leaving the set may hold different values in the two targets.
    m_pingPong.currentChanged();
    m_activeRects.clear();
    if (sorted.empty())
        return;
    const Atlas& atlas = *m_k.domain.atlasMap();
    const int n = atlas.tileSize(), perRow = atlas.tilesPerRow();
    for (int t : sorted) {
        const int x = (t % perRow) * n, y = (t / perRow) * n;
        CellRect* last = m_activeRects.empty() ? nullptr : &m_activeRects.back();
        if (last && last->y == y && last->x + last->width == x)
            last->width += n; // the next tile of the same atlas row
        else
            m_activeRects.push_back({x, y, n, n});
    }
}

void GpuSimulator::run(int steps) {
    bindAuxiliaryTextures();
    const bool local = !m_activeRects.empty();
    if (m_k.integrator == Integrator::ExplicitEuler) {
        if (local)
            m_pingPong.runRects(m_program, steps, m_activeRects);
        else
            m_pingPong.run(m_program, steps);
        return;
    }
    // Each chemical stops after its own passes (chemicalRelaxationPasses, as
    // the CPU's), the same in every step of the run.
    std::array<int, kMaxChemicals> own{};
    for (int c = 0; c < m_k.chemicals; ++c)
        own[std::size_t(c)] = chemicalRelaxationPasses(m_k, c);
    for (int i = 0; i < steps; ++i) {
        // rhs = c + dt f(c), then relaxation passes from x0 = c; localized,
        // both inside the active tiles' rectangles only (the passes read the
        // rhs nowhere else).
        m_rhsProgram.use();
        m_pingPong.vertexArray().bind();
        m_rhsFramebuffer.bind();
        m_pingPong.bindCurrent();
        if (local) {
            glEnable(GL_SCISSOR_TEST);
            for (const CellRect& r : m_activeRects) {
                glViewport(r.x, r.y, r.width, r.height);
                glScissor(r.x, r.y, r.width, r.height);
                glDrawArrays(GL_TRIANGLES, 0, 3);
            }
            glDisable(GL_SCISSOR_TEST);
            glViewport(0, 0, m_session.width, m_session.height);
        } else {
            glDrawArrays(GL_TRIANGLES, 0, 3);
        }
        relax(local, own);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GpuSimulator::relax(bool local, const std::array<int, kMaxChemicals>& own) {
    // The passes run in groups with one set of relaxing chemicals.
    int done = 0;
    while (done < m_k.relaxationPasses) {
        std::array<float, kMaxChemicals> relaxing{};
        int until = m_k.relaxationPasses;
        bool any = false;
        for (int c = 0; c < m_k.chemicals; ++c)
            if (own[std::size_t(c)] > done) {
                relaxing[std::size_t(c)] = 1.0f;
                until = std::min(until, own[std::size_t(c)]);
                any = true;
            }
        if (!any)
            break; // nothing relaxes: the current textures hold every result
        m_program.use();
        setChemicalVec4s(m_program.uniform("uRelaxing"), relaxing, m_pingPong.count());
        if (local)
            m_pingPong.runRects(m_program, until - done, m_activeRects);
        else
            m_pingPong.run(m_program, until - done);
        done = until;
    }
}

void GpuSimulator::setLiveUniforms(const Program& program) const {
    using Form = DiffusionOperator::Form;
    const ReactionModel& model = *m_model;
    const DiffusionOperator& op = m_k.op;
    const int textures = stateTextures(m_k.chemicals);
    program.use();
    glUniform1f(program.uniform("uDt"), m_k.dt);
    setChemicalVec4s(program.uniform("uDiffusion"), op.rates, textures);
    setChemicalVec4s(program.uniform("uClampMin"), m_k.clampMin, textures);
    setChemicalVec4s(program.uniform("uClampMax"), m_k.clampMax, textures);
    for (std::size_t i = 0; i < model.params().size(); ++i)
        glUniform1f(program.uniform(("u_" + model.params()[i].name).c_str()), m_k.params[i]);
    if (op.form == Form::Kernel3 || op.form == Form::Kernel5) {
        // Texture t's taps, one vec4 each, one component per chemical.
        std::vector<float> weights(std::size_t(textures) * 25 * 4, 0.0f);
        for (int c = 0; c < op.chemicals; ++c)
            for (std::size_t tap = 0; tap < 25; ++tap)
                weights[(std::size_t(c / 4) * 25 + tap) * 4 + std::size_t(c % 4)] =
                    float(op.kernels[std::size_t(c)].w[tap]);
        glUniform4fv(program.uniform("uKernel"), 25 * textures, weights.data());
    }
    if (op.form == Form::TensorMap) {
        std::array<float, kMaxChemicals> m{}, dc{}, ds{};
        for (int c = 0; c < op.chemicals; ++c) {
            m[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][0];
            dc[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][1];
            ds[std::size_t(c)] = op.mapCoefficients[std::size_t(c)][2];
        }
        setChemicalVec4s(program.uniform("uMapM"), m, textures);
        setChemicalVec4s(program.uniform("uMapDc"), dc, textures);
        setChemicalVec4s(program.uniform("uMapDs"), ds, textures);
    }
    if (m_k.drifting())
        setChemicalVec4s(program.uniform("uDrifts"), m_k.drifts, textures);
    if (m_k.drifting() && m_k.driftCarrier >= 0) {
        float mask[4] = {0, 0, 0, 0};
        mask[m_k.driftCarrier] = 1.0f;
        glUniform4fv(program.uniform("uCarrier"), 1, mask);
        glUniform1f(program.uniform("uCling"), m_k.driftCling);
    }
    if (m_k.tensorWeighted()) {
        std::array<std::array<float, kMaxChemicals>, 3> mix{};
        for (int c = 0; c < op.chemicals; ++c)
            for (std::size_t q = 0; q < 3; ++q)
                mix[q][std::size_t(c)] = m_k.tensorMixes[std::size_t(c)][q];
        setChemicalVec4s(program.uniform("uMixP"), mix[0], textures);
        setChemicalVec4s(program.uniform("uMixQ1"), mix[1], textures);
        setChemicalVec4s(program.uniform("uMixQ2"), mix[2], textures);
    }
}

void GpuSimulator::updateLiveUniforms() {
    setLiveUniforms(m_program);
    if (m_k.integrator == Integrator::SemiImplicit) {
        // omega depends on dt (and the kernel): the Jacobi pass's own uniform.
        setChemicalVec4s(m_program.uniform("uOmega"), m_k.omega, m_pingPong.count());
        setLiveUniforms(m_rhsProgram);
    }
}

void GpuSimulator::applyLiveChange(Session next) {
    // Derived before anything changes: a refused change (InputError) leaves the run as it was.
    const int still = stillTextures(m_k);
    const bool uniformsOnly = updateLiveConstants(m_k, next);
    m_session = std::move(next);
    // A rate that comes or goes changes STILL_TEXTURES.
    if (uniformsOnly && stillTextures(m_k) == still)
        updateLiveUniforms();
    else
        buildPrograms();
}

} // namespace morphogen::gl
