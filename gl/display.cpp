#include "gl/display.hpp"

#include <cassert>
#include <string>

#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::gl {

namespace {

constexpr int kSourceUnit = 0;
constexpr int kMinMaxUnit = 1;
constexpr int kSecondStateUnit = 1; // the watercolour pass's second state texture
constexpr int kNearUnit = 2;        // ... and its wet-area blurs
constexpr int kWideUnit = 3;
constexpr int kScratch = 0, kNear = 1, kWide = 2; // m_edgeTextures

int quarter(int n) {
    return (n + 3) / 4;
}

} // namespace

Display::Display(int width, int height)
    : m_width(width), m_height(height), m_display(width, height, GL_RGBA8),
      m_displayFramebuffer(m_display) {
    const ShaderPiece vertex = embeddedShader("glsl/fullscreen.vert");
    m_reduceFirst = Program({vertex}, {embeddedShader("glsl/minmax.frag")}, {"FIRST"});
    m_reduce = Program({vertex}, {embeddedShader("glsl/minmax.frag")}, {});
    m_colour = Program({vertex}, {embeddedShader("glsl/display.frag")},
                       {"MAX_ANCHORS " + std::to_string(kMaxColormapAnchors)});
    m_watercolour = Program({vertex}, {embeddedShader("glsl/watercolour_display.frag")}, {});
    m_watercolour.use();
    glUniform1i(m_watercolour.uniform("uState0"), kSourceUnit);
    glUniform1i(m_watercolour.uniform("uState1"), kSecondStateUnit);
    const WatercolourLook look;
    glUniform3fv(m_watercolour.uniform("uPaper"), 1, look.paper.data());
    glUniform3fv(m_watercolour.uniform("uAbsorbance"), 2, look.absorbance[0].data());
    glUniform1f(m_watercolour.uniform("uWetShare"), look.wetShare);
    glUniform1f(m_watercolour.uniform("uSheen"), look.sheen);
    glUniform1f(m_watercolour.uniform("uGrain"), look.grain);
    glUniform1i(m_watercolour.uniform("uNear"), kNearUnit);
    glUniform1i(m_watercolour.uniform("uWide"), kWideUnit);
    m_edgeBlur = Program({vertex}, {embeddedShader("glsl/wet_edge_blur.frag")}, {});
    m_edgeBlur.use();
    glUniform1i(m_edgeBlur.uniform("uSource"), kSourceUnit);
    glUniform2f(m_edgeBlur.uniform("uWetEdge"), WatercolourEdges::kWetEdge[0],
                WatercolourEdges::kWetEdge[1]);
    for (const Program* p : {&m_reduceFirst, &m_reduce}) {
        p->use();
        glUniform1i(p->uniform("uSource"), kSourceUnit);
    }
    m_colour.use();
    glUniform1i(m_colour.uniform("uState"), kSourceUnit);
    glUniform1i(m_colour.uniform("uMinMax"), kMinMaxUnit);
    int w = width, h = height;
    do {
        w = quarter(w);
        h = quarter(h);
        m_levels.emplace_back(w, h, GL_RG32F);
    } while (w > 1 || h > 1);
    for (const Texture2D& level : m_levels)
        m_levelFramebuffers.emplace_back(level);
}

void Display::update(const Simulator& simulator, int chemical, const ColorMapSpec& spec,
                     EdgeMode edges) {
    if (const auto* gpu = dynamic_cast<const GpuSimulator*>(&simulator))
        render(*gpu, chemical, spec, edges);
    else if (const auto* cpu = dynamic_cast<const CpuSimulator*>(&simulator))
        upload(cpu->currentState(), chemical, spec, edges);
    else
        upload(simulator.state(), chemical, spec, edges);
}

