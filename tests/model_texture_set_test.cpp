// A texture set for a model (core/output/model_texture_set.hpp): in the
// model's own UVs each island texel's height is the chemical at its point on
// the surface, the normal map is that height's slope in the stated
// convention, the albedo is transparent where no part of the model is; a
// model without UVs gets the tiles' atlas and the tiled surface as model.glb.
// The chemical is a smooth made-up field of position, so what a texel should
// hold is known.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/mesh/mesh_samples.hpp"
#include "core/output/colormap.hpp"
#include "core/output/model_texture_set.hpp"
#include "core/output/texture_set.hpp"
#include "core/surface/display_atlas.hpp"
#include "core/surface/surface_glb.hpp"
#include "core/surface/tile_builder.hpp"
#include "test_support.hpp"
#include "uv_torus_fixture.hpp"

using namespace morphogen;

namespace {

// The field's height (0..1 over the session's levels) at a point.
double fieldHeight(const Eigen::Vector3f& p) {
    return 0.5 + 0.4 * std::sin(1.3 * p.x()) * std::cos(0.9 * p.z());
}

struct Fixture {
    UvMesh mesh; // uv_torus_fixture.hpp
    SurfaceTiles tiles;
    Session session;
    State state;
    HeightLevels levels;
};

Fixture makeFixture() {
    Fixture f;
    test::UvTorus torus = test::uvTorus();
    f.mesh = std::move(torus.mesh);
    f.tiles = std::move(torus.tiles);
    f.session = loadPreset("turk_small_spots");
    f.session.surface.mesh = "torus.obj";
    const ReactionModel& model = f.session.outputModel();
    const Atlas& atlas = *f.tiles.atlas;
    f.state = State(atlas.width(), atlas.height(), int(model.chemicals().size()));
    const int chemical = colormapChemical(f.session.colormap, model);
    f.levels = heightLevels(f.session, chemical);
    float* plane = f.state.plane(chemical);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i))
            plane[i] = float(f.levels.low + (f.levels.high - f.levels.low) *
                                                fieldHeight(f.tiles.texelPositions[i]));
    return f;
}

struct Image {
    int width = 0, height = 0, channels = 0;
    std::vector<float> px;
    float at(int x, int y, int c = 0) const {
        return px[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
                  std::size_t(c)];
    }
};

Image readImage(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    EXPECT_TRUE(in) << path;
    Image image;
    if (!in)
        return image;
    image.width = in->spec().width;
    image.height = in->spec().height;
    image.channels = in->spec().nchannels;
    image.px.resize(std::size_t(image.width) * std::size_t(image.height) *
                    std::size_t(image.channels));
    EXPECT_TRUE(in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.px.data()));
    return image;
}

std::filesystem::path writeSet(const Fixture& f, const std::string& name, const UvMesh* uvs,
                               int size) {
    const std::filesystem::path dir = test::scratchDir("morphogen_model_texture_set_test") / name;
    ModelTextureSetOptions options;
    options.size = size;
    OutputFiles files;
    writeModelTextureSet(dir.string(), f.state, f.session, f.tiles, uvs, options, files);
    files.commit();
    return dir;
}

} // namespace

