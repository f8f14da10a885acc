#include "core/output/texture_set.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/io/output_files.hpp"
#include "core/output/colormap.hpp"

namespace morphogen {

namespace fs = std::filesystem;

HeightLevels heightLevels(const Session& session, int chemical) {
    if (session.heightMaps.range)
        return {(*session.heightMaps.range)[0], (*session.heightMaps.range)[1], "session"};
    const ReactionModel& model = session.outputModel();
    assert(chemical >= 0 && chemical < int(model.chemicals().size()));
    const std::array<float, 2> r = model.chemicals()[std::size_t(chemical)].displayRange;
    return {r[0], r[1], "model display range"};
}

namespace {

// (value - low) / (high - low) of one cell: heightField's value.
struct HeightOf {
    const float* plane;
    float low;
    float scale;
    HeightOf(const State& state, int chemical, const HeightLevels& levels)
        : plane(state.plane(chemical)), low(levels.low), scale(1.0f / (levels.high - levels.low)) {
        assert(levels.low < levels.high);
    }
    float operator()(std::size_t i) const { return (plane[i] - low) * scale; }
};

// Row y of the normal map of the height field `h` (h(i): the height of cell
// i, row-major with row 0 at the top), interleaved RGB into `out`.
template <class Height>
void normalRow(const Height& h, int width, int height_, int y, EdgeMode edges, float strength,
               NormalFormat format, float* rgb) {
    const auto at = [&](int x, int yy) {
        x = GridDomain::wrapOrClamp(x, width, edges);
        yy = GridDomain::wrapOrClamp(yy, height_, edges);
        return h(std::size_t(yy) * std::size_t(width) + std::size_t(x));
    };
    // Green is +Y up the image for OpenGL; rows grow downwards, so the upward
    // slope is (row above - row below) / 2.
    const float ySign = format == NormalFormat::OpenGl ? 1.0f : -1.0f;
    for (int x = 0; x < width; ++x) {
        const float dx = strength * 0.5f * (at(x + 1, y) - at(x - 1, y));
        const float dyUp = strength * 0.5f * (at(x, y - 1) - at(x, y + 1));
        // The normal of z = s h(x, y) is (-dz/dx, -dz/dy, 1), normalised.
        const float nx = -dx, ny = -dyUp * ySign, nz = 1.0f;
        const float inv = 1.0f / std::sqrt(nx * nx + ny * ny + nz * nz);
        float* out = rgb + std::size_t(x) * 3;
        out[0] = nx * inv * 0.5f + 0.5f;
        out[1] = ny * inv * 0.5f + 0.5f;
        out[2] = nz * inv * 0.5f + 0.5f;
    }
}

} // namespace

std::vector<float> heightField(const State& state, int chemical, const HeightLevels& levels) {
    const HeightOf height(state, chemical, levels);
    std::vector<float> h(state.cellCount());
    for (std::size_t i = 0; i < h.size(); ++i)
        h[i] = height(i);
    return h;
}

std::vector<float> normalMap(const std::vector<float>& height, int width, int height_,
                             EdgeMode edges, float strength, NormalFormat format) {
    assert(height.size() == std::size_t(width) * std::size_t(height_));
    std::vector<float> rgb(height.size() * 3);
    const auto h = [&](std::size_t i) { return height[i]; };
    for (int y = 0; y < height_; ++y)
        normalRow(h, width, height_, y, edges, strength, format,
                  rgb.data() + std::size_t(y) * std::size_t(width) * 3);
    return rgb;
}

std::vector<float> heightMask(const std::vector<float>& height, float threshold) {
    std::vector<float> mask(height.size());
    for (std::size_t i = 0; i < height.size(); ++i)
        mask[i] = height[i] > threshold ? 1.0f : 0.0f;
    return mask;
}

const std::vector<std::string>& textureSetFiles() {
    static const std::vector<std::string> files = {"albedo.png",      "height.png", "height.exr",
                                                   "normal.png",      "mask.png",   "session.json",
                                                   "texture_set.json"};
    return files;
}

void prepareTextureSetDir(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir))
        throw InputError("--texture-set '" + dir + "': cannot create the folder" +
                         (ec ? ": " + ec.message() : std::string(" (a file has that name)")));
    checkWritable((fs::path(dir) / "texture_set.json").string());
}

nlohmann::json textureSetFileEntry(const std::string& name, const std::string& meaning,
                                   const std::string& colourSpace, const nlohmann::json& bitDepth) {
    return {{"file", name},
            {"meaning", meaning},
            {"colour_space", colourSpace},
            {"bit_depth", bitDepth}};
}

