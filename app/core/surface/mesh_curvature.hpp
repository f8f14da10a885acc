#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// Per-vertex unit normals: the sum of the adjacent triangles' area vectors
// (so larger triangles count more), normalised; outward for a mesh wound
// counter-clockwise seen from outside. A vertex of no triangle (or whose
// triangles cancel) gets +z.
std::vector<Eigen::Vector3f> areaWeightedVertexNormals(const TriangleMesh& mesh);

// Per-vertex mean curvature (1/length) from the cotangent Laplacian (Meyer et
// al. 2003): Laplace-Beltrami(x)_i = (L x)_i / A_i with L the cotangent
// weights and A_i the vertex's mixed Voronoi area (barycentric parts on obtuse
// triangles). Laplace-Beltrami(x) = -2 H n, so H = |LB(x)| / 2, positive where
// LB(x) points against `normals` (a convex surface bending away from its
// outward normal: a sphere of radius r has 1/r), negative where it points
// along them (a saddle's concave direction dominating). Boundary vertices,
// where the cotangent sum is not a curvature, take the mean of their interior
// neighbours (0 if they have none).
std::vector<float> vertexMeanCurvature(const TriangleMesh& mesh,
                                       const std::vector<Eigen::Vector3f>& normals);

} // namespace morphogen
