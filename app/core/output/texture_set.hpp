#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/base/state.hpp"
#include "core/domain/grid_domain.hpp"
#include "core/io/output_files.hpp"
#include "core/session/session.hpp"

namespace morphogen {

// A texture set from one final state: albedo (the colour map), height, a
// tangent-space normal map and a mask, for a game engine or a renderer.

// The chemical values mapped to height 0 and 1: fixed levels, the same for
// every render of a model, so a series of renders matches (not the colour
// map's per-image min-max).
struct HeightLevels {
    float low = 0.0f;
    float high = 1.0f;
    std::string source; // "session" (the "height" block) or "model display range"
};

// session.height.range, else the display range of `chemical` of the final
// state's model.
HeightLevels heightLevels(const Session& session, int chemical);

// Linear height of one chemical: (value - low) / (high - low), not clamped
// (the EXR keeps values outside the levels; PNG writers clamp to [0, 1]).
std::vector<float> heightField(const State& state, int chemical, const HeightLevels& levels);

// Tangent-space normals of a height field (row 0 at the top of the image) as
// interleaved RGB in [0, 1] (n * 0.5 + 0.5). The surface is z = strength * h
// texels, i.e. a height step of the whole range (0 to 1) rises `strength`
// texels; slopes are central differences over two texels, wrapped on
// periodic edges (so the map tiles) and with the edge texel repeated on
// clamped ones. OpenGL: +Y (green) points up the image; DirectX: down.
std::vector<float> normalMap(const std::vector<float>& height, int width, int height_,
                             EdgeMode edges, float strength, NormalFormat format);

// 1 where height > threshold, else 0 (written as 255 / 0).
std::vector<float> heightMask(const std::vector<float>& height, float threshold);

// The files of a set, in the order written.
const std::vector<std::string>& textureSetFiles();

// Creates `dir` if needed and checks it can be written, before a long run;
// throws InputError naming it.
void prepareTextureSetDir(const std::string& dir);

// Writes albedo.png, height.png (16-bit), height.exr, normal.png, mask.png,
// session.json (the session that reproduces the set) and texture_set.json
// (the manifest) into `dir`, creating it. Throws InputError when the folder
// cannot be created or written.
// They replace a previous set together, once all are written (output_files.hpp).
void writeTextureSet(const std::string& dir, const State& state, const Session& session);
// The same, staged into `files` with other outputs of the run; renamed into
// place by files.commit(), in the order above (the manifest last).
void writeTextureSet(const std::string& dir, const State& state, const Session& session,
                     OutputFiles& files);

// One entry of a manifest's "files": the file, what it holds, its colour space
// and bit depth (null for a file that is no image).
nlohmann::json textureSetFileEntry(const std::string& name, const std::string& meaning,
                                   const std::string& colourSpace, const nlohmann::json& bitDepth);

// The manifest texture_set.json holds (exposed for tests).
nlohmann::json textureSetManifest(const Session& session, int chemical, const HeightLevels& levels,
                                  float observedMin, float observedMax);

} // namespace morphogen
