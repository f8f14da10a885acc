#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/session/session.hpp"

namespace morphogen {

class WatercolourEdges;

// Colour map names accepted by --colormap and "colormap.name".
const std::vector<std::string>& colormapNames();

// The table's spelling of a map ("grey" for "gray"); throws InputError naming
// the accepted maps.
std::string canonicalColormapName(const std::string& name);

// The chemical the colour map shows: spec.chemical, or the model's display chemical.
int colormapChemical(const ColorMapSpec& spec, const ReactionModel& model);

// The map as evenly spaced anchors, interpolated piecewise linearly: grey is
// black to white, two-colour spec.low to spec.high, custom spec.colours
// (InputError without them; other maps ignore them) (what applyColormap and
// the GPU display pass both sample).
std::vector<std::array<float, 3>> colormapAnchors(const ColorMapSpec& spec);

// True for the "watercolour" map: not a palette over one chemical but the
// watercolour model's pigments painted on its paper (watercolour_paint.hpp).
// Throws InputError for an unknown name.
bool isWatercolourMap(const ColorMapSpec& spec);

// `spec` as `session`'s images are painted with it: on a surface atlas the
// watercolour map has no dark edges (its blurs would read across tiles that
// are not neighbours in the texture; watercolour_paint.hpp).
ColorMapSpec colormapOn(const ColorMapSpec& spec, const Session& session);

// Most anchors a map has (the GPU display pass's uniform array).
constexpr int kMaxColormapAnchors = 16;

// One chemical, normalised by its own min and max over the grid (de Kleine's
// min-max mapping), windowed by spec.levels, through the named map:
// interleaved RGB in [0, 1].
// `edges`: how the watercolour map's edge darkening reads across the image's
// border (the session's edges; other maps read no neighbours).
std::vector<float> applyColormap(const State& state, int chemical, const ColorMapSpec& spec,
                                 EdgeMode edges = EdgeMode::Clamped);

// A colour map applied a row at a time: the levels are found once, then rows
// are mapped on demand, so a big image is written without a whole-image RGB
// buffer. Holds a reference to the state.
class ColourMapRows {
public:
    // applyColormap's min-max levels over the chemical's plane. `edges` as
    // applyColormap's.
    ColourMapRows(const State& state, int chemical, const ColorMapSpec& spec,
                  EdgeMode edges = EdgeMode::Clamped);
    // Fixed levels: chemical values low..high (low < high) map to 0..1 before
    // spec.levels' window (applyLockedColormap, frames.hpp).
    ColourMapRows(const State& state, int chemical, const ColorMapSpec& spec, float low, float high,
                  EdgeMode edges = EdgeMode::Clamped);
    ~ColourMapRows();
    ColourMapRows(const ColourMapRows&) = delete;
    ColourMapRows& operator=(const ColourMapRows&) = delete;
    int width() const { return m_state.width(); }
    int height() const { return m_state.height(); }
    // Row y's interleaved RGB in [0, 1] (width * 3 values).
    void row(int y, float* rgb) const;
    // Row y for the screen: RGBA8 (width * 4 bytes, alpha 255). A palette
    // goes through a table of kScreenSteps colours, within one step of 255
    // of row() rounded (the designer's CPU display does this every frame,
    // and row() and the rounding were a fifth of a frame's interface); the
    // watercolour map is row() rounded, exactly.
    void rowRgba8(int y, std::uint8_t* rgba) const;
    static constexpr int kScreenSteps = 4096;

private:
    void prepare(const ColorMapSpec& spec, EdgeMode edges);

    const State& m_state;
    int m_chemical;
    std::vector<std::array<float, 3>> m_palette;
    float m_low = 0.0f;
    float m_scale = 0.0f;
    float m_levelLow;
    float m_levelScale;
    bool m_paint = false; // the watercolour map: paintWatercolourRow, not the palette
    std::vector<std::array<std::uint8_t, 4>> m_screen; // rowRgba8's table (palettes)
    float m_edgeDarkening = 0.0f;
    std::unique_ptr<WatercolourEdges> m_edges; // the watercolour map's, when it darkens
};

// Writes the rows as an 8- or 16-bit RGB PNG/TIFF (image_io's writeImageRows).
void writeColourMapped(const std::string& path, const ColourMapRows& rows, int bitDepth);

} // namespace morphogen
