#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace morphogen {

// A triangle soup or surface: positions and triangles as indices into them.
// Loaded meshes (mesh_io.hpp) come welded (one vertex per distinct position),
// without collapsed triangles or unreferenced vertices, and with the triangles
// of each orientable component wound consistently.
struct TriangleMesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct Bounds {
    Eigen::Vector3f min = Eigen::Vector3f::Zero();
    Eigen::Vector3f max = Eigen::Vector3f::Zero();
    float diagonal() const { return (max - min).norm(); }
};

// The box around the referenced and unreferenced positions alike (zero for no
// positions).
Bounds boundsOf(const std::vector<Eigen::Vector3f>& positions);

// Twice the area of triangle t, as a vector along its normal (right-handed
// with the winding), in double precision.
Eigen::Vector3d doubleAreaVector(const TriangleMesh& mesh, std::size_t t);
double triangleArea(const TriangleMesh& mesh, std::size_t t);
double surfaceArea(const TriangleMesh& mesh);

// The triangles of each piece joined through shared vertices (a union-find
// over the vertices), in the order of each piece's first triangle.
std::vector<std::vector<std::uint32_t>> componentTriangles(const TriangleMesh& mesh);

// What welding changed (weldVertices).
struct WeldStats {
    std::size_t verticesBefore = 0;
    std::size_t verticesAfter = 0;       // distinct referenced positions
    std::size_t unreferencedDropped = 0; // vertices no triangle used
    std::size_t collapsedRemoved = 0;    // triangles with a repeated vertex after welding
};

// Merges vertices whose positions are bit-for-bit equal (after -0 becomes +0),
// drops vertices no triangle uses and removes triangles that then repeat a
// vertex. Exact, not within a tolerance: files duplicate a vertex at a UV or
// normal seam by copying its position, so the copies are equal; merging points
// that are merely close could glue distinct sheets together and make the mesh
// non-manifold. The merged vertices keep the order of their first copies, so
// a mesh without duplicates keeps its numbering. The indices must be in range
// (the readers check them).
WeldStats weldVertices(TriangleMesh& mesh);

// Winds every triangle of a component like its neighbours across the edges
// that join exactly two triangles (a breadth-first walk from each component's
// first triangle), then reverses the whole component if that flipped more than
// half of it, so the file's own majority winding wins. Returns how many
// triangles end up reversed. A non-orientable component (a Moebius strip)
// keeps the winding the walk gave it; mesh_check reports it.
std::size_t orientConsistently(TriangleMesh& mesh);

} // namespace morphogen
