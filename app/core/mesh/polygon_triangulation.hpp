#pragma once
// Splitting a polygon of a mesh file (an OBJ face of four or more corners)
// into triangles that cover it and nothing else. A fan from the first corner
// is right only for convex polygons: on a concave one its triangles overlap
// and stick out of the face. Ear clipping in the polygon's own plane is right
// for any simple polygon.

#include <array>
#include <vector>

#include <Eigen/Core>

namespace morphogen {

// Triangles as indices into `corners` (in order around the polygon), wound
// as the polygon is. A polygon that is not simple (self-intersecting, or
// degenerate in its plane) falls back to the fan from corner 0.
std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Eigen::Vector3f>& corners);

} // namespace morphogen
