#pragma once

#include <string>
#include <vector>

#include "core/mesh/mesh_io.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// The sample meshes in models/meshes/, generated (`morphogen mesh-gen`). All
// closed, manifold and wound outward, except the scan (scan_sample.hpp: open
// ears, small handles, islands, as a scanner's mesh); sizes in model units.

// A unit sphere: the icosahedron with every triangle split in four `level`
// times, projected onto the sphere (20 * 4^level triangles).
TriangleMesh icosphere(int level);

// A torus around the z axis, tube centre radius 1 and tube radius 0.4, of
// `ring` x `ring / 2` quads split into triangles (genus 1).
TriangleMesh torus(int ring);

// The same torus as an exporter writes it: the vertices on the u = 1 and v = 1
// seams copied (positions bit for bit, texture coordinates 1 instead of 0), with
// normals and texture coordinates; (ring + 1) x (ring / 2 + 1) vertices.
TriangleMesh torusWithSeams(int ring, MeshAttributes& attributes);

// A rounded slab with three holes in a row (genus 3, like Lo et al.'s HOLES3):
// a 7 x 3 x 1.2 box cage with three unit holes, smoothed by `levels` rounds of
// Catmull-Clark subdivision (68 * 4^levels quads, two triangles each).
TriangleMesh holes(int levels);

// An organic shape: an icosphere whose radius swells into a head, a tail and
// four legs, with a slight ripple, stretched into a body (a star-shaped
// surface, so it cannot cross itself; genus 0).
TriangleMesh blob(int level);

// The kinds `morphogen mesh-gen` accepts and their default detail.
struct SampleKind {
    const char* name;
    int detail;          // level, ring segments or subdivision rounds
    const char* meaning; // what detail means
};
const std::vector<SampleKind>& sampleKinds();

// Generates kind `name` at `detail` (<= 0: its default). Throws InputError for
// an unknown kind or a detail past its limit (about 2 million triangles).
TriangleMesh sampleMesh(const std::string& name, int detail);

} // namespace morphogen
