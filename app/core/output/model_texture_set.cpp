#include "core/output/model_texture_set.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "core/output/texture_set.hpp"
#include "core/surface/display_atlas.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_glb.hpp"
#include "core/surface/textured_surface.hpp"
#include "core/surface/uv_bake.hpp"

namespace morphogen {

namespace fs = std::filesystem;

namespace {

// The maps of one layout, per texel, before they are written.
struct Layout {
    int width = 0, height = 0;
    std::vector<std::array<std::uint8_t, 4>> albedo;
    std::vector<float> heightMap; // by the session's levels, not clamped
    std::vector<char> covered;    // texels that belong to the model (islands, padding, tiles)
    RgbaImage normal;             // the session's format
    TexturedMesh model;           // for model.glb
};

// DirectX's green runs down the image; the bakes' y runs along -v, up it.
void flipGreen(RgbaImage& image) {
    for (auto& t : image.texels)
        t[1] = std::uint8_t(255 - t[1]);
}

Layout inModelUvs(const UvMesh& uvs, const SurfaceTiles& tiles, const SurfaceColours& colours,
                  const std::vector<float>& value, const HeightLevels& levels,
                  const HeightSpec& spec, const ModelTextureSetOptions& options) {
    UvBakeOptions bake;
    bake.size = options.size;
    bake.padding = options.padding;
    const SurfaceLook look;
    bake.bump = look.bump;
    UvTexels texels = sampleIntoUvs(uvs, tiles, colours, bake, &value);
    Layout out;
    out.width = out.height = texels.size;
    out.heightMap.assign(texels.value.size(), 0.0f);
    for (std::size_t i = 0; i < out.heightMap.size(); ++i)
        if (texels.covered[i])
            out.heightMap[i] = (texels.value[i] - levels.low) / (levels.high - levels.low);
    const double relief = uvRelief(tiles, look.bump);
    out.normal = uvNormalMap(texels, out.heightMap, relief * double(spec.normalStrength),
                             spec.normalFormat == NormalFormat::DirectX);
    // The GLB is what `--out model.glb` writes: its relief follows the display.
    RgbaImage glbNormals = uvNormalMap(texels, texels.height, relief * colours.relief, false);
    out.model =
        uvBakedMesh(uvs, RgbaImage{texels.size, texels.size, texels.colour}, std::move(glbNormals));
    out.albedo = std::move(texels.colour);
    out.covered = std::move(texels.covered);
    return out;
}

Layout inTheAtlas(const SurfaceTiles& tiles, const SurfaceColours& colours,
                  const std::vector<float>& value, const HeightLevels& levels,
                  const HeightSpec& spec) {
    const Atlas& atlas = *tiles.atlas;
    const SurfaceLook look;
    std::shared_ptr<const DisplayAtlas> made = colours.displayAtlas;
    if (!made || made->scale() != displayScale(atlas, look) || made->gutter() != look.gutter)
        made = std::make_shared<const DisplayAtlas>(atlas, look.gutter, displayScale(atlas, look));
    const DisplayAtlas& display = *made;
    Layout out;
    out.width = display.width();
    out.height = display.height();
    out.model = texturedSurface(tiles, colours, look);
    out.albedo = out.model.baseColour.texels;
    std::vector<float> cellHeight(atlas.cellCount(), 0.0f);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            cellHeight[i] = (value[i] - levels.low) / (levels.high - levels.low);
    out.heightMap = display.pad(cellHeight, 1);
    out.covered.assign(display.texelCount(), 0);
    for (std::size_t p = 0; p < display.texelCount(); ++p)
        out.covered[p] = display.covered(p) ? 1 : 0;
    const TexelFrames frames = texelFrames(tiles);
    out.normal = bakeNormalMap(atlas, display, cellHeight, frames,
                               look.bump * frames.meanTexelLength * spec.normalStrength);
    if (spec.normalFormat == NormalFormat::DirectX)
        flipGreen(out.normal);
    for (std::size_t p = 0; p < out.albedo.size(); ++p)
        if (!out.covered[p])
            out.albedo[p] = {0, 0, 0, 0};
    return out;
}

nlohmann::json manifest(const Session& session, const Layout& layout, bool modelUvs,
                        const std::string& chemical, const HeightLevels& levels,
                        const ModelTextureSetOptions& options, float observedMin,
                        float observedMax) {
    using nlohmann::json;
    const HeightSpec& h = session.heightMaps;
    json files = json::array();
    const auto file = [&](const char* name, const std::string& meaning, const char* colourSpace,
                          const json& depth) {
        files.push_back(textureSetFileEntry(name, meaning, colourSpace, depth));
    };
    file("albedo.png",
         "colour map '" + session.colormap.name + "' of chemical '" + chemical +
             "' as the model shows it; alpha 0 where no part of the model is",
         "sRGB", 8);
    file("height.png",
         "height of chemical '" + chemical + "': (value - low) / (high - low), clamped to [0, 1]",
         "linear", 16);
    file("height.exr",
         "height of chemical '" + chemical +
             "': (value - low) / (high - low), not clamped, one float channel 'height'",
         "linear", "32-bit float");
    file("normal.png", "tangent-space normal map of the height, RGB = n * 0.5 + 0.5", "linear", 8);
    file("mask.png", "255 where the height is above mask_threshold, else 0", "linear", 8);
    file("model.glb",
         modelUvs ? "the model with its own UVs, the base colour and normal map embedded"
                  : "the tiled surface, whose UVs index this set's atlas layout",
         "", json());
    file("session.json",
         "the session that reproduces this set (morphogen render --session session.json "
         "--texture-set DIR)",
         "", json());
    json out = {
        {"generator", "morphogen render --texture-set (on a model)"},
        {"layout", modelUvs ? "model uvs" : "tiles atlas"},
        {"model", session.surface.mesh},
        {"size", {layout.width, layout.height}},
        {"chemical", chemical},
        {"height",
         {{"low", levels.low},
          {"high", levels.high},
          {"levels_from", levels.source},
          {"observed", {observedMin, observedMax}}}},
        {"normal",
         {{"format", toString(h.normalFormat)},
          {"green",
           h.normalFormat == NormalFormat::OpenGl ? "+Y up the image" : "+Y down the image"},
          {"tangent", "along +u of the layout's texture coordinates"},
          {"strength", h.normalStrength},
          {"strength_units", "1: a height step of 1 rises 2 mean texel lengths of the surface "
                             "tiles (the relief the model.glb and screenshots show)"}}},
        {"mask_threshold", h.maskThreshold},
        {"session", "session.json"},
        {"files", files}};
    if (modelUvs)
        out["padding"] = options.padding;
    return out;
}

} // namespace

const std::vector<std::string>& modelTextureSetFiles() {
    static const std::vector<std::string> files = {"albedo.png",   "height.png",      "height.exr",
                                                   "normal.png",   "mask.png",        "model.glb",
                                                   "session.json", "texture_set.json"};
    return files;
}

ModelTextureSetSummary writeModelTextureSet(const std::string& dir, const State& state,
                                            const Session& session, const SurfaceTiles& tiles,
                                            const UvMesh* uvs,
                                            const ModelTextureSetOptions& options,
                                            OutputFiles& files) {
    prepareTextureSetDir(dir);
    const Atlas& atlas = *tiles.atlas;
    const int chemical = colormapChemical(session.colormap, session.outputModel());
    const std::string chemicalName = session.outputModel().chemicals()[std::size_t(chemical)].name;
    const HeightLevels levels = heightLevels(session, chemical);
    const SurfaceColours colours = surfaceColours(state, session, atlas);
    const float* plane = state.plane(chemical);
    const std::vector<float> value(plane, plane + atlas.cellCount());
    float observedMin = 0, observedMax = 0;
    bool any = false;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            observedMin = any ? std::min(observedMin, value[i]) : value[i];
            observedMax = any ? std::max(observedMax, value[i]) : value[i];
            any = true;
        }

