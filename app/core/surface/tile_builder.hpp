#pragma once

#include <functional>
#include <string>

#include "core/mesh/triangle_mesh.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// The automatic tile budget (TileOptions::tiles == 0): about 2,000 tiles, so
// an ordinary model gets some 700 triangles after simplification, lowered if
// the limits (core/base/limits.hpp) or the 65536-texel atlas side allow fewer
// tiles of this size.
int automaticTileBudget(int tileSize);

// Throws InputError naming --tile-size or --tiles and the accepted range:
// tileSize kMinSurfaceTileSize..kMaxSurfaceTileSize; tiles 0 (automatic) or
// kMinSurfaceTiles..kMaxSurfaceTiles, and tiles x tileSize^2 at most
// kMaxSurfaceTexels.
void checkTileOptions(const TileOptions& options);

// Called between the phases of buildSurfaceTiles ("simplify", "tiles" and
// "projection", which also computes normals and curvature) with the fraction
// of that phase done (0..1).
using TileProgress = std::function<void(const std::string& phase, double fraction)>;

// From a welded manifold mesh (loadMesh's output; open boundaries, several
// components and any genus accepted) to tiles with their geometry:
//  1. simplify to tiles / 3 triangles (simplifyForTiles; a mesh under budget
//     is kept as it is), then, if it was simplified, even out its triangles'
//     sizes and shapes on the full mesh, keeping its topology: split its long
//     edges (splitLongEdges: over 4/3 of the budget's equilateral edge; the
//     simplification is redone to that many fewer triangles first, so the
//     budget holds), then edge flips and area-evening tangential smoothing
//     (improveForTiles). The explicit step is limited by the smallest texels,
//     and a simplifier leaves flat regions in long, thin triangles and curved
//     ones in small ones,
//  2. split each triangle (a, b, c) into the quads (a, m_ab, g, m_ca),
//     (b, m_bc, g, m_ab), (c, m_ca, g, m_bc) (m: edge midpoints, g: the
//     split point, the centroid unless the triangle is badly shaped:
//     quadSplitPoint), which run round in the triangle's own sense, so tiles of
//     neighbouring triangles are glued properly (not mirrored) on an
//     orientable mesh; tile 3t + k is corner k of triangle t,
//  3. glue them into an atlas (Atlas::fromQuads),
//  4. per texel corner and texel centre: the point bilinear on the planar quad
//     projected onto `full` (its closest point), the interpolated normal and
//     mean curvature, and per texel the Jacobian and area (surface_geometry).
// Throws InputError for bad options (checkTileOptions), a non-manifold mesh
// (requireManifold, naming `source`), or when the simplified mesh's tiles pass
// the limits (naming --tiles).
SurfaceTiles buildSurfaceTiles(const TriangleMesh& full, const TileOptions& options,
                               const TileProgress& progress = {},
                               const std::string& source = "mesh");

// Steps 2 and 3 alone, on a mesh used as it is: quadVertices (planar), quads,
// tileTriangle and the atlas; no geometry.
SurfaceTiles splitIntoTiles(const TriangleMesh& mesh, int tileSize);

} // namespace morphogen
