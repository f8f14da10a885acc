#pragma once
// Baking a pattern grown on surface tiles into the artist's own texture
// layout: the model as its file has it (its vertices, its UVs), textures
// whose texels sample the pattern where they lie on the surface, so the
// result drops into any material that uses those UVs.

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

// Whether every UV lies in [0, 1] (tiled or UDIM layouts do not: they are
// not baked, the atlas export is used instead).
bool bakeableUvs(const UvMesh& mesh);

} // namespace morphogen
