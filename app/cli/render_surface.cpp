#include "cli/render_surface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/output/colormap.hpp"
#include "core/output/model_texture_set.hpp"
#include "core/session/session.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_features.hpp"
#include "core/surface/surface_glb.hpp"
#include "core/surface/uv_bake.hpp"
#include "gl/surface_view.hpp"

namespace morphogen::cli {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string framePath(const std::string& out, int frame) {
    std::filesystem::path p(out);
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "_%03d", frame);
    return (p.parent_path() / (p.stem().string() + suffix + p.extension().string())).string();
}

// The session's camera as the renderer takes it.
gl::ViewOptions viewOptions(const SurfaceView& v) {
    gl::ViewOptions view;
    view.width = v.width;
    view.height = v.height;
    view.azimuth = v.azimuth;
    view.elevation = v.elevation;
    view.distance = v.distance;
    return view;
}

void writeScreenshot(const gl::SurfaceImage& image, const std::string& path) {
    writeImageRows(path, image.width, image.height, 4, 8, [&](int y, float* row) {
        const std::uint8_t* src = image.rgba.data() + std::size_t(y) * image.width * 4;
        for (int i = 0; i < image.width * 4; ++i)
            row[i] = src[i] / 255.0f;
    });
}

// A model whose parts lie far apart (or that is a sliver of its bounding box)
// covers a few pixels of a screenshot framed on the whole: an empty-looking
// picture that must not pass in silence.
void warnIfBarelyVisible(const gl::SurfaceImage& image, const gl::ViewOptions& view,
                         const SurfaceSetup& setup, const std::string& path) {
    std::uint8_t background[4];
    for (int c = 0; c < 4; ++c)
        background[c] = std::uint8_t(
            std::lround(std::clamp(view.background[std::size_t(c)], 0.0f, 1.0f) * 255));
    std::size_t covered = 0;
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    for (std::size_t i = 0; i < pixels; ++i)
        covered += std::equal(background, background + 4, image.rgba.data() + i * 4) ? 0 : 1;
    if (double(covered) >= 0.005 * double(pixels))
        return;
    const MeshReport report = checkMesh(setup.mesh.mesh);
    std::fprintf(stderr,
                 "morphogen: warning: %s: the model covers %zu of its %zu pixels (%.3g%%): the "
                 "view frames the whole bounding box (diagonal %.6g), and the model's %zu "
                 "part(s) fill little of it%s; move the camera closer with --view "
                 "AZIMUTH,ELEVATION,DISTANCE, or render the parts as separate models\n",
                 path.c_str(), covered, pixels, 100.0 * double(covered) / double(pixels),
                 double(report.bounds.diagonal()), report.components.size(),
                 report.components.size() > 1 ? " (they lie far apart)" : "");
}

} // namespace

bool isModelOutput(const std::string& out) {
    return lowerExtension(out) == ".glb";
}

void checkSurfaceOutput(const std::string& out) {
    if (isModelOutput(out))
        return;
    if (imageFormatForPath(out) == ImageFormat::Exr)
        throw InputError("--out " + out +
                         ": a surface render writes a screenshot (PNG, JPEG, "
                         "TIFF) or the textured model (.glb), not raw EXR chemicals");
}

std::string describeSurfaceResult(const RunResult& result, const SurfaceSetup& setup) {
    const Session& session = result.completed;
    const SurfaceTiles& tiles = setup.tiles;
    const int chemical = colormapChemical(session.colormap, session.outputModel());
    const std::vector<SurfaceFeature> features = findSurfaceFeatures(
        *tiles.atlas, result.state.plane(chemical), tiles.texelArea, tiles.texelPositions);
    const FeatureAreaStats stats = featureAreaStats(features);
    std::ostringstream os;
    os.precision(3);
    if (stats.count == 0)
        return "no features on the surface";
    const double across = boundsOf(setup.mesh.mesh.positions).diagonal() /
                          std::sqrt(tiles.surfaceArea / double(stats.count));
    os << stats.count << " features on the surface (spots or stripe pieces), about " << across
       << " across the model (its bounding-box diagonal); feature areas vary by "
       << stats.coefficientOfVariation * 100 << "% (coefficient of variation)";
    return os.str();
}

void checkBakeSize(int size) {
    if (size < 16 || size > 8192)
        throw InputError("--bake-size " + std::to_string(size) +
                         " is out of range (accepted: 16..8192 texels per side)");
}