nlohmann::json textureSetManifest(const Session& session, int chemical, const HeightLevels& levels,
                                  float observedMin, float observedMax) {
    const ReactionModel& model = session.outputModel();
    const std::string chem = model.chemicals()[std::size_t(chemical)].name;
    const HeightSpec& h = session.heightMaps;
    using nlohmann::json;
    json files = json::array();
    const auto file = [&](const char* name, const std::string& meaning, const char* colourSpace,
                          const json& depth) {
        files.push_back(textureSetFileEntry(name, meaning, colourSpace, depth));
    };
    file("albedo.png",
         "colour map '" + session.colormap.name + "' of chemical '" + chem +
             "' (per-image min-max, levels [" + std::to_string(session.colormap.levels[0]) + ", " +
             std::to_string(session.colormap.levels[1]) + "])",
         "sRGB", 8);
    file("height.png",
         "height of chemical '" + chem +
             "': (value - low) / (high - low), clamped "
             "to [0, 1], grey",
         "linear", 16);
    file("height.exr",
         "height of chemical '" + chem +
             "': (value - low) / (high - low), not "
             "clamped, one float channel 'height'",
         "linear", "32-bit float");
    file("normal.png", "tangent-space normal map of the height, RGB = n * 0.5 + 0.5", "linear", 8);
    file("mask.png", "255 where the height is above mask_threshold, else 0", "linear", 8);
    file("session.json",
         "the session that reproduces this set (morphogen render --session "
         "session.json --texture-set DIR)",
         "", json());
    return {{"generator", "morphogen render --texture-set"},
            {"size", {session.width, session.height}},
            {"edges", toString(session.edges)},
            {"chemical", chem},
            {"height",
             {{"low", levels.low},
              {"high", levels.high},
              {"levels_from", levels.source},
              {"observed", {observedMin, observedMax}}}},
            {"normal",
             {{"format", toString(h.normalFormat)},
              {"green",
               h.normalFormat == NormalFormat::OpenGl ? "+Y up the image" : "+Y down the image"},
              {"strength", h.normalStrength},
              {"strength_units", "texels of displacement for a height step of 1 (low to high)"},
              {"differences", session.edges == EdgeMode::Periodic
                                  ? "central, wrapped at the edges (tiles)"
                                  : "central, edge texel repeated"}}},
            {"mask_threshold", h.maskThreshold},
            {"session", "session.json"},
            {"files", files}};
}

void writeTextureSet(const std::string& dir, const State& state, const Session& session,
                     OutputFiles& files) {
    prepareTextureSetDir(dir);
    const fs::path d(dir);
    const auto staged = [&](const char* name) { return files.stage((d / name).string()); };
    const int w = state.width(), hgt = state.height();
    const int chemical = colormapChemical(session.colormap, session.outputModel());
    const HeightLevels levels = heightLevels(session, chemical);

    // Every map a row at a time from the state: no whole-image buffers.
    writeColourMapped(staged("albedo.png"),
                      ColourMapRows(state, chemical, session.colormap, session.edges), 8);
    const HeightOf h(state, chemical, levels);
    const auto heightRow = [&](int y, float* row) {
        const std::size_t first = std::size_t(y) * std::size_t(w);
        for (std::size_t x = 0; x < std::size_t(w); ++x)
            row[x] = h(first + x);
    };
    writeImageRows(staged("height.png"), w, hgt, 1, 16, heightRow);
    writeRawRows(staged("height.exr"), w, hgt, 1, {"height"}, heightRow);
    const HeightSpec& spec = session.heightMaps;
    writeImageRows(staged("normal.png"), w, hgt, 3, 8, [&](int y, float* rgb) {
        normalRow(h, w, hgt, y, session.edges, spec.normalStrength, spec.normalFormat, rgb);
    });
    writeImageRows(staged("mask.png"), w, hgt, 1, 8, [&](int y, float* row) {
        const std::size_t first = std::size_t(y) * std::size_t(w);
        for (std::size_t x = 0; x < std::size_t(w); ++x)
            row[x] = h(first + x) > spec.maskThreshold ? 1.0f : 0.0f;
    });
    saveSessionFile(session, staged("session.json"));

    const float* c = state.plane(chemical);
    const auto [lo, hi] = std::minmax_element(c, c + state.cellCount());
    writeTextAtomically(staged("texture_set.json"),
                        textureSetManifest(session, chemical, levels, *lo, *hi).dump(2) + "\n");
}

void writeTextureSet(const std::string& dir, const State& state, const Session& session) {
    OutputFiles files;
    writeTextureSet(dir, state, session, files);
    files.commit();
}

} // namespace morphogen
