#pragma once

#include <optional>
#include <string>

#include "core/io/output_files.hpp"
#include "core/sim/runner.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/context.hpp"

namespace morphogen::cli {

// Whether `out` asks for the textured model (.glb) rather than a screenshot.
bool isModelOutput(const std::string& out);

// Checks a surface render's output path before the run: .glb, or an 8-bit
// image format a screenshot can be (PNG, JPEG, TIFF, ...). Throws InputError.
void checkSurfaceOutput(const std::string& out);

// After a surface run: the feature count and how many fit across the model,
// the spread of feature areas (for the report).
std::string describeSurfaceResult(const RunResult& result, const SurfaceSetup& setup);

// Writes a surface run's outputs into `files`: the textured model (out.glb)
// or the screenshot (one, or view.turntable of them named OUT_000.png ...),
// drawn on `context` (null: a headless context of `contextKind` is made), then
// the session. Returns the paths written, in order.
std::vector<std::string> writeSurfaceOutput(const RunResult& result, const SurfaceSetup& setup,
                                            const std::string& out, const std::string& sessionOut,
                                            gl::Context* context,
                                            std::optional<gl::ContextKind> contextKind,
                                            OutputFiles& files);

} // namespace morphogen::cli
