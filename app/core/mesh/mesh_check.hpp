#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// One connected piece of the surface (triangles joined through shared vertices).
struct MeshComponent {
    std::size_t vertices = 0;
    std::size_t edges = 0;
    std::size_t triangles = 0;
    std::size_t boundaryLoops = 0;
    long eulerCharacteristic = 0; // V - E + F
    bool manifold = true;         // no non-manifold edge or vertex in it
    bool orientable = true;
    // For an orientable manifold: V - E + F = 2 - 2g - b. -1 when not defined
    // (non-manifold or non-orientable).
    int genus = -1;
    double area = 0;
    Bounds bounds;
};

// How many of one kind of problem, and where the first one is (model units):
// an edge's midpoint, a vertex, a triangle's centroid.
struct MeshDefect {
    std::size_t count = 0;
    Eigen::Vector3f first = Eigen::Vector3f::Zero();
};

struct MeshReport {
    std::size_t vertices = 0;
    std::size_t edges = 0;
    std::size_t triangles = 0;
    Bounds bounds;
    double area = 0;
    std::size_t boundaryEdges = 0; // edges of exactly one triangle (allowed)
    std::size_t boundaryLoops = 0;
    // In file order of their first vertex.
    std::vector<MeshComponent> components;

    // Refused by requireManifold:
    MeshDefect nonManifoldEdges;    // edges of more than two triangles
    MeshDefect nonManifoldVertices; // vertices whose triangles form more than one fan, not
                                    // counting the ends of non-manifold edges
    // Reported, kept:
    // Triangles whose height is below 1e-6 of their longest edge (three distinct
    // vertices on a line or nearly): kept, since removing them would cut the surface
    // open, but a later tiling step cannot give them a tile of any size.
    MeshDefect zeroAreaTriangles;
    // Triangles on the same three vertices as an earlier one.
    MeshDefect duplicateTriangles;
    // Triangles wound against their neighbours (loadMesh has turned them already).
    MeshDefect inconsistentWinding;
    // Boundary vertices within 1e-5 of the box diagonal of another boundary vertex:
    // a seam in the file whose copies differ slightly, so welding (exact) left it open.
    MeshDefect nearSeamVertices;

    bool manifold() const { return nonManifoldEdges.count == 0 && nonManifoldVertices.count == 0; }
    // Some triangle has an area: a mesh of zero-area triangles alone (or of
    // none) has no surface to grow a pattern on.
    bool hasArea() const { return triangles > zeroAreaTriangles.count && area > 0; }
    // What surface tiles need, as mesh-info reports it and render checks it.
    bool usableForTiles() const { return manifold() && hasArea(); }
};

// Analyses a mesh whose indices are in range (any loaded mesh). Never throws for
// a bad surface: every problem is counted in the report.
MeshReport checkMesh(const TriangleMesh& mesh);

// Surface tiles need a manifold: each edge on at most two triangles and each
// vertex's triangles one fan. Throws InputError naming `source`, the counts and
// the first location otherwise. Open boundaries, several components, any genus,
// non-orientable components and zero-area triangles are accepted.
void requireManifold(const MeshReport& report, const std::string& source);

// requireManifold, and a surface with area (report.hasArea()): the one check
// of whether surface tiles can be built, shared by mesh-info and render.
void requireUsableForTiles(const MeshReport& report, const std::string& source);

// Why surface tiles cannot be built on the mesh, one line; "" when they can.
std::string whyNotUsableForTiles(const MeshReport& report);

} // namespace morphogen
