#pragma once

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// What a 3D scanner's reconstruction looks like: the zero set of a blob (a
// body, a head, two thin ears cut open at the box's top) plus value noise at
// two scales, extracted by marching tetrahedra over `cells` cells per side.
// The rough noise makes small handles (genus > 0), islands of a few dozen
// triangles and open boundaries: cells 60 with noise 0.02 gives about 30k
// triangles of genus 3; cells 110 with 0.03 about 108k triangles in 8 parts.
// Welded (vertices shared along grid edges), manifold, wound outward.
TriangleMesh scanLikeMesh(int cells, double noise);

} // namespace morphogen
