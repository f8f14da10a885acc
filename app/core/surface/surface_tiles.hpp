#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/domain/atlas.hpp"
#include "core/mesh/triangle_mesh.hpp"
#include "core/surface/mesh_simplify.hpp"
#include "core/surface/tile_fidelity.hpp"

namespace morphogen {

// How a mesh becomes tiles (Lo et al. section 3 on a mesh of our own).
struct TileOptions {
    int tileSize = 16; // texels per tile side (n)
    int tiles = 0;     // tile budget: 3 tiles per triangle of the simplified mesh; 0 = automatic
};

// A triangle mesh covered by square tiles: every triangle of the simplified
// mesh is split into three quads (corner, edge midpoint, an interior split
// point, edge midpoint), each quad an n x n tile of the atlas. Everything geometric is in
// the mesh's own (world) units.
struct SurfaceTiles {
    TriangleMesh simplified;     // the mesh the tiles were laid on
    SimplifyStats simplifyStats; // how it was simplified (simplifyForTiles)
    FollowStats follow;          // the model's vertices put back (followModel)
    // The quads' corner points: the simplified mesh's vertices, then one point
    // per edge (its midpoint), then one per triangle (its split point).
    std::vector<Eigen::Vector3f> quadVertices;
    // Per simplified triangle: its split point's barycentric coordinates
    // (quadSplitPoint, tile_split.hpp); empty means the centroids.
    std::vector<Eigen::Vector3f> splitBarycentric;
    // Per tile: its corners 0..3 (counter-clockwise in the tile frame, see
    // atlas.hpp) as indices into quadVertices; the input of Atlas::fromQuads.
    std::vector<std::array<int, 4>> quads;
    // Per tile: the simplified triangle it lies in.
    std::vector<std::uint32_t> tileTriangle;
    std::shared_ptr<const Atlas> atlas;

    // Per tile, the (n+1) x (n+1) grid of texel CORNERS (index tile * (n+1)^2 +
    // j * (n+1) + i; i along u = +x, j along v = +y), projected onto the
    // full-resolution mesh: the geometry a renderer draws, texel corner (i, j)
    // having atlas texture coordinate (tile origin + (i, j)) in texels.
    std::vector<Eigen::Vector3f> gridPositions;
    std::vector<Eigen::Vector3f> gridNormals; // unit, outward (the mesh's winding)

    // Per atlas cell (cellCount() entries; zero for unused cells): the texel
    // centre on the full-resolution mesh, the unit normal there, the Jacobian's
    // columns (world units per texel along the tile's u = +x and v = +y), the
    // texel's area on the surface and the mean curvature there (1/radius: a
    // sphere of radius r has 1/r everywhere, the sign positive where the
    // surface bends away from its normal, as on a convex shape).
    std::vector<Eigen::Vector3f> texelPositions;
    std::vector<Eigen::Vector3f> texelNormals;
    std::vector<Eigen::Vector3f> jacobianU, jacobianV;
    std::vector<float> texelArea;
    std::vector<float> meanCurvature;

    double surfaceArea = 0; // of the full-resolution mesh
};

} // namespace morphogen