std::vector<std::string> writeSurfaceOutput(const RunResult& result, const SurfaceSetup& setup,
                                            const SurfaceOutputPaths& paths, gl::Context* context,
                                            std::optional<gl::ContextKind> contextKind,
                                            OutputFiles& files) {
    checkBakeSize(paths.bakeSize);
    const std::string& out = paths.out;
    std::vector<std::string> written;
    const Atlas& atlas = *setup.tiles.atlas;
    const SurfaceView& v = result.completed.surface.view;
    // A model with texture coordinates gets the pattern baked into them: its
    // own mesh and layout, ready for its material. Without, the tiled surface
    // and its atlas are the model.
    std::optional<UvMesh> uvs;
    if (isModelOutput(out) || !paths.textureSetDir.empty()) {
        uvs = readUvMesh(setup.mesh.file.path);
        if (uvs && !bakeableUvs(*uvs)) {
            std::fprintf(stderr, "morphogen: the model's texture coordinates leave [0, 1] (a "
                                 "tiled or UDIM layout): written in the tiles' atlas instead\n");
            uvs.reset();
        }
    }
    // The finer atlas texture's colours only where an atlas texture is drawn
    // (a screenshot, or an export without the model's UVs): a bake into the
    // UVs samples the atlas texels themselves.
    SurfaceLook look;
    if (uvs && (out.empty() || isModelOutput(out)))
        look.scale = 1;
    const SurfaceColours c = surfaceColours(result.state, result.completed, atlas, {}, look);
    if (!paths.textureSetDir.empty()) {
        ModelTextureSetOptions options;
        options.size = paths.bakeSize;
        const ModelTextureSetSummary summary =
            writeModelTextureSet(paths.textureSetDir, result.state, result.completed, setup.tiles,
                                 uvs ? &*uvs : nullptr, options, files);
        std::fprintf(stderr, "morphogen: texture set in %s: %dx%d\n",
                     summary.modelUvs ? "the model's own texture coordinates"
                                      : "the tiles' atlas (the model has no texture coordinates; "
                                        "model.glb is the tiled surface that uses it)",
                     summary.width, summary.height);
        written.push_back(
            (std::filesystem::path(paths.textureSetDir) / "texture_set.json").string());
    }
    if (!out.empty() && isModelOutput(out)) {
        if (uvs) {
            UvBakeOptions bake;
            bake.size = paths.bakeSize;
            writeTexturedGlb(bakeIntoUvs(*uvs, setup.tiles, c, bake), files.stage(out));
            const std::size_t materials = uvs->materials.materials.size();
            std::fprintf(stderr,
                         "morphogen: baked into the model's own texture coordinates: %zu "
                         "vertices, %zu triangles, %dx%d textures%s\n",
                         uvs->positions.size(), uvs->triangles.size(), bake.size, bake.size,
                         materials == 0 ? ""
                                        : (", its " + std::to_string(materials) +
                                           (materials == 1 ? " material" : " materials") +
                                           " kept with the pattern as base colour and normal map")
                                              .c_str());
        } else {
            writeTexturedGlb(texturedSurface(setup.tiles, c), files.stage(out));
        }
        written.push_back(out);
    } else if (!out.empty()) {
        std::unique_ptr<gl::Context> own;
        if (context)
            context->makeCurrent();
        else
            own = gl::createHeadlessContext(contextKind);
        const gl::ViewOptions view = viewOptions(v);
        const gl::SurfaceRenderer renderer(texturedSurface(setup.tiles, c));
        if (v.turntable > 0) {
            const std::vector<gl::SurfaceImage> frames =
                gl::renderTurntable(renderer, view, v.turntable);
            for (int k = 0; k < int(frames.size()); ++k) {
                const std::string path = framePath(out, k);
                if (k == 0)
                    warnIfBarelyVisible(frames[0], view, setup, path);
                writeScreenshot(frames[std::size_t(k)], files.stage(path));
                written.push_back(path);
            }
        } else {
            const gl::SurfaceImage image = renderer.render(view);
            warnIfBarelyVisible(image, view, setup, out);
            writeScreenshot(image, files.stage(out));
            written.push_back(out);
        }
    }
    if (!paths.sessionOut.empty()) {
        saveSessionFile(result.completed, files.stage(paths.sessionOut));
        written.push_back(paths.sessionOut);
    }
    return written;
}

SurfaceFrames::SurfaceFrames(const SurfaceSetup& setup, gl::Context* context,
                             std::optional<gl::ContextKind> contextKind)
    : m_setup(setup), m_context(context), m_contextKind(contextKind) {}

SurfaceFrames::~SurfaceFrames() = default;

void SurfaceFrames::draw(const std::string& path, const RunResult& sofar,
                         const FrameColouring& colouring) {
    if (m_context)
        m_context->makeCurrent();
    else if (!m_own)
        m_own = gl::createHeadlessContext(m_contextKind);
    // An earlier stage's own chemical (frameColouring): surfaceColours reads
    // the colour map from the session.
    std::optional<Session> stage;
    if (colouring.spec.chemical != sofar.completed.colormap.chemical) {
        stage = sofar.completed;
        stage->colormap = colouring.spec;
    }
    const SurfaceColours c =
        surfaceColours(sofar.state, stage ? *stage : sofar.completed, *m_setup.tiles.atlas,
                       std::make_pair(colouring.levels.low, colouring.levels.high), {}, m_display);
    m_display = c.displayAtlas;
    const TexturedMesh textured = texturedSurface(m_setup.tiles, c);
    if (m_renderer)
        m_renderer->setTextures(textured);
    else
        m_renderer = std::make_unique<gl::SurfaceRenderer>(textured);
    writeScreenshot(m_renderer->render(viewOptions(sofar.completed.surface.view)), path);
}

} // namespace morphogen::cli
