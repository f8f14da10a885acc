#pragma once

#include <cstddef>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// What simplification did.
struct SimplifyStats {
    std::size_t trianglesBefore = 0;
    std::size_t trianglesAfter = 0;
    std::size_t components = 1;
    int attempts = 0;        // meshoptimizer runs (a run that changed the topology is retried)
    bool simplified = false; // false: the mesh was kept as it is
    // Components where meshoptimizer's runs all changed the topology and
    // CGAL's collapse made the result.
    std::size_t linkConditionComponents = 0;
    // Components kept as they are: neither simplifier kept their topology.
    std::size_t componentsKept = 0;
};

// Simplifies a welded manifold mesh towards `targetTriangles` with
// meshoptimizer's edge collapses (meshopt_simplify, no error bound, borders
// locked so open boundaries keep their shape and place). A mesh already at or
// under the target is returned unchanged. Several connected components are
// simplified one by one, each towards its share of the target by area (at
// least 4 triangles), and concatenated in order of their first triangle. Each
// result must keep the component's topology: manifold, no duplicate
// triangles, and the same boundary loops and Euler characteristic. A run
// that breaks any of this is retried with a 1.5x larger target (up to 6
// runs); then CGAL's topology-keeping collapse (mesh_collapse.hpp) is tried;
// when that too fails the component is kept as it is (the caller sees
// trianglesAfter and may refuse the budget). Unused vertices are dropped; a
// single component's kept vertices keep their order.
TriangleMesh simplifyForTiles(const TriangleMesh& mesh, std::size_t targetTriangles,
                              SimplifyStats* stats = nullptr);

} // namespace morphogen
