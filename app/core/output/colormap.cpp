#include "core/output/colormap.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>

#include "core/analysis/result_checks.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/models/watercolour.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/session/gradient.hpp"

namespace morphogen {

// The display pass's uniform array must hold the longest custom gradient.
static_assert(kMaxColormapAnchors >= kMaxGradientStops);

namespace {

using Rgb = std::array<float, 3>;

Rgb hex(unsigned v) {
    return {float((v >> 16) & 0xff) / 255.0f, float((v >> 8) & 0xff) / 255.0f,
            float(v & 0xff) / 255.0f};
}

enum class Palette { Grey, TwoColour, Viridis, Magma, Inferno, Coolwarm, Custom, Watercolour };

const EnumName<Palette> kPalettes[] = {
    {Palette::Grey, "grey"},       {Palette::TwoColour, "two-colour"},
    {Palette::Viridis, "viridis"}, {Palette::Magma, "magma"},
    {Palette::Inferno, "inferno"}, {Palette::Coolwarm, "coolwarm"},
    {Palette::Custom, "custom"},   {Palette::Watercolour, "watercolour"}};

const EnumAlias<Palette> kPaletteAliases[] = {
    {"gray", Palette::Grey},           {"two-color", Palette::TwoColour},
    {"twocolour", Palette::TwoColour}, {"twocolor", Palette::TwoColour},
    {"cool-warm", Palette::Coolwarm},  {"watercolor", Palette::Watercolour}};

// Perceptual palettes as evenly spaced anchors (matplotlib's viridis, magma,
// inferno; a cool-warm diverging map), interpolated piecewise linearly.
const std::vector<Rgb>& anchors(Palette palette) {
    static const std::vector<Rgb> viridis = {
        hex(0x440154), hex(0x482878), hex(0x3e4989), hex(0x31688e), hex(0x26828e),
        hex(0x1f9e89), hex(0x35b779), hex(0x6ece58), hex(0xb5de2b), hex(0xfde725)};
    static const std::vector<Rgb> magma = {hex(0x000004), hex(0x1c1044), hex(0x4f127b),
                                           hex(0x812581), hex(0xb5367a), hex(0xe55964),
                                           hex(0xfb8761), hex(0xfec287), hex(0xfcfdbf)};
    static const std::vector<Rgb> inferno = {hex(0x000004), hex(0x1f0c48), hex(0x550f6d),
                                             hex(0x88226a), hex(0xba3655), hex(0xe35933),
                                             hex(0xf98e09), hex(0xf9cb35), hex(0xfcffa4)};
    static const std::vector<Rgb> coolwarm = {hex(0x3b4cc0), hex(0x7093f3), hex(0xaac7fd),
                                              hex(0xdddddd), hex(0xf7b89c), hex(0xe7755b),
                                              hex(0xb40426)};
    switch (palette) {
    case Palette::Viridis:
        return viridis;
    case Palette::Magma:
        return magma;
    case Palette::Inferno:
        return inferno;
    default:
        assert(palette == Palette::Coolwarm && "grey and two-colour have no anchors");
        return coolwarm;
    }
}

// Throws InputError naming the accepted maps.
Palette parsePalette(const std::string& name) {
    const std::optional<Palette> palette = valueNamed(kPalettes, kPaletteAliases, name);
    if (!palette)
        throw InputError("colour map '" + name + "' is unknown (accepted: " + nameList(kPalettes) +
                         ")" + didYouMean(name, splitNameList(nameList(kPalettes))));
    return *palette;
}

Rgb lerp(const Rgb& a, const Rgb& b, float t) {
    return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}

Rgb samplePalette(const std::vector<Rgb>& palette, float t) {
    const float x = std::clamp(t, 0.0f, 1.0f) * float(palette.size() - 1);
    const std::size_t i = std::min(std::size_t(x), palette.size() - 2);
    return lerp(palette[i], palette[i + 1], x - float(i));
}

} // namespace

const std::vector<std::string>& colormapNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const EnumName<Palette>& p : kPalettes)
            list.push_back(p.name);
        return list;
    }();
    return names;
}

