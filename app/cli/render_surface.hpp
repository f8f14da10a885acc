#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/io/output_files.hpp"
#include "core/output/frames.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/display_atlas.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/context.hpp"

namespace morphogen::gl {
class SurfaceRenderer;
}

namespace morphogen::cli {

// Whether `out` asks for the textured model (.glb) rather than a screenshot.
bool isModelOutput(const std::string& out);

// Checks a surface render's output path before the run: .glb, or an 8-bit
// image format a screenshot can be (PNG, JPEG, TIFF, ...). Throws InputError.
void checkSurfaceOutput(const std::string& out);

// After a surface run: the feature count and how many fit across the model,
// the spread of feature areas (for the report).
std::string describeSurfaceResult(const RunResult& result, const SurfaceSetup& setup);

// What a surface render writes; empty paths are not written.
struct SurfaceOutputPaths {
    std::string out;           // a screenshot or the textured model (.glb)
    std::string sessionOut;    // the session
    std::string textureSetDir; // a texture set in the model's UVs (or the tiles' atlas)
    int bakeSize = 1024;       // texels per side of what is baked into the model's UVs
};

// Writes a surface run's outputs into `files`: the texture set, the textured
// model (out.glb; baked into the model's own UVs when it has them in
// [0, 1], else the tiled surface and its atlas) or the screenshot (one, or
// view.turntable of them named OUT_000.png ...), drawn on `context` (null: a
// headless context of `contextKind` is made), then the session. Returns the
// paths written, in order.
std::vector<std::string> writeSurfaceOutput(const RunResult& result, const SurfaceSetup& setup,
                                            const SurfaceOutputPaths& paths, gl::Context* context,
                                            std::optional<gl::ContextKind> contextKind,
                                            OutputFiles& files);

// Checks --bake-size before the run; throws InputError naming the value.
void checkBakeSize(int size);

// The frames of a run on a model (`render --frames N` with a mesh): each one
// a screenshot from the session's view, its colours at the frames' locked
// levels (the relief and a watercolour's water as in the final screenshot),
// drawn on `context` (null: a headless context of `contextKind`, made on the
// first frame). The mesh is uploaded once; later frames re-texture it.
class SurfaceFrames {
public:
    SurfaceFrames(const SurfaceSetup& setup, gl::Context* context,
                  std::optional<gl::ContextKind> contextKind);
    ~SurfaceFrames();
    SurfaceFrames(const SurfaceFrames&) = delete;
    SurfaceFrames& operator=(const SurfaceFrames&) = delete;

    void draw(const std::string& path, const RunResult& sofar, const FrameColouring& colouring);

private:
    const SurfaceSetup& m_setup;
    gl::Context* m_context;
    std::optional<gl::ContextKind> m_contextKind;
    std::unique_ptr<gl::Context> m_own;
    std::unique_ptr<gl::SurfaceRenderer> m_renderer;
    std::shared_ptr<const DisplayAtlas> m_display; // the first frame's, for the rest
};

} // namespace morphogen::cli
