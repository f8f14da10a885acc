#pragma once
// Repair between loading a mesh and building surface tiles on it. Real
// models are rarely clean 2-manifolds: scans carry duplicate faces, fins
// (edges of three or more triangles), bowtie vertices and specks; exported
// and procedural models carry seams whose copies differ in the last bits.
// Every mesh editor and baker accepts them, so this does too: what can be
// mended is, the surface's shape unchanged (no triangle moves; sheets that
// only touch are cut apart where they touch), and every change is counted.

#include <cstddef>

#include "core/mesh/triangle_mesh.hpp"
#include "core/mesh/wrap_mode.hpp"

namespace morphogen {

// Open-boundary vertices closer than this fraction of the bounding box's
// diagonal are merged by default: as Blender's Merge by Distance, small
// enough to leave real gaps alone; the same distance mesh-info's
// "near seam" check reports.
constexpr double kDefaultMergeDistance = 1e-5;
constexpr double kMaxMergeDistance = 0.01;

// A component whose area is below this fraction of the whole is a speck
// (scan noise, a stray triangle): removed.
constexpr double kSpeckAreaFraction = 1e-4;

struct RepairOptions {
    bool enabled = true;
    double mergeDistance = kDefaultMergeDistance; // of the box diagonal; 0: no merging
    // Wrap the welded mesh (mesh_wrap.hpp) before repairing it: always, never,
    // or when it looks like a soup of pieces (automatic, with the repair on).
    WrapMode wrap = WrapMode::Automatic;
};

// What repairMesh found and changed.
struct RepairStats {
    // Found on the welded mesh before repair (mesh_check's definitions).
    std::size_t nonManifoldEdges = 0;
    std::size_t nonManifoldVertices = 0;
    // Changed.
    std::size_t mergedVertices = 0;     // open-boundary vertices merged into a close one
    std::size_t duplicateTriangles = 0; // removed: the same three vertices as another
    std::size_t collapsedTriangles = 0; // removed: two corners merged into one
    std::size_t splitVertices = 0;      // copies added where sheets met at an edge or a point
    std::size_t specks = 0;             // components removed (area below kSpeckAreaFraction)
    std::size_t speckTriangles = 0;
    bool changed() const {
        return mergedVertices + duplicateTriangles + collapsedTriangles + splitVertices + specks >
               0;
    }
};

// Repairs `mesh` in place (a welded mesh: weldVertices first), in this order:
// open-boundary vertices within the merge distance merged; duplicate and
// collapsed triangles removed; vertices duplicated along fins and at bowtie
// vertices so every edge has at most two triangles and every vertex one fan
// (CGAL's polygon soup repair and orientation); specks removed. The result
// is a manifold (checkMesh(mesh).manifold()). Unused vertices are dropped.
RepairStats repairMesh(TriangleMesh& mesh, const RepairOptions& options);

} // namespace morphogen