std::string canonicalColormapName(const std::string& name) {
    return nameOf(kPalettes, parsePalette(name));
}

std::vector<Rgb> colormapAnchors(const ColorMapSpec& spec) {
    const Palette palette = parsePalette(spec.name);
    if (palette == Palette::Grey)
        return {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};
    if (palette == Palette::TwoColour)
        return {spec.low, spec.high};
    if (palette == Palette::Custom) {
        if (spec.colours.empty())
            throw InputError("colour map 'custom' needs its colours (--colours "
                             "'#1b1b1b,#d9a441,#f4e8c1', --palette FILE, or \"colours\" in the "
                             "session's \"colormap\")");
        checkGradientStops(spec.colours.size(), "colour map 'custom'");
        return spec.colours;
    }
    if (palette == Palette::Watercolour) {
        // Where only a palette fits (one chemical through anchors): paper to
        // the first pigment's colour at density 1, as paintWatercolourRow shows it.
        const WatercolourLook look;
        Rgb pigment;
        for (int c = 0; c < 3; ++c)
            pigment[std::size_t(c)] =
                look.paper[std::size_t(c)] * std::exp(-look.absorbance[0][std::size_t(c)]);
        return {look.paper, pigment};
    }
    return anchors(palette);
}

bool isWatercolourMap(const ColorMapSpec& spec) {
    return parsePalette(spec.name) == Palette::Watercolour;
}

ColorMapSpec colormapOn(const ColorMapSpec& spec, const Session& session) {
    ColorMapSpec on = spec;
    if (session.surface.active())
        on.edgeDarkening = 0.0f;
    return on;
}

int colormapChemical(const ColorMapSpec& spec, const ReactionModel& model) {
    if (spec.chemical.empty())
        return model.displayChemical();
    const int index = model.chemicalIndex(spec.chemical);
    if (index < 0)
        throw InputError("colour map chemical '" + spec.chemical + "' is not a chemical of " +
                         model.name() + " (chemicals: " + model.chemicalNames() + ")" +
                         didYouMean(spec.chemical, splitNameList(model.chemicalNames())));
    return index;
}

namespace {

// The watercolour map paints the watercolour model's layout; any other state is bad input.
bool paintsState(const ColorMapSpec& spec, const State& state) {
    if (!isWatercolourMap(spec))
        return false;
    if (state.channels() != WatercolourModel::Cell::kChemicals)
        throw InputError("colour map 'watercolour' paints the watercolour model's pigments on its "
                         "paper; this state has " +
                         std::to_string(state.channels()) +
                         " chemicals, not the watercolour model's 7 (use another map)");
    return true;
}

} // namespace

ColourMapRows::ColourMapRows(const State& state, int chemical, const ColorMapSpec& spec,
                             EdgeMode edges)
    : m_state(state), m_chemical(chemical), m_palette(colormapAnchors(spec)),
      m_levelLow(spec.levels[0]), m_levelScale(1.0f / (spec.levels[1] - spec.levels[0])),
      m_paint(paintsState(spec, state)) {
    prepare(spec, edges);
    const float* p = state.plane(chemical);
    const std::ptrdiff_t n = std::ptrdiff_t(state.cellCount());
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    // On every core for large states (the designer's display does this each
    // frame); a min and a max are the same in any order.
#pragma omp parallel for reduction(min : lo) reduction(max : hi) if (n >= 65536)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        if (std::isfinite(p[i])) {
            lo = std::min(lo, p[i]);
            hi = std::max(hi, p[i]);
        }
    // A flat field maps to the low end: stretching float round-off (a range
    // of a few ulps) to the full palette would invent a pattern.
    m_low = lo;
    m_scale = isFlatRange(lo, hi) ? 0.0f : 1.0f / (hi - lo);
}

