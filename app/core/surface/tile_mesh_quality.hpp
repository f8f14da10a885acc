#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh/triangle_mesh.hpp"
#include "core/surface/mesh_projector.hpp"

namespace morphogen {

struct MeshQualityStats {
    std::size_t flips = 0;     // edges flipped
    std::size_t moves = 0;     // vertex moves accepted
    double minAngleBefore = 0; // smallest triangle angle, degrees
    double minAngleAfter = 0;
};

// Makes a simplified mesh's triangles better tiles without changing its
// topology: a simplifier keeps error low, not shapes good, and leaves slivers
// (angles under 1 degree) whose tiles get texels of almost no area (a huge
// diffusion coefficient, so a tiny stable time step) and, where a sliver lies
// across a curved region, folded texels. `rounds` times:
//  - flip each interior edge whose flip raises the smaller minimum angle of its
//    two triangles, if the two are nearly coplanar (normals within 30 degrees),
//    the new edge does not exist yet, the new triangles face the same way, and
//    neither end of the edge drops below 4 triangles;
//  - move each interior vertex towards the area-weighted mean of its
//    triangles' centroids within its tangent plane, then onto the full-resolution mesh (`full`), if
//    the worst shape of its triangles stays at least what it was or 0.5, whichever is less (shape:
//    4 sqrt(3) area / sum of squared edges, signed by the vertex normal; 1 equilateral, <= 0
//    folded), so folds and slivers only improve while sizes even out.
// 8 rounds: measured with `morphogen tile-stats` (max / median texel weight sum
// at 4x4 and 16x16 tiles, after splitLongEdges), 4 rounds leave the torus at
// 8-9 (its triangles' areas 0.2 to 2.4 times the median), 6 to 14 rounds bring
// it to 4.5 and the holes model from 6-8 to 5.5-7; 8 was best overall, and the
// area-weighted smoothing needs them for the angles too (11.4 degrees at the
// worst after 4 rounds on a simplified holes model, 12+ after 8).
// Vertices of open boundaries stay where they are; `pins` keep some others
// near a point (followModel's: a tip put back may even out its triangles but
// not slide off the tip). Changes V, E and F not at all, so the components,
// boundaries and genus are those of the input.
struct VertexPins {
    std::vector<char> pinned;        // per vertex (shorter: the rest are free)
    std::vector<Eigen::Vector3f> at; // per pinned vertex, where it must stay near
    float reach = 0;
};
MeshQualityStats improveForTiles(TriangleMesh& mesh, const MeshProjector& full, int rounds = 8,
                                 const VertexPins* pins = nullptr);

// Splits every edge longer than maxLength at its midpoint (projected onto
// `full`), longest first, until none is left or the next split would take
// the mesh past maxTriangles; returns the splits. A simplifier spends its
// budget where the surface bends and leaves flat regions in a few long, thin
// triangles (a fan across a flat face), whose tiles get texels many times
// longer than they are wide; split, then flipped and smoothed
// (improveForTiles), they become triangles of about the others' size.
// Changes V, E and F by +1, +3, +2 per split (+1, +2, +1 on an open boundary):
// the Euler characteristic, components and boundary loops stay.
std::size_t splitLongEdges(TriangleMesh& mesh, const MeshProjector& full, double maxLength,
                           std::size_t maxTriangles);

// The edge of an equilateral triangle of the mean area if `mesh`'s area were
// shared by `triangles` of them.
double tileEdgeLength(const TriangleMesh& mesh, std::size_t triangles);

// The smallest angle of any triangle, in degrees (180 for no triangles).
double minimumAngle(const TriangleMesh& mesh);

} // namespace morphogen