void Display::render(const GpuSimulator& simulator, int chemical, const ColorMapSpec& spec,
                     EdgeMode edges) {
    const Texture2D& state = simulator.stateTexture(chemical / 4);
    assert(chemical >= 0 && chemical / 4 < simulator.stateTextureCount());
    assert(state.width() == m_width && state.height() == m_height);
    const std::vector<std::array<float, 3>> anchors = colormapAnchors(spec); // checks the name
    if (isWatercolourMap(spec)) {
        paint(simulator, spec, edges);
        return;
    }
    assert(anchors.size() >= 2 && anchors.size() <= std::size_t(kMaxColormapAnchors));
    m_vao.bind();

    const Texture2D* source = &state;
    for (std::size_t i = 0; i < m_levels.size(); ++i) {
        const Program& program = i == 0 ? m_reduceFirst : m_reduce;
        program.use();
        if (i == 0)
            glUniform1i(program.uniform("uComponent"), chemical % 4);
        glUniform2i(program.uniform("uSourceSize"), source->width(), source->height());
        source->bind(kSourceUnit);
        m_levelFramebuffers[i].bind();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        source = &m_levels[i];
    }

    m_colour.use();
    glUniform1i(m_colour.uniform("uComponent"), chemical % 4);
    glUniform2f(m_colour.uniform("uLevels"), spec.levels[0],
                1.0f / (spec.levels[1] - spec.levels[0]));
    glUniform3fv(m_colour.uniform("uAnchors"), GLsizei(anchors.size()), anchors[0].data());
    glUniform1i(m_colour.uniform("uAnchorCount"), GLint(anchors.size()));
    state.bind(kSourceUnit);
    m_levels.back().bind(kMinMaxUnit);
    m_displayFramebuffer.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Display::blurPass(const Texture2D& source, int target, bool alongX, int radius, bool wrap,
                       bool mask) {
    glUniform2i(m_edgeBlur.uniform("uAxis"), alongX ? 1 : 0, alongX ? 0 : 1);
    glUniform1i(m_edgeBlur.uniform("uRadius"), radius);
    glUniform1i(m_edgeBlur.uniform("uWrap"), wrap ? 1 : 0);
    glUniform1i(m_edgeBlur.uniform("uMask"), mask ? 1 : 0);
    source.bind(kSourceUnit);
    m_edgeFramebuffers[std::size_t(target)].bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Display::paint(const GpuSimulator& simulator, const ColorMapSpec& spec, EdgeMode edges) {
    // Sessions check the model (colormapFromJson); this guards the layout.
    if (simulator.stateTextureCount() != 2)
        throw InputError("colour map 'watercolour' paints the watercolour model's pigments; "
                         "this simulation's model has none (use another map)");
    m_vao.bind();
    if (m_edgeTextures.empty()) {
        for (int i = 0; i < 3; ++i)
            m_edgeTextures.emplace_back(m_width, m_height, GL_R32F);
        for (const Texture2D& t : m_edgeTextures)
            m_edgeFramebuffers.emplace_back(t);
    }
    const bool darken = spec.edgeDarkening > 0.0f;
    const std::array<int, 2> r = WatercolourEdges::radii(m_width, spec.edgeWidth);
    if (darken) {
        // As WatercolourEdges: near = one box of the mask, wide = two wider ones.
        const bool wrap = edges == EdgeMode::Periodic;
        const Texture2D& state = simulator.stateTexture(1);
        m_edgeBlur.use();
        blurPass(state, kScratch, true, r[0], wrap, true);
        blurPass(m_edgeTextures[kScratch], kNear, false, r[0], wrap, false);
        blurPass(state, kScratch, true, r[1], wrap, true);
        blurPass(m_edgeTextures[kScratch], kWide, false, r[1], wrap, false);
        blurPass(m_edgeTextures[kWide], kScratch, true, r[1], wrap, false);
        blurPass(m_edgeTextures[kScratch], kWide, false, r[1], wrap, false);
    }
    m_watercolour.use();
    glUniform1f(m_watercolour.uniform("uEdgeDarkening"),
                darken ? spec.edgeDarkening / WatercolourEdges::crispPeak(r) : 0.0f);
    simulator.stateTexture(0).bind(kSourceUnit);
    simulator.stateTexture(1).bind(kSecondStateUnit);
    m_edgeTextures[kNear].bind(kNearUnit);
    m_edgeTextures[kWide].bind(kWideUnit);
    m_displayFramebuffer.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Display::upload(const State& state, int chemical, const ColorMapSpec& spec, EdgeMode edges) {
    assert(state.width() == m_width && state.height() == m_height);
    // Row by row on every core: the designer does this every frame on the
    // CPU backend, and the frame's time is the simulation's.
    const ColourMapRows rows(state, chemical, spec, edges);
    const std::size_t w = std::size_t(m_width);
    std::vector<std::uint8_t>& rgba = m_uploadRgba;
    rgba.resize(state.cellCount() * 4);
#pragma omp parallel for schedule(static) if (state.cellCount() >= 65536)
    for (int y = 0; y < m_height; ++y)
        rows.rowRgba8(y, rgba.data() + std::size_t(y) * w * 4);
    glBindTexture(GL_TEXTURE_2D, m_display.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE,
                    rgba.data());
}

std::vector<std::uint8_t> Display::downloadRgba8() const {
    std::vector<std::uint8_t> rgba(std::size_t(m_width) * std::size_t(m_height) * 4);
    glBindTexture(GL_TEXTURE_2D, m_display.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return rgba;
}

} // namespace morphogen::gl
