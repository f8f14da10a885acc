#pragma once
// The limits on everything morphogen reads (session and preset JSON, palette
// files, images, command-line flags), written down once. Readers and flags
// check values against these and refuse others with an InputError (exit 2)
// naming the field or flag and the accepted range; products and sums are
// computed in 64 bits before they are compared. docs/limits.md lists
// them for users; keep the two in step.

#include <cstdint>

namespace morphogen {

// Grid: cells per side of a session, a schedule level, --size and the like.
// The GPU may allow less (checked at allocation).
constexpr int kMaxGridSide = 16384;

// Steps of a run: a session's "steps", a cascade stage's, a schedule level's,
// and their total over the stages or levels (--steps, --max-steps, a gallery's
// --steps-scale result). The engine also refuses a segment whose steps times
// its substeps (a grid finer than one cell per unit) pass INT_MAX.
constexpr long long kMaxSteps = 100000000;

// Cascade stages of a session ("stages").
constexpr int kMaxStages = 1000;

// Coarse-to-fine levels of a session ("schedule", --schedule).
constexpr int kMaxScheduleLevels = 32;

// Time step: a session's "dt" and a stage's, --dt, and what the stability
// check may cap a dt to (below kMinDt the session is refused instead).
constexpr double kMinDt = 1e-6;
constexpr double kMaxDt = 100.0;

// A session's "length" (the image's width in model units; 0: one unit per
// cell), also after --scale divides it.
constexpr double kMinLength = 1e-3;
constexpr double kMaxLength = 1e7;

// Relaxation passes of a semi-implicit step ("relaxation_passes", --relaxation-passes).
constexpr int kMaxRelaxationPasses = 1000;

// Seeds: integers a JSON number (a double) holds exactly.
constexpr long long kMaxSeed = 1LL << 53;

// A batched sweep: tiles of `sweep --grid` (columns x rows), and per side of
// a session's "tiles" grid (whose tiles must also be at least 4 x 4 cells).
constexpr int kMaxSweepTiles = 4096;
constexpr int kMaxTilesPerSide = 4096;
constexpr int kMinTileCells = 4;

// Images read (parameter maps, orientation and scale images, `colour`'s raw
// state): checked from the file's header before any pixel is decoded.
constexpr int kMaxImageSide = kMaxGridSide;
constexpr long long kMaxImagePixels = static_cast<long long>(kMaxGridSide) * kMaxGridSide;
constexpr int kMaxImageChannels = 64;

// Output paths: a file name's bytes (leaving room under the file system's
// 255 for the temporary names the writers use) and the whole path's.
constexpr int kMaxOutputNameBytes = 240;
constexpr int kMaxOutputPathBytes = 4000;

// JSON text (sessions, presets, palettes): file size and nesting of arrays
// and objects (checked on the text before it is parsed, so a deeply nested
// file cannot exhaust the stack).
constexpr std::int64_t kMaxJsonBytes = 16 * 1024 * 1024;
constexpr int kMaxJsonDepth = 64;

// Orientation fields: fields in one "orientation" (a blend's parts, counted
// through nested blends) and blends nested in blends.
constexpr int kMaxOrientationFields = 32;
constexpr int kMaxBlendDepth = 4;

// Generalized diffusion: the magnitude of a tensor component ("xx=1,...").
constexpr double kMaxTensorComponent = 1000.0;

// `bench --seconds`: time per measurement.
constexpr double kMaxBenchSeconds = 600.0;

// Surfaces (a session's "surface" block): texels per tile side, the tile
// budget, the screenshot's sides and turntable frames, the camera distance in
// bounding-sphere radii and the curvature scaling's strength.
constexpr int kMinSurfaceTileSize = 4;
constexpr int kMaxSurfaceTileSize = 64;
constexpr int kMinSurfaceTiles = 3;
constexpr int kMaxSurfaceTiles = 100000;
// The atlas's used texels (tiles x tile size^2; about 100 bytes of geometry and
// weights each on the CPU). The atlas must also stay under 65536 texels on a
// side (16-bit addresses on the GPU).
constexpr long long kMaxSurfaceTexels = 32LL * 1024 * 1024;
constexpr int kMinViewSide = 16;
constexpr int kMaxViewSide = 8192;
constexpr int kMaxTurntableFrames = 3600;
constexpr double kMinViewDistance = 1.05;
constexpr double kMaxViewDistance = 100.0;
constexpr double kMaxSurfaceScaleStrength = 100.0;
// A surface direction's axis and point, per coordinate (mesh units): far past
// any model, small enough that their products stay finite in float.
constexpr double kMaxSurfacePoint = 1e9;

} // namespace morphogen
