#pragma once
// Keeping the tiles on the whole model. A simplifier spends its triangle
// budget where the surface bends most and, on a tight budget, cuts off what
// sticks out: an ear's tip, a spout, a finger. The tiles are projected onto
// the full mesh, but only where their points land, so a part the simplified
// mesh lost stays bare (torn ears in the screenshot, no pattern there).

#include <cstddef>
#include <vector>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

struct FollowStats {
    std::size_t insertions = 0; // model vertices put back
    double gapBefore = 0; // the farthest model vertex from the mesh, a fraction of the diagonal
    double gapAfter = 0;
};

// Puts back the model's vertices the simplified `mesh` misses by more than
// `tolerance` (a fraction of `full`'s bounding-box diagonal), farthest first:
// each becomes a vertex of the triangle nearest to it (split in three at the
// nearest point, or its edge split where the nearest point lies on an edge),
// moved to where it is on the model. The nearest point is the foot of the
// perpendicular, so the new triangles rise over the old one and none turns
// over. At most one insertion per triangle a round, up to `rounds` rounds,
// and none that would take the mesh past maxTriangles. Topology unchanged
// (V + 1, E + 3, F + 2 per insertion; + 1, + 2, + 1 on an open boundary).
// `inserted`, when given, gets 1 for each vertex put back (0 for the rest),
// for the smoothing to leave them where they are.
// `candidates`, when given, marks the model's vertices that may be put back
// (those the tiles miss: on a smooth part the simplified mesh's chords stray
// too, but the projection onto the model closes that gap by itself).
FollowStats followModel(TriangleMesh& mesh, const TriangleMesh& full, double tolerance,
                        std::size_t maxTriangles, int rounds = 6,
                        std::vector<char>* inserted = nullptr,
                        const std::vector<char>* candidates = nullptr);

} // namespace morphogen