ColourMapRows::ColourMapRows(const State& state, int chemical, const ColorMapSpec& spec, float low,
                             float high, EdgeMode edges)
    : m_state(state), m_chemical(chemical), m_palette(colormapAnchors(spec)), m_low(low),
      m_scale(1.0f / (high - low)), m_levelLow(spec.levels[0]),
      m_levelScale(1.0f / (spec.levels[1] - spec.levels[0])), m_paint(paintsState(spec, state)) {
    assert(low < high);
    prepare(spec, edges);
}

ColourMapRows::~ColourMapRows() = default;

void ColourMapRows::prepare(const ColorMapSpec& spec, EdgeMode edges) {
    if (!m_paint) {
        // rowRgba8's table: the palette at kScreenSteps evenly spaced t.
        m_screen.resize(kScreenSteps);
        for (int i = 0; i < kScreenSteps; ++i) {
            const Rgb c = samplePalette(m_palette, float(i) / float(kScreenSteps - 1));
            m_screen[std::size_t(i)] = {toUnorm8(c[0]), toUnorm8(c[1]), toUnorm8(c[2]), 255};
        }
    }
    if (!m_paint || !(spec.edgeDarkening > 0.0f))
        return;
    m_edgeDarkening = spec.edgeDarkening;
    m_edges = std::make_unique<WatercolourEdges>(m_state, spec.edgeWidth, edges);
}

void ColourMapRows::row(int y, float* rgb) const {
    if (m_paint) {
        paintWatercolourRow(m_state, y, WatercolourLook(), rgb, m_edges.get(), m_edgeDarkening);
        return;
    }
    const std::size_t w = std::size_t(m_state.width());
    const float* p = m_state.plane(m_chemical) + std::size_t(y) * w;
    for (std::size_t x = 0; x < w; ++x) {
        const float normalised = std::isfinite(p[x]) ? (p[x] - m_low) * m_scale : 0.0f;
        const float t = std::clamp((normalised - m_levelLow) * m_levelScale, 0.0f, 1.0f);
        // Grey and two-colour are two-anchor palettes: 0 + (1 - 0) * t is t
        // exactly, and low + (high - low) * t the plain blend.
        const Rgb c = samplePalette(m_palette, t);
        rgb[x * 3 + 0] = c[0];
        rgb[x * 3 + 1] = c[1];
        rgb[x * 3 + 2] = c[2];
    }
}

void ColourMapRows::rowRgba8(int y, std::uint8_t* rgba) const {
    const std::size_t w = std::size_t(m_state.width());
    if (m_paint) {
        thread_local std::vector<float> rgb;
        rgb.resize(w * 3);
        row(y, rgb.data());
        for (std::size_t x = 0; x < w; ++x) {
            for (std::size_t k = 0; k < 3; ++k)
                rgba[x * 4 + k] = toUnorm8(rgb[x * 3 + k]);
            rgba[x * 4 + 3] = 255;
        }
        return;
    }
    // row()'s t, scaled to the table's index and rounded.
    const float* p = m_state.plane(m_chemical) + std::size_t(y) * w;
    const float steps = float(kScreenSteps - 1);
    for (std::size_t x = 0; x < w; ++x) {
        const float normalised = std::isfinite(p[x]) ? (p[x] - m_low) * m_scale : 0.0f;
        const float t = std::clamp((normalised - m_levelLow) * m_levelScale, 0.0f, 1.0f);
        std::memcpy(rgba + x * 4, m_screen[std::size_t(t * steps + 0.5f)].data(), 4);
    }
}

std::vector<float> applyColormap(const State& state, int chemical, const ColorMapSpec& spec,
                                 EdgeMode edges) {
    const ColourMapRows rows(state, chemical, spec, edges);
    const std::size_t rowLength = std::size_t(state.width()) * 3;
    std::vector<float> rgb(state.cellCount() * 3);
    for (int y = 0; y < state.height(); ++y)
        rows.row(y, rgb.data() + std::size_t(y) * rowLength);
    return rgb;
}

void writeColourMapped(const std::string& path, const ColourMapRows& rows, int bitDepth) {
    writeImageRows(path, rows.width(), rows.height(), 3, bitDepth,
                   [&](int y, float* rgb) { rows.row(y, rgb); });
}

} // namespace morphogen
