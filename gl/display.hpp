#pragma once

#include <cstdint>
#include <vector>

#include "core/session/session.hpp"
#include "core/sim/simulator.hpp"
#include "gl/objects.hpp"

namespace morphogen::gl {

class GpuSimulator;

// An RGBA8 display texture of one chemical of a simulation, coloured as the
// image writer colours it (applyColormap: min-max normalisation, levels,
// the same maps). Texel (x, y) is cell (x, y), as in the state textures.
//
// GPU path: a chain of 4 x 4 min-max reductions into RG32F textures ends in
// one texel that glsl/display.frag reads; nothing is read back. The shader
// ports applyColormap's formulas and samples the anchors colormapAnchors()
// gives, so it differs from the CPU only by float rounding and the
// driver's float-to-unorm8 conversion (at most 1 of 255 per channel).
// CPU path: applyColormap on the CPU, quantised as the PNG writer does
// (toUnorm8), and only the display image uploaded.
// The "watercolour" map paints the watercolour model's pigments on its paper
// (core/output/watercolour_paint.hpp) from both state textures, on either path.
// Needs a current context for its whole life.
class Display {
public:
    Display(int width, int height);

    // Front: a GpuSimulator takes the GPU pass, any other backend the CPU path.
    // `edges`: the session's, for the watercolour map's dark edges (read
    // across the border as the simulation does; applyColormap).
    void update(const Simulator& simulator, int chemical, const ColorMapSpec& spec,
                EdgeMode edges = EdgeMode::Clamped);
    void render(const GpuSimulator& simulator, int chemical, const ColorMapSpec& spec,
                EdgeMode edges = EdgeMode::Clamped);
    void upload(const State& state, int chemical, const ColorMapSpec& spec,
                EdgeMode edges = EdgeMode::Clamped);

    const Texture2D& texture() const { return m_display; }
    // Reads the display texture back (tests, screenshots): RGBA, row 0 = cell row 0.
    std::vector<std::uint8_t> downloadRgba8() const;

private:
    int m_width, m_height;
    VertexArray m_vao;
    Texture2D m_display;
    std::vector<std::uint8_t> m_uploadRgba; // upload's, kept: a new one a frame page-faults
    Framebuffer m_displayFramebuffer;
    // The "watercolour" map: the watercolour model's two state textures
    // painted (glsl/watercolour_display.frag), no reduction; first the
    // wet-area mask's blurs for its dark edges (glsl/wet_edge_blur.frag).
    void paint(const GpuSimulator& simulator, const ColorMapSpec& spec, EdgeMode edges);
    // One blur pass of `source` along x or y into m_edgeTextures[target].
    void blurPass(const Texture2D& source, int target, bool alongX, int radius, bool wrap,
                  bool mask);

    Program m_reduceFirst, m_reduce, m_colour, m_watercolour, m_edgeBlur;
    // The watercolour map's blurs (R32F): a scratch pass, near, wide; made on first use.
    std::vector<Texture2D> m_edgeTextures;
    std::vector<Framebuffer> m_edgeFramebuffers;
    std::vector<Texture2D> m_levels; // each a quarter of the one before per side, to 1 x 1
    std::vector<Framebuffer> m_levelFramebuffers;
};

} // namespace morphogen::gl
