#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/mesh/mesh_material.hpp"
#include "core/mesh/mesh_repair.hpp"
#include "core/mesh/mesh_wrap.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// What a mesh file held, as read (before welding).
struct MeshFileInfo {
    std::string path;
    std::string format; // "OBJ", "glTF" or "GLB"
    // Vertices and triangles as stored, summed over the parts read. A glTF mesh
    // that several nodes use is counted once per node; polygons, strips and fans
    // count as the triangles they split into.
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    // OBJ: shapes (o/g groups); glTF: triangle primitives placed by the scene's nodes.
    std::size_t parts = 0;
    // glTF primitives of points or lines, and OBJ lines and points: not surfaces.
    std::size_t skippedParts = 0;
    std::vector<std::string> warnings;
};

struct LoadedMesh {
    TriangleMesh mesh;
    MeshFileInfo file;
    WeldStats weld;
    WrapStats wrap;             // whether the welded mesh was replaced by its alpha wrap
    RepairStats repair;         // what repairMesh changed (nothing with repair off)
    std::size_t reoriented = 0; // triangles turned to agree with their neighbours
};

// Reads an OBJ (.obj), glTF (.gltf) or GLB (.glb) file into one triangle soup:
// every OBJ shape; every triangle primitive (triangles, strips, fans) of the
// glTF default scene (or its first scene) with the node transforms applied, a
// mirroring transform reversing the winding so it stays outward. Polygons are
// split by ear clipping in their plane (polygon_triangulation.hpp), right for
// concave ones too. Throws InputError naming the file and the reason for a
// missing or unreadable file, a folder, an unknown extension, a truncated or
// malformed file, an index out of range, a NaN or infinite coordinate, or no
// triangles at all.
TriangleMesh readMeshFile(const std::string& path, MeshFileInfo* info = nullptr);

// readMeshFile, then weldVertices, the alpha wrap where `repair.wrap` asks
// for it (mesh_wrap.hpp), repairMesh (mesh_repair.hpp) and
// orientConsistently: what surface tiles are built on. Throws InputError also
// when every triangle collapses when welded or is removed by the repair.
LoadedMesh loadMesh(const std::string& path, const RepairOptions& repair = {});

// The model as its file lays it out in texture space: one vertex per
// distinct (position, texture coordinate) pair, triangles as the file's faces
// split (the same triangles readMeshFile reads, in the same coordinates).
struct UvMesh {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector2f> uvs; // glTF's convention: v = 0 is the image's top row
    std::vector<std::array<std::uint32_t, 3>> triangles;
    MeshMaterials materials; // a glTF's; none for an OBJ
};

// The file's first texture coordinates, for baking into them: an OBJ whose
// every face has them ("vt", flipped to glTF's v down), a glTF whose every
// primitive has TEXCOORD_0 (node transforms applied to the positions, as
// readMeshFile does; with the glTF's materials). Nothing for a file without them everywhere. Throws
// InputError as readMeshFile does.
std::optional<UvMesh> readUvMesh(const std::string& path);

// Extra vertex data for writeGlb, one entry per position when not empty.
struct MeshAttributes {
    std::vector<Eigen::Vector3f> normals;
    std::vector<Eigen::Vector2f> texcoords;
};

// Writes an OBJ file (positions, triangles, `comment` lines as # comments).
// Atomic: a temporary file renamed into place. Throws InputError if the
// folder cannot be written.
void writeObj(const TriangleMesh& mesh, const std::string& path,
              const std::vector<std::string>& comment = {});

// Writes a binary glTF (GLB) with one mesh of one triangle primitive (uint32
// indices, float positions and the given attributes) placed by one node with
// the rotation (unit quaternion x, y, z, w) and uniform scale given. Atomic.
void writeGlb(const TriangleMesh& mesh, const MeshAttributes& attributes, const std::string& path,
              const Eigen::Vector4d& rotation = {0, 0, 0, 1}, double scale = 1.0);

// Writes `bytes` to `path` through a temporary file renamed into place, so a
// failed write leaves nothing behind. Throws InputError naming the path.
void writeFileAtomically(const std::string& path, const std::string& bytes);

} // namespace morphogen