TEST(ModelTextureSet, InTheModelsUvsEachTexelHoldsTheHeightAtItsPoint) {
    const Fixture f = makeFixture();
    const int size = 256;
    const std::filesystem::path dir = writeSet(f, "uvs", &f.mesh, size);
    for (const std::string& file : modelTextureSetFiles())
        EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
    const Image height = readImage(dir / "height.exr");
    const Image albedo = readImage(dir / "albedo.png");
    const Image mask = readImage(dir / "mask.png");
    ASSERT_EQ(height.width, size);
    ASSERT_EQ(albedo.channels, 4);
    // At each triangle's centroid. Tolerance: the blend spans about 1.5 tile
    // texels (0.06 units) and the texel centre lies up to half a baked texel
    // from the centroid; the field's slope is at most 0.53 per unit: 0.05.
    double worst = 0;
    int checked = 0;
    for (const auto& t : f.mesh.triangles) {
        const Eigen::Vector2f uv = (f.mesh.uvs[t[0]] + f.mesh.uvs[t[1]] + f.mesh.uvs[t[2]]) / 3;
        const Eigen::Vector3f p =
            (f.mesh.positions[t[0]] + f.mesh.positions[t[1]] + f.mesh.positions[t[2]]) / 3;
        const int x = int(uv.x() * size), y = int(uv.y() * size);
        ASSERT_EQ(albedo.at(x, y, 3), 1.0f) << "an island texel left transparent";
        const double h = height.at(x, y);
        worst = std::max(worst, std::abs(h - fieldHeight(p)));
        EXPECT_EQ(mask.at(x, y), h > f.session.heightMaps.maskThreshold ? 1.0f : 0.0f);
        ++checked;
    }
    EXPECT_GT(checked, 500);
    EXPECT_LE(worst, 0.05);
    // Far from the island: transparent, no height, no mask.
    EXPECT_EQ(albedo.at(230, 240, 3), 0.0f);
    EXPECT_EQ(height.at(230, 240), 0.0f);
    EXPECT_EQ(mask.at(230, 240), 0.0f);
    // Padded: three texels right of the island's edge (u = 0.6).
    EXPECT_EQ(albedo.at(int(0.6 * size) + 3, size / 2, 3), 1.0f);

    std::ifstream in(dir / "texture_set.json");
    const nlohmann::json manifest = nlohmann::json::parse(in);
    EXPECT_EQ(manifest["layout"], "model uvs");
    EXPECT_EQ(manifest["size"], nlohmann::json::array({size, size}));
    EXPECT_EQ(manifest["normal"]["green"], "+Y up the image");
    const TexturedMesh model = readTexturedGlb((dir / "model.glb").string());
    EXPECT_EQ(model.positions.size(), f.mesh.positions.size());
    EXPECT_EQ(model.baseColour.width, size);
}

// The share of texels where the normal leans against the height's slope as
// `format` says: OpenGL's green runs up the image (where the height rises
// towards the top row, green is below 0.5), DirectX's down; red against the
// slope to the right. Only texels whose four neighbours are `inside` and
// whose height differs by `clear` or more across them both ways.
double agreement(const Image& height, const Image& normal, NormalFormat format,
                 const std::vector<char>& inside, float clear, int& sloped) {
    int agree = 0;
    sloped = 0;
    const int w = height.width;
    const auto in = [&](int x, int y) { return inside[std::size_t(y) * std::size_t(w) + x] != 0; };
    for (int y = 1; y < height.height - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            if (!in(x, y - 1) || !in(x, y + 1) || !in(x - 1, y) || !in(x + 1, y))
                continue;
            const float up = height.at(x, y - 1) - height.at(x, y + 1);
            const float right = height.at(x + 1, y) - height.at(x - 1, y);
            if (std::abs(up) < clear || std::abs(right) < clear)
                continue; // where the slope is clear
            const float green = normal.at(x, y, 1) - 0.5f, red = normal.at(x, y, 0) - 0.5f;
            const float wantGreen = format == NormalFormat::OpenGl ? -up : up;
            ++sloped;
            agree += (green * wantGreen > 0 && red * -right > 0) ? 1 : 0;
        }
    return sloped ? double(agree) / sloped : 0.0;
}

TEST(ModelTextureSet, TheNormalMapIsTheHeightsSlopeInTheStatedConvention) {
    Fixture f = makeFixture();
    const Atlas& atlas = *f.tiles.atlas;
    const DisplayAtlas display(atlas, SurfaceLook{}.gutter, displayScale(atlas, SurfaceLook{}));
    // The atlas layout: the texels of each tile (not its gutter).
    std::vector<char> inTiles(display.texelCount(), 0);
    for (int tile = 0; tile < atlas.tileCount(); ++tile)
        for (int v = 0; v < display.displayTileSize(); ++v)
            for (int u = 0; u < display.displayTileSize(); ++u) {
                const std::array<int, 2> p = display.texel(tile, u, v);
                inTiles[std::size_t(p[1]) * std::size_t(display.width()) + std::size_t(p[0])] = 1;
            }
    const int size = 128;
    for (NormalFormat format : {NormalFormat::OpenGl, NormalFormat::DirectX})
        for (bool modelUvs : {true, false}) {
            SCOPED_TRACE(toString(format) + (modelUvs ? " model uvs" : " atlas"));
            f.session.heightMaps.normalFormat = format;
            const std::filesystem::path dir =
                writeSet(f, toString(format) + (modelUvs ? "_uvs" : "_atlas"),
                         modelUvs ? &f.mesh : nullptr, size);
            const Image height = readImage(dir / "height.exr");
            const Image normal = readImage(dir / "normal.png");
            std::vector<char> inside = inTiles;
            if (modelUvs) {
                const Image albedo = readImage(dir / "albedo.png");
                inside.assign(albedo.px.size() / 4, 0);
                for (std::size_t i = 0; i < inside.size(); ++i)
                    inside[i] = albedo.px[i * 4 + 3] > 0 ? 1 : 0;
            }
            int sloped = 0;
            // The atlas's texture texels are a scale's fraction of a tile
            // texel: their steps in height are as much smaller.
            const float clear = modelUvs ? 0.01f : 0.01f / float(display.scale());
            const double share = agreement(height, normal, format, inside, clear, sloped);
            EXPECT_GT(sloped, 300);
            // In the model's UVs a few texels by the islands' seams see
            // neighbours across them. In the atlas the slope is taken on the
            // surface and written in an orthonormal frame (tangent along u),
            // so on skewed tiles the bitangent is not the image's v and some
            // texels with a small slope along one axis differ (the mirrored
            // convention agrees on under a tenth).
            EXPECT_GE(share, modelUvs ? 0.97 : 0.85) << sloped << " texels with a clear slope";
        }
}

