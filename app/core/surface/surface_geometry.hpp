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
// (corners 0..3 at (0,0), (1,0), (1,1), (0,1)), lifted towards the surface by
// Phong tessellation of its simplified triangle (with full's normals at the
// triangle's vertices), then moved onto `full` along the interpolated normal
// (the nearest hit within half the mean simplified edge; the closest point of
// `full` where that line finds none). Not the closest point itself: on a
// piecewise-flat mesh with facets larger than texels it squeezes texels to
// nothing outside every convex crease. A tile whose projected grid still has
// folded or squeezed texels (a simplified triangle spanning a smaller feature)
// has its interior grid points smoothed on the surface, its border kept.
// Normals and mean curvature are those of full's vertices
// (area-weighted normals, cotangent mean curvature: mesh_curvature.hpp)
// interpolated barycentrically at that point. A texel's Jacobian columns are
// the central differences of its four projected corners (the mean of the two
// edges along u, and along v), in world units per texel, and its area is
// |Ju x Jv|. Texel corners on an edge shared by two tiles are the same
// points of the surface on both sides, bit for bit (no cracks). `progress`
// (may be empty) gets the fraction of tiles done, from a worker thread.
void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const std::function<void(double)>& progress = {});
// The same with a projector already built on `full`.
void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const MeshProjector& projector,
                            const std::function<void(double)>& progress = {});

} // namespace morphogen
