#pragma once

#include <cstddef>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// What simplification did.
struct SimplifyStats {
    std::size_t trianglesBefore = 0;
    std::size_t trianglesAfter = 0;
    int attempts = 0;        // meshoptimizer runs (a run that changed the topology is retried)
    bool simplified = false; // false: the mesh was kept as it is
};

// Simplifies a welded manifold mesh towards `targetTriangles` with
// meshoptimizer's edge collapses (meshopt_simplify, no error bound, borders
// locked so open boundaries keep their shape and place). A mesh already at or
// under the target is returned unchanged. The result must keep the input's
// topology: manifold, no duplicate triangles, and the same number of
// components, boundary loops and Euler characteristic. A run that breaks any
// of this is retried with a 1.5x larger target (up to 6 runs); when none
// succeeds the input is returned unchanged (the caller sees trianglesAfter
// and may refuse the budget). Unused vertices are dropped; the kept ones
// keep their order.
TriangleMesh simplifyForTiles(const TriangleMesh& mesh, std::size_t targetTriangles,
                              SimplifyStats* stats = nullptr);

} // namespace morphogen