TEST(ModelTextureSet, WithoutUvsTheSetIsInTheTilesAtlasWithTheTiledSurface) {
    const Fixture f = makeFixture();
    const std::filesystem::path dir = writeSet(f, "atlas", nullptr, 64);
    const Atlas& atlas = *f.tiles.atlas;
    const DisplayAtlas display(atlas, SurfaceLook{}.gutter, displayScale(atlas, SurfaceLook{}));
    ASSERT_GT(display.scale(), 1); // 4 x 4 tiles: the texture is finer than the atlas
    const Image albedo = readImage(dir / "albedo.png");
    const Image height = readImage(dir / "height.exr");
    EXPECT_EQ(albedo.width, display.width());
    EXPECT_EQ(albedo.height, display.height());
    std::ifstream in(dir / "texture_set.json");
    EXPECT_EQ(nlohmann::json::parse(in)["layout"], "tiles atlas");
    const TexturedMesh model = readTexturedGlb((dir / "model.glb").string());
    ASSERT_EQ(model.baseColour.width, display.width());
    // Every texel of a tile: opaque albedo equal to the GLB's; where the
    // texel's bilinear footprint lies inside its tile, the height is the
    // bilinear interpolation of its four atlas cells' heights at its centre.
    const int n = atlas.tileSize(), s = display.scale();
    double worst = 0;
    int interpolated = 0;
    for (int tile = 0; tile < atlas.tileCount(); ++tile)
        for (int v = 0; v < n * s; ++v)
            for (int u = 0; u < n * s; ++u) {
                const std::array<int, 2> p = display.texel(tile, u, v);
                const double x = (u + 0.5) / s - 0.5, y = (v + 0.5) / s - 0.5;
                const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
                if (x0 >= 0 && y0 >= 0 && x0 + 1 < n && y0 + 1 < n) {
                    const auto h = [&](int i, int j) {
                        return fieldHeight(f.tiles.texelPositions[atlas.tileCell(tile, i, j)]);
                    };
                    const double fx = x - x0, fy = y - y0;
                    const double want = (1 - fx) * (1 - fy) * h(x0, y0) +
                                        fx * (1 - fy) * h(x0 + 1, y0) +
                                        (1 - fx) * fy * h(x0, y0 + 1) + fx * fy * h(x0 + 1, y0 + 1);
                    worst = std::max(worst, std::abs(height.at(p[0], p[1]) - want));
                    ++interpolated;
                }
                ASSERT_EQ(albedo.at(p[0], p[1], 3), 1.0f);
                const auto& glb =
                    model.baseColour.texels[std::size_t(p[1]) * std::size_t(display.width()) +
                                            std::size_t(p[0])];
                ASSERT_NEAR(albedo.at(p[0], p[1], 0) * 255.0f, glb[0], 0.5f);
            }
    EXPECT_GT(interpolated, atlas.tileCount() * (n - 1) * (n - 1) * s * s / 2);
    // The EXR holds floats of (value - low) / (high - low): rounding only.
    EXPECT_LE(worst, 1e-5);
}
