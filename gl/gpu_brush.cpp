// Brush writes on the GPU backend. Chemicals: a pass of glsl/brush.frag over
// each of the region's rectangles (the mask of weights and noise uploaded for
// the rectangle only). The frozen mask and the parameter maps are inputs the
// engine keeps on the CPU side too; their rectangles are updated there and
// uploaded. Nothing reads back or re-uploads the whole state.

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>
#include <string>

#include "gl/gpu_simulator.hpp"

namespace morphogen::gl {

namespace {

float finiteBound(float v) {
    return std::isinf(v) ? std::copysign(FLT_MAX, v) : v;
}

bool contains(const CellRect& r, int x, int y) {
    return x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
}

// A rectangle of RGBA floats with `fill(cell, texel)` called for each region
// cell inside it (texel: the RGBA quadruple to fill) and zeros elsewhere.
template <class Fill>
std::vector<float> rectTexels(const BrushRegion& region, const CellRect& r, const Fill& fill) {
    std::vector<float> rgba(std::size_t(r.width) * std::size_t(r.height) * 4, 0.0f);
    const std::uint32_t w = std::uint32_t(region.gridWidth());
    for (const BrushRegion::Cell& cell : region.cells()) {
        const int x = int(cell.index % w), y = int(cell.index / w);
        if (contains(r, x, y))
            fill(cell,
                 &rgba[(std::size_t(y - r.y) * std::size_t(r.width) + std::size_t(x - r.x)) * 4]);
    }
    return rgba;
}

} // namespace

void PingPong::runRect(const Program& program, const CellRect& rect) {
    const int next = 1 - m_current;
    program.use();
    m_vao.bind();
    m_framebuffers[std::size_t(next)].bind();
    glViewport(rect.x, rect.y, rect.width, rect.height);
    glScissor(rect.x, rect.y, rect.width, rect.height);
    glEnable(GL_SCISSOR_TEST);
    bindCurrent();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_SCISSOR_TEST);
    // Copy the rectangle back attachment by attachment; the read buffer is
    // framebuffer state, so it is restored for the step passes.
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffers[std::size_t(next)].id());
    for (int t = 0; t < count(); ++t) {
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + t));
        current(t).bind(kStateUnits[t]);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, rect.x, rect.y, rect.x, rect.y, rect.width,
                            rect.height);
    }
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    m_otherMatches = false; // rect differs in the other set now
}

void GpuSimulator::applyBrush(const Brush& brush) {
    checkBrush(brush, *m_model, m_k.domain);
    if (brush.region.empty())
        return;
    switch (brush.mode) {
    case BrushMode::Hold:
    case BrushMode::Release:
        brushFrozen(brush);
        return;
    case BrushMode::Paint:
        brushParamMap(brush);
        return;
    default:
        brushChemical(brush);
        return;
    }
}

void GpuSimulator::brushChemical(const Brush& brush) {
    const int textures = m_pingPong.count();
    if (!m_brushProgram.id()) {
        m_brushProgram =
            Program({embeddedShader("glsl/fullscreen.vert")}, {embeddedShader("glsl/brush.frag")},
                    {"STATE_TEXTURES " + std::to_string(textures),
                     "MODE_ADD " + std::to_string(int(BrushMode::Add)),
                     "MODE_REMOVE " + std::to_string(int(BrushMode::Remove)),
                     "MODE_SET " + std::to_string(int(BrushMode::Set)),
                     "MODE_RANDOMISE " + std::to_string(int(BrushMode::Randomise))});
        m_brushProgram.use();
        for (int t = 0; t < textures; ++t)
            glUniform1i(m_brushProgram.uniform(("uState" + std::to_string(t)).c_str()),
                        kStateUnits[t]);
        glUniform1i(m_brushProgram.uniform("uMask"), kBrushMaskUnit);
    }
    const int c = brush.chemical;
    const Program& program = m_brushProgram;
    program.use();
    glUniform1i(program.uniform("uTexture"), c / 4);
    glUniform1i(program.uniform("uComponent"), c % 4);
    glUniform1i(program.uniform("uMode"), int(brush.mode));
    glUniform1f(program.uniform("uValue"), brush.value);
    glUniform1f(program.uniform("uLo"), finiteBound(m_k.clampMin[std::size_t(c)]));
    glUniform1f(program.uniform("uHi"), finiteBound(m_k.clampMax[std::size_t(c)]));
    const bool noisy = brush.mode == BrushMode::Randomise;
    for (const CellRect& rect : brush.region.rects()) {
        // Noise comes from the CPU's counter-based generator, so both backends
        // add the same numbers.
        Texture2D mask(rect.width, rect.height, GL_RGBA32F);
        mask.uploadRgba(
            rectTexels(brush.region, rect, [&](const BrushRegion::Cell& cell, float* t) {
                t[0] = cell.weight;
                t[1] = noisy ? brushNoise(brush.seed, cell.index) : 0.0f;
            }));
        mask.bind(kBrushMaskUnit);
        program.use();
        glUniform2i(program.uniform("uRectOrigin"), rect.x, rect.y);
        m_pingPong.runRect(program, rect);
    }
}

