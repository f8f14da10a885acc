#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/mesh/mesh_material.hpp"
#include "core/surface/display_atlas.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// An 8-bit RGBA image, row 0 first (texture coordinate v = 0: the first row
// GL uploads and the top row of a PNG, as glTF expects).
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::array<std::uint8_t, 4>> texels;
};

// A tiled surface ready to draw or export: one triangle mesh with per-vertex
// attributes and two textures over the padded atlas (DisplayAtlas). The
// renderer (gl/surface_view.hpp) and the GLB file (surface_glb.hpp) hold
// exactly this, so a reloaded GLB draws the same as the direct render.
struct TexturedMesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals; // unit
    // xyz: unit tangent along +u, orthogonal to the normal; w = +-1, the
    // bitangent being w * cross(normal, tangent), along -v, up the image (glTF's TANGENT; its
    // normal textures have +Y up).
    std::vector<Eigen::Vector4f> tangents;
    std::vector<Eigen::Vector2f> uvs; // in [0, 1], inside the padded atlas
    std::vector<std::array<std::uint32_t, 3>> triangles;
    RgbaImage baseColour;
    // Tangent-space normals, xyz * 0.5 + 0.5 (alpha 255): x along the
    // tangent, y along the bitangent, z along the normal.
    RgbaImage normalMap;
    // glTF's metallic-roughness layout (roughness in G, metallic in B, R and
    // A 255) where the surface is partly wet (Lo 5.6's drops: smooth water
    // on a rough surface, from SurfaceColours::wetness); 0 x 0 when it is dry
    // everywhere (roughness 0.7, the renderer's plain shading).
    RgbaImage metallicRoughness;
    // The model's own materials, per triangle (a bake into its UVs): each
    // gets the textures above and keeps the rest (writeTexturedGlb). Empty:
    // one material of the exporter's.
    MeshMaterials materials;
};

struct SurfaceLook {
    int gutter = 2; // texels round each tile in the textures (DisplayAtlas)
    // Texture texels per atlas texel along a side (DisplayAtlas's scale); 0:
    // displayScale's choice. 1 pads the atlas as it is (the designer's live
    // view, redrawn as the pattern grows).
    int scale = 0;
    // Bump mapping (Turk 1991, "Rendering"): the height, min-max normalised
    // to 0..1, acts as a relief `bump` mean texel lengths high (bakeNormalMap;
    // measured on the surface, so stretched or skewed texels get the same
    // relief). 0: no relief.
    float bump = 2.0f;
};

// Tiles of at least this many texture texels on a side: the gutter then
// takes at most 36% of the texture (g = 2) and a spot's edge is drawn over
// several texels, where 4 x 4 tiles padded as they are spend 75% on gutter.
constexpr int kDisplayTileTexels = 16;
// look.scale, or the smallest scale that makes the tiles kDisplayTileTexels
// wide (at most 8).
int displayScale(const Atlas& atlas, const SurfaceLook& look);

// The tiles' (n+1)^2 grids as triangles (two per texel square, split along
// the shorter diagonal and wound with the grid normals), UVs into the padded
// atlas, tangents from the grid positions' differences along u and v, the
// per-cell colours padded as the base colour, and the normal map baked from
// the per-cell height (empty: flat). `colours` and a non-empty `height` hold
// one entry per atlas cell. Throws std::invalid_argument for sizes that do not
// match the atlas.
TexturedMesh texturedSurface(const SurfaceTiles& tiles, const std::vector<float>& height,
                             const std::vector<std::array<std::uint8_t, 4>>& colours,
                             const SurfaceLook& look = {});

// The same from a state's SurfaceColours: its relief scales look.bump, and a
// non-empty wetness gives the mesh its metallic-roughness texture (roughness
// mix(kDryRoughness, kWetRoughness, wetness), padded as the colours). Colours
// mapped at the texture's resolution (SurfaceColours::display, made for the
// same gutter and scale) are used as they are.

struct SurfaceColours;
constexpr float kDryRoughness = 0.7f;
constexpr float kWetRoughness = 0.08f;
TexturedMesh texturedSurface(const SurfaceTiles& tiles, const SurfaceColours& colours,
                             const SurfaceLook& look = {});

// Per atlas cell (zero for unused cells), from the tiles' corner grids: the
// Jacobian's columns (the means of the texel's two edges along u and along
// v, world units per texel) and the orthonormal frame the normal map is in
// (normal: the mean of the corners'; tangent: along u in the tangent plane;
// bitangent: perpendicular to both, on the side of -v (up the image), as the renderer
// rebuilds it from the vertex tangents).
struct TexelFrames {
    std::vector<Eigen::Vector3f> jacobianU, jacobianV, tangent, bitangent, normal;
    std::vector<Eigen::Vector3f> centre; // the mean of the texel's four corners
    float meanTexelLength = 0;           // over every texel edge
};
TexelFrames texelFrames(const SurfaceTiles& tiles);

// The tangent-space normal map of a per-cell height: the normal tilts by
// -relief g, g the height's surface gradient (least squares over each
// texel's four neighbours through the atlas connectivity, in the tangent
// plane) and `relief` the height's world-unit amplitude (Blinn's bump
// mapping, Turk 1991 "Rendering"). The tilts are padded like the colours, so
// a gutter texel holds its neighbour's own tilt, and each is written in its
// tile's frame (the nearest texel's for the gutter) as normalize(tilt.tangent,
// tilt.bitangent, 1): across an edge both tiles hold the same relief. The
// formula texturedSurface uses.
RgbaImage bakeNormalMap(const Atlas& atlas, const DisplayAtlas& display,
                        const std::vector<float>& height, const TexelFrames& frames, float relief);

// Centre and radius of a sphere round every position (the bounding box's
// centre and the farthest position from it).
struct BoundingSphere {
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    float radius = 0;
};
BoundingSphere boundingSphere(const std::vector<Eigen::Vector3f>& positions);

} // namespace morphogen
