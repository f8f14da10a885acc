#pragma once

#include <cstddef>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// Simplifies a welded, oriented manifold mesh towards `targetTriangles` with
// CGAL's edge collapse (Lindstrom-Turk cost and placement), which collapses an
// edge only where the link condition holds: the result is a manifold of the
// input's topology (components, boundary loops, genus) whatever the input's
// small handles and islands, at some cost in speed against meshoptimizer. It
// stops early where no edge can be collapsed, so a component keeps at least a
// few triangles. Returns the input unchanged when CGAL cannot take it as a
// polygon mesh (not a manifold).
TriangleMesh collapseKeepingTopology(const TriangleMesh& mesh, std::size_t targetTriangles);

} // namespace morphogen
