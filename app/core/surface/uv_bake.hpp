#pragma once
// Baking a pattern grown on surface tiles into the artist's own texture
// layout: the model as its file has it (its vertices, its UVs), textures
// whose texels sample the pattern where they lie on the surface, so the
// result drops into any material that uses those UVs.

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh/mesh_io.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/surface_tiles.hpp"
#include "core/surface/textured_surface.hpp"

namespace morphogen {

struct UvBakeOptions {
    int size = 1024;   // texels per side of each texture
    int padding = 8;   // texels of dilation beyond the UV islands' edges
    float bump = 2.0f; // relief, in mean texel lengths of the tiles (SurfaceLook::bump)
};

// `mesh` ready for writeTexturedGlb, with textures in its own UV layout. Each
// texel a triangle of `mesh` covers in UV space gets the pattern at its point
// of that triangle: the colour and height of the tiled surface's texels
// nearest to it, blended by distance, among those facing the same way where
// any are near (so a thin part's two sides do not swap). Texels beyond the islands take the mean of
// their covered neighbours, `padding` rings out (mipmaps then do not bleed
// the background into the edges); the rest are transparent black. The normal
// map is the baked height's, in the tangent frame of the UVs' derivatives
// (per vertex, as glTF's TANGENT). UVs outside [0, 1] are refused by
// bakeableUvs. Throws std::invalid_argument for an inconsistent mesh.
TexturedMesh bakeIntoUvs(const UvMesh& mesh, const SurfaceTiles& tiles,
                         const SurfaceColours& colours, const UvBakeOptions& options = {});

// What a bake samples per texel of the size x size layout (row 0: v = 0),
// before any image is made of it: the texture set writes its own maps from
// these, bakeIntoUvs its GLB textures.
struct UvTexels {
    int size = 0;
    std::vector<std::array<std::uint8_t, 4>> colour; // alpha 0 where nothing is
    std::vector<float> height;                       // SurfaceColours::height
    std::vector<float> value;         // the `value` field given to sampleIntoUvs, if any
    std::vector<float> worldPerTexel; // surface length per texel of the layout
    std::vector<char> covered;        // on an island or in its padding
};

// Samples the pattern into the UV layout as bakeIntoUvs does; `value`, when
// given, is one more per-cell field (a chemical's raw value) blended and
// padded alike.
UvTexels sampleIntoUvs(const UvMesh& mesh, const SurfaceTiles& tiles, const SurfaceColours& colours,
                       const UvBakeOptions& options, const std::vector<float>* value = nullptr);

// The tangent-space normal map of a baked height (one value per texel of
// `texels`, 0 where not covered), the surface rising `relief` world units for
// a height step of 1: x along +u; y along +v (rows down the image) when
// yDown, else up the image (OpenGL's and MikkTSpace-from-v-up convention).
RgbaImage uvNormalMap(const UvTexels& texels, const std::vector<float>& height, double relief,
                      bool yDown);

// `mesh` with its vertex normals and tangents (the bitangent along -v, up the image, as
// bakeIntoUvs's normal map expects) and the two textures.
TexturedMesh uvBakedMesh(const UvMesh& mesh, RgbaImage baseColour, RgbaImage normalMap);

// The relief bakeIntoUvs gives the normal map for a height step of 1: `bump`
// mean texel lengths of the tiles.
double uvRelief(const SurfaceTiles& tiles, float bump);

// Whether every UV lies in [0, 1] (tiled or UDIM layouts do not: they are
// not baked, the atlas export is used instead).
bool bakeableUvs(const UvMesh& mesh);

} // namespace morphogen
