#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "core/surface/surface_tiles.hpp"

namespace morphogen::test {

// A "cube sphere": Atlas::cube(n), each face's texel-corner grid and texel
// centres projected onto the sphere of `radius` round the origin, normals
// = positions / radius. Fills atlas, quads, gridPositions, gridNormals,
// texelPositions and texelNormals (what rendering needs), nothing else.
// `rotation` turns the cube before projecting: the same sphere with its tile
// edges elsewhere.
SurfaceTiles cubeSphereTiles(int tileSize, float radius = 1.0f,
                             const Eigen::Matrix3f& rotation = Eigen::Matrix3f::Identity());

// buildSurfaceTiles with this budget and tile size.
SurfaceTiles buildTiles(const TriangleMesh& mesh, int tiles, int tileSize);

// Equilateral triangles of side 1/m in m rows of m, the odd rows shifted by half
// a side: the shape a simplifier aims for. Counter-clockwise seen from +z.
TriangleMesh equilateralSheet(int m);

// A field over the surface as per-cell values (unused cells 0).
std::vector<float> fieldOnTexels(const SurfaceTiles& tiles,
                                 const std::function<float(const Eigen::Vector3f&)>& f);

// One colour for every cell.
std::vector<std::array<std::uint8_t, 4>> constantColours(const SurfaceTiles& tiles,
                                                         std::array<std::uint8_t, 4> colour);

// Per-cell values 0..1 through a simple blue-white-orange ramp.
std::vector<std::array<std::uint8_t, 4>> rampColours(const std::vector<float>& values);

} // namespace morphogen::test
