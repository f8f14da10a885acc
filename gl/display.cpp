#include "gl/display.hpp"

#include <cassert>
#include <string>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::gl {

namespace {

constexpr int kSourceUnit = 0;
constexpr int kMinMaxUnit = 1;
constexpr int kSecondStateUnit = 1; // the watercolour pass's second state texture

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

void Display::update(const Simulator& simulator, int chemical, const ColorMapSpec& spec) {
    if (const auto* gpu = dynamic_cast<const GpuSimulator*>(&simulator))
        render(*gpu, chemical, spec);
    else if (const auto* cpu = dynamic_cast<const CpuSimulator*>(&simulator))
        upload(cpu->currentState(), chemical, spec);
    else
        upload(simulator.state(), chemical, spec);
}

void Display::render(const GpuSimulator& simulator, int chemical, const ColorMapSpec& spec) {
    const Texture2D& state = simulator.stateTexture(chemical / 4);
    assert(chemical >= 0 && chemical / 4 < simulator.stateTextureCount());
    assert(state.width() == m_width && state.height() == m_height);
    const std::vector<std::array<float, 3>> anchors = colormapAnchors(spec); // checks the name
    if (isWatercolourMap(spec)) {
        paint(simulator);
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

void Display::paint(const GpuSimulator& simulator) {
    // Sessions check the model (colormapFromJson); this guards the layout.
    if (simulator.stateTextureCount() != 2)
        throw InputError("colour map 'watercolour' paints the watercolour model's pigments; "
                         "this simulation's model has none (use another map)");
    m_vao.bind();
    m_watercolour.use();
    simulator.stateTexture(0).bind(kSourceUnit);
    simulator.stateTexture(1).bind(kSecondStateUnit);
    m_displayFramebuffer.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Display::upload(const State& state, int chemical, const ColorMapSpec& spec) {
    assert(state.width() == m_width && state.height() == m_height);
    // Row by row on every core: the designer does this every frame on the
    // CPU backend, and the frame's time is the simulation's.
    const ColourMapRows rows(state, chemical, spec);
    const std::size_t w = std::size_t(m_width);
    std::vector<std::uint8_t>& rgba = m_uploadRgba;
    rgba.resize(state.cellCount() * 4);
#pragma omp parallel if (state.cellCount() >= 65536)
    {
        std::vector<float> rgb(w * 3);
#pragma omp for schedule(static)
        for (int y = 0; y < m_height; ++y) {
            rows.row(y, rgb.data());
            std::uint8_t* out = rgba.data() + std::size_t(y) * w * 4;
            for (std::size_t x = 0; x < w; ++x) {
                for (std::size_t k = 0; k < 3; ++k)
                    out[x * 4 + k] = toUnorm8(rgb[x * 3 + k]);
                out[x * 4 + 3] = 255;
            }
        }
    }
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