void GpuSimulator::brushFrozen(const Brush& brush) {
    const bool hold = brush.mode == BrushMode::Hold;
    if (m_frozenMask.empty()) {
        if (!hold)
            return;
        // The first held cells: the FROZEN variant comes in with a full mask.
        std::vector<std::uint8_t> mask(m_k.domain.cellCount(), 0);
        for (const BrushRegion::Cell& cell : brush.region.cells())
            mask[cell.index] = 1;
        setFrozen(mask);
        return;
    }
    for (const BrushRegion::Cell& cell : brush.region.cells())
        m_frozenMask[cell.index] = hold ? 1 : 0;
    if (!hold &&
        std::none_of(m_frozenMask.begin(), m_frozenMask.end(), [](std::uint8_t m) { return m; })) {
        setFrozen({}); // back to the plain step
        return;
    }
    const std::uint32_t w = std::uint32_t(m_k.domain.width());
    for (const CellRect& r : brush.region.rects()) {
        std::vector<std::uint8_t> bytes(std::size_t(r.width) * std::size_t(r.height));
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                bytes[std::size_t(y) * std::size_t(r.width) + std::size_t(x)] =
                    m_frozenMask[std::size_t(r.y + y) * w + std::size_t(r.x + x)] ? 255 : 0;
        m_frozen.uploadBytesRect(r.x, r.y, r.width, r.height, bytes.data());
    }
}

void GpuSimulator::brushParamMap(const Brush& brush) {
    int m = mappedIndex(m_k, *m_model, brush.param);
    if (m < 0) {
        // A new map: new constants, texture and programs (a rebuild, once).
        Session session = m_session;
        StepConstants k = withParamMap(session, m_k, brush.param);
        m_k = std::move(k);
        m_session = std::move(session);
        m_paramMap = Texture2D(m_k.domain.width(), m_k.domain.height(), GL_RGBA32F);
        m_paramMap.setWrap(m_k.domain.edges() == EdgeMode::Periodic ? GL_REPEAT : GL_CLAMP_TO_EDGE);
        float* plane = m_k.paramMaps.plane(mappedIndex(m_k, *m_model, brush.param));
        for (const BrushRegion::Cell& cell : brush.region.cells())
            plane[cell.index] = blend(plane[cell.index], brush.value, cell.weight);
        m_paramMap.uploadRgba(m_k.paramMaps.toRgba());
        buildPrograms();
        return;
    }
    float* plane = m_k.paramMaps.plane(m);
    for (const BrushRegion::Cell& cell : brush.region.cells())
        plane[cell.index] = blend(plane[cell.index], brush.value, cell.weight);
    const std::size_t w = std::size_t(m_k.domain.width());
    const int maps = m_k.paramMaps.channels();
    for (const CellRect& r : brush.region.rects()) {
        std::vector<float> rgba(std::size_t(r.width) * std::size_t(r.height) * 4, 0.0f);
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                for (int c = 0; c < maps; ++c)
                    rgba[(std::size_t(y) * std::size_t(r.width) + std::size_t(x)) * 4 +
                         std::size_t(c)] =
                        m_k.paramMaps.plane(c)[std::size_t(r.y + y) * w + std::size_t(r.x + x)];
        m_paramMap.uploadRgbaRect(r.x, r.y, r.width, r.height, rgba);
    }
}

} // namespace morphogen::gl
