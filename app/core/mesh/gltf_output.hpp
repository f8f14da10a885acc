#pragma once
// Building blocks of the GLB files the program writes (writeGlb, the textured
// surface export): one buffer, 4-byte aligned views, and an atomic write.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <tiny_gltf.h>

#include "core/mesh/mesh_material.hpp"

namespace morphogen::gltf {

// A glTF 2.0 model with one empty buffer, "morphogen" as its generator.
tinygltf::Model newModel();

// Appends `bytes` to buffer 0 (4-byte aligned) and returns its view.
int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target);

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count);

// A float vertex attribute of `count` elements (its own view), set on `primitive`.
int addFloatAttribute(tinygltf::Model& model, tinygltf::Primitive& primitive, const char* name,
                      const void* data, std::size_t elementSize, int type, std::size_t count);

// POSITION with the min and max the specification requires.
int addPositions(tinygltf::Model& model, tinygltf::Primitive& primitive,
                 const std::vector<Eigen::Vector3f>& positions);

// A material as the UV bake keeps it (mesh_material.hpp), and back: the
// glTF material with the pattern's colour (its factor white, the alpha kept)
// and the rest as the artist set it, over `base` (the exporter's textures).
MeshMaterial keptMaterial(const tinygltf::Material& material);
tinygltf::Material withKept(tinygltf::Material base, const MeshMaterial& kept,
                            bool keepMetallicRoughness);

// `mesh` placed by `node` (its mesh set to it) in the one scene, encoded as
// GLB and written to `path` atomically. Throws InputError naming the path.
void writeModel(tinygltf::Model& model, tinygltf::Mesh mesh, tinygltf::Node node,
                const std::string& path);

} // namespace morphogen::gltf
