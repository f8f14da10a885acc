#include "core/mesh/gltf_output.hpp"

#include <sstream>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/triangle_mesh.hpp"

namespace morphogen::gltf {

namespace {

void padBuffer(tinygltf::Model& model) {
    std::vector<unsigned char>& data = model.buffers[0].data;
    while (data.size() % 4 != 0)
        data.push_back(0);
}

} // namespace

tinygltf::Model newModel() {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "morphogen";
    model.buffers.emplace_back();
    return model;
}

int addView(tinygltf::Model& model, const void* bytes, std::size_t size, int target) {
    padBuffer(model);
    std::vector<unsigned char>& data = model.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    const auto* p = static_cast<const unsigned char*>(bytes);
    data.insert(data.end(), p, p + size);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& model, int view, int componentType, int type, std::size_t count) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.componentType = componentType;
    a.type = type;
    a.count = count;
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
}

int addFloatAttribute(tinygltf::Model& model, tinygltf::Primitive& primitive, const char* name,
                      const void* data, std::size_t elementSize, int type, std::size_t count) {
    const int view = addView(model, data, count * elementSize, TINYGLTF_TARGET_ARRAY_BUFFER);
    const int accessor = addAccessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, count);
    primitive.attributes[name] = accessor;
    return accessor;
}

int addPositions(tinygltf::Model& model, tinygltf::Primitive& primitive,
                 const std::vector<Eigen::Vector3f>& positions) {
    const int accessor =
        addFloatAttribute(model, primitive, "POSITION", positions.data(), sizeof(Eigen::Vector3f),
                          TINYGLTF_TYPE_VEC3, positions.size());
    const Bounds box = boundsOf(positions);
    model.accessors[std::size_t(accessor)].minValues = {box.min.x(), box.min.y(), box.min.z()};
    model.accessors[std::size_t(accessor)].maxValues = {box.max.x(), box.max.y(), box.max.z()};
    return accessor;
}

void writeModel(tinygltf::Model& model, tinygltf::Mesh mesh, tinygltf::Node node,
                const std::string& path) {
    padBuffer(model);
    model.meshes.push_back(std::move(mesh));
    node.mesh = int(model.meshes.size() - 1);
    model.nodes.push_back(std::move(node));
    tinygltf::Scene scene;
    scene.nodes = {int(model.nodes.size() - 1)};
    model.scenes.push_back(scene);
    model.defaultScene = int(model.scenes.size() - 1);

    std::ostringstream bytes;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, bytes, false, true))
        throw InputError(path + ": could not encode the GLB");
    writeFileAtomically(path, bytes.str());
}

MeshMaterial keptMaterial(const tinygltf::Material& material) {
    MeshMaterial kept;
    kept.name = material.name;
    const auto& pbr = material.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
        kept.baseColourAlpha = pbr.baseColorFactor[3];
    kept.metallic = pbr.metallicFactor;
    kept.roughness = pbr.roughnessFactor;
    for (std::size_t k = 0; k < 3 && k < material.emissiveFactor.size(); ++k)
        kept.emissive[k] = material.emissiveFactor[k];
    if (!material.alphaMode.empty())
        kept.alphaMode = material.alphaMode;
    kept.alphaCutoff = material.alphaCutoff;
    kept.doubleSided = material.doubleSided;
    return kept;
}

tinygltf::Material withKept(tinygltf::Material base, const MeshMaterial& kept,
                            bool keepMetallicRoughness) {
    base.name = kept.name;
    base.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, kept.baseColourAlpha};
    if (keepMetallicRoughness) {
        base.pbrMetallicRoughness.metallicFactor = kept.metallic;
        base.pbrMetallicRoughness.roughnessFactor = kept.roughness;
    }
    base.emissiveFactor = {kept.emissive[0], kept.emissive[1], kept.emissive[2]};
    base.alphaMode = kept.alphaMode;
    base.alphaCutoff = kept.alphaCutoff;
    base.doubleSided = kept.doubleSided;
    return base;
}

} // namespace morphogen::gltf
