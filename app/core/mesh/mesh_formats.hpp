#pragma once

#include <cstddef>
#include <string>

#include "core/mesh/mesh_io.hpp"

// The format readers behind readMeshFile. Each checks what its library lets
// through (index ranges, buffer bounds, coordinates it parses as zero) and
// throws InputError naming `path`; readMeshFile checks what is common.
namespace morphogen::mesh_formats {

// Largest vertex or triangle count read (2^26, about 67 million): far past
// any model surface tiles need, and below what 32-bit indices and memory allow.
constexpr std::size_t kMaxMeshElements = std::size_t(1) << 26;

// `uvs`, when given, receives the faces with their texture coordinates (left
// empty when some face, or glTF primitive, has none).
TriangleMesh readObj(const std::string& path, const std::string& text, MeshFileInfo& info,
                     UvMesh* uvs = nullptr);
TriangleMesh readGltf(const std::string& path, bool binary, MeshFileInfo& info,
                      UvMesh* uvs = nullptr);

} // namespace morphogen::mesh_formats
