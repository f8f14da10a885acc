#pragma once

#include <functional>

#include "core/mesh/triangle_mesh.hpp"
#include "core/surface/mesh_projector.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// Fills the geometry of tiles whose quads and atlas are set (splitIntoTiles):
// gridPositions and gridNormals per texel corner, and per atlas cell
// texelPositions, texelNormals, jacobianU/V, texelArea and meanCurvature, and
// surfaceArea.
//
// A point (s, t) of a tile is first placed bilinearly on its planar quad
// (corners 0..3 at (0,0), (1,0), (1,1), (0,1)), then moved to the closest
// point of `full`. Normals and mean curvature are those of full's vertices
// (area-weighted normals, cotangent mean curvature: mesh_curvature.hpp)
// interpolated barycentrically at that point. A texel's Jacobian columns are
// the central differences of its four projected corners (the mean of the two
// edges along u, and along v), in world units per texel, and its area is
// |Ju x Jv|. Texel corners on an edge shared by two tiles are the same
// points of the surface on both sides. `progress` (may be empty) gets the
// fraction of tiles done.
void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const std::function<void(double)>& progress = {});
// The same with a projector already built on `full`.
void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const MeshProjector& projector,
                            const std::function<void(double)>& progress = {});

} // namespace morphogen