    const Layout layout =
        uvs ? inModelUvs(*uvs, tiles, colours, value, levels, session.heightMaps, options)
            : inTheAtlas(tiles, colours, value, levels, session.heightMaps);
    const fs::path d(dir);
    const auto staged = [&](const char* name) { return files.stage((d / name).string()); };
    const int w = layout.width, hgt = layout.height;
    const auto rowStart = [&](int y) { return std::size_t(y) * std::size_t(w); };
    writeImageRows(staged("albedo.png"), w, hgt, 4, 8, [&](int y, float* row) {
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < 4; ++k)
                row[x * 4 + k] =
                    layout.albedo[rowStart(y) + std::size_t(x)][std::size_t(k)] / 255.0f;
    });
    const auto heightRow = [&](int y, float* row) {
        std::copy_n(layout.heightMap.data() + rowStart(y), std::size_t(w), row);
    };
    writeImageRows(staged("height.png"), w, hgt, 1, 16, heightRow);
    writeRawRows(staged("height.exr"), w, hgt, 1, {"height"}, heightRow);
    writeImageRows(staged("normal.png"), w, hgt, 3, 8, [&](int y, float* row) {
        for (int x = 0; x < w; ++x)
            for (int k = 0; k < 3; ++k)
                row[x * 3 + k] =
                    layout.normal.texels[rowStart(y) + std::size_t(x)][std::size_t(k)] / 255.0f;
    });
    const float threshold = session.heightMaps.maskThreshold;
    writeImageRows(staged("mask.png"), w, hgt, 1, 8, [&](int y, float* row) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = rowStart(y) + std::size_t(x);
            row[x] = layout.covered[i] && layout.heightMap[i] > threshold ? 1.0f : 0.0f;
        }
    });
    writeTexturedGlb(layout.model, staged("model.glb"));
    saveSessionFile(session, staged("session.json"));
    writeTextAtomically(staged("texture_set.json"),
                        manifest(session, layout, uvs != nullptr, chemicalName, levels, options,
                                 observedMin, observedMax)
                                .dump(2) +
                            "\n");
    return {uvs != nullptr, w, hgt};
}

} // namespace morphogen
