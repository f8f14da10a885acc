#pragma once
// The fallback for meshes the repair cannot make into a surface: a soup of
// pieces (every triangle its own vertices, jittered; a model of many loose
// shells) stays thousands of fragments, each tiled on its own, and the
// pattern comes out in shards. CGAL's 3D alpha wrapping (Portaneri et al.
// 2022) shrink-wraps any triangle soup into a closed, oriented 2-manifold
// at a chosen resolution, which tiles as one surface.

#include "core/mesh/triangle_mesh.hpp"
#include "core/mesh/wrap_mode.hpp"
#include <cstddef>
#include <string>

namespace morphogen {

// The wrap's resolution and distance from the input, as fractions of the
// bounding box's diagonal: gaps and cavities narrower than about alpha are
// closed over; the wrap lies `offset` outside the input (0.17%, well inside
// the 1% the tiles may stray from a model).
constexpr double kWrapAlpha = 0.01;
constexpr double kWrapOffset = 1.0 / 600.0;

// A soup: at least kSoupComponents connected pieces, more than half of them
// of at most kSoupFragmentTriangles triangles. A scan's few parts, two far
// spheres or a model with separate eyes are not.
constexpr std::size_t kSoupComponents = 32;
constexpr std::size_t kSoupFragmentTriangles = 4;
bool looksLikeSoup(const TriangleMesh& mesh);
// Connected pieces (triangles joined through shared vertices).
std::size_t meshPieces(const TriangleMesh& mesh);

struct WrapStats {
    bool wrapped = false;
    std::string failed;               // why a wrap asked for could not be made (the mesh then kept)
    std::size_t componentsBefore = 0; // pieces of the repaired mesh
    std::size_t triangles = 0;        // of the wrap
    double alpha = 0, offset = 0;     // model units
};

// The closed wrap of `mesh` at alpha = alphaFraction and offset =
// offsetFraction of its bounding box's diagonal, outward-oriented. Throws
// std::runtime_error for a mesh without a finite extent or a wrap CGAL
// could not make (loadMesh then keeps the mesh and says why).
TriangleMesh alphaWrap(const TriangleMesh& mesh, double alphaFraction = kWrapAlpha,
                       double offsetFraction = kWrapOffset, WrapStats* stats = nullptr);

} // namespace morphogen
