#pragma once
// A texture set for a pattern grown on a model: the maps a flat render's set
// has (texture_set.hpp), laid out where the model's material reads them. A
// model with texture coordinates gets them in its own UV layout; one without
// gets them in the tiles' atlas, with the tiled surface (whose UVs index that
// atlas) as model.glb beside them.

#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/base/state.hpp"
#include "core/io/output_files.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/session/session.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

struct ModelTextureSetOptions {
    int size = 1024; // texels per side in the model's UVs (the atlas has its own size)
    int padding = 8; // texels of dilation beyond the UV islands
};

// What was written, for the log.
struct ModelTextureSetSummary {
    bool modelUvs = false; // in the model's UVs, else the tiles' atlas
    int width = 0, height = 0;
};

// The files of a model's set, in the order written.
const std::vector<std::string>& modelTextureSetFiles();

// Writes albedo.png (RGBA: alpha 0 off the islands and their padding), height.png
// (16-bit) and height.exr (the session's height levels, as a flat set), normal.png
// (the height's slope; strength 1 is the GLB's relief, `bump` mean tile texel
// lengths for a height step of 1, in the session's normal format), mask.png,
// model.glb (the model with the base colour and normal map embedded),
// session.json and texture_set.json into `dir`, staged into `files`.
// `uvs`: the model as its file has it, UVs in [0, 1] (bakeableUvs), or null
// for the atlas layout. Throws InputError when the folder cannot be written.
ModelTextureSetSummary writeModelTextureSet(const std::string& dir, const State& state,
                                            const Session& session, const SurfaceTiles& tiles,
                                            const UvMesh* uvs,
                                            const ModelTextureSetOptions& options,
                                            OutputFiles& files);

} // namespace morphogen
