// GLB output of a textured surface through tinygltf; the PNG images are
// encoded here (stb_image_write, which tinygltf itself uses) so they can live
// in buffer views with a MIME type rather than as base64 data URIs.

#include "core/surface/surface_glb.hpp"

#include <cstring>
#include <stdexcept>

#include <stb/stb_image_write.h>
#include <tiny_gltf.h>

#include "core/base/errors.hpp"
#include "core/mesh/gltf_output.hpp"
#include "core/mesh/mesh_io.hpp"

namespace morphogen {

namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* p = static_cast<const unsigned char*>(data);
    out->insert(out->end(), p, p + size);
}

// An image as a PNG in the binary chunk, and a texture using it.
int addPngTexture(tinygltf::Model& model, const RgbaImage& image, const std::string& name) {
    std::vector<unsigned char> png;
    if (image.width < 1 || image.height < 1 ||
        !stbi_write_png_to_func(appendBytes, &png, image.width, image.height, 4,
                                image.texels.data(), image.width * 4))
        throw std::runtime_error("writeTexturedGlb: could not encode the " + name + " PNG");
    tinygltf::Image gltfImage;
    gltfImage.name = name;
    gltfImage.mimeType = "image/png";
    gltfImage.bufferView = gltf::addView(model, png.data(), png.size(), 0);
    model.images.push_back(gltfImage);
    tinygltf::Texture texture;
    texture.name = name;
    texture.sampler = 0;
    texture.source = int(model.images.size() - 1);
    model.textures.push_back(texture);
    return int(model.textures.size() - 1);
}

// The accessor's elements as floats, N per element; InputError unless it is
// N-component float data inside its buffer.
std::vector<float> floats(const tinygltf::Model& model, int index, int type, int n,
                          const std::string& path, const std::string& what) {
    if (index < 0 || std::size_t(index) >= model.accessors.size())
        throw InputError(path + ": no " + what + " accessor");
    const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != type || a.bufferView < 0 ||
        std::size_t(a.bufferView) >= model.bufferViews.size())
        throw InputError(path + ": " + what + " is not float data of " + std::to_string(n) +
                         " components in a buffer view");
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
    const std::size_t stride = view.byteStride ? view.byteStride : sizeof(float) * n;
    const std::vector<unsigned char>& data = model.buffers.at(std::size_t(view.buffer)).data;
    if (a.count > 0 &&
        (view.byteOffset + view.byteLength > data.size() ||
         a.byteOffset + (a.count - 1) * stride + sizeof(float) * n > view.byteLength))
        throw InputError(path + ": " + what + " runs past its buffer");
    std::vector<float> out(a.count * std::size_t(n));
    for (std::size_t i = 0; i < a.count; ++i)
        std::memcpy(&out[i * n], &data[view.byteOffset + a.byteOffset + i * stride],
                    sizeof(float) * n);
    return out;
}

RgbaImage textureImage(const tinygltf::Model& model, int textureIndex, const std::string& path,
                       const std::string& what) {
    if (textureIndex < 0 || std::size_t(textureIndex) >= model.textures.size())
        throw InputError(path + ": the material has no " + what);
    const int source = model.textures[std::size_t(textureIndex)].source;
    if (source < 0 || std::size_t(source) >= model.images.size())
        throw InputError(path + ": the " + what + " has no image");
    const tinygltf::Image& im = model.images[std::size_t(source)];
    if (im.bits != 8 || (im.component != 3 && im.component != 4) ||
        im.image.size() != std::size_t(im.width) * im.height * im.component)
        throw InputError(path + ": the " + what + " is not an 8-bit RGB or RGBA image");
    RgbaImage out;
    out.width = im.width;
    out.height = im.height;
    out.texels.resize(std::size_t(im.width) * im.height);
    for (std::size_t p = 0; p < out.texels.size(); ++p)
        for (int k = 0; k < 4; ++k)
            out.texels[p][std::size_t(k)] =
                k < im.component ? im.image[p * im.component + std::size_t(k)] : 255;
    return out;
}

} // namespace

void writeTexturedGlb(const TexturedMesh& mesh, const std::string& path) {
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n || mesh.tangents.size() != n || mesh.uvs.size() != n)
        throw std::invalid_argument("writeTexturedGlb: every vertex needs a normal, a tangent "
                                    "and a texture coordinate");

    const MeshMaterials& kept = mesh.materials;
    if (!kept.ofTriangle.empty() && kept.ofTriangle.size() != mesh.triangles.size())
        throw std::invalid_argument("writeTexturedGlb: " + std::to_string(kept.ofTriangle.size()) +
                                    " triangle materials for " +
                                    std::to_string(mesh.triangles.size()) + " triangles");

    tinygltf::Model model = gltf::newModel();
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    gltf::addPositions(model, prim, mesh.positions);
    gltf::addFloatAttribute(model, prim, "NORMAL", mesh.normals.data(), sizeof(Eigen::Vector3f),
                            TINYGLTF_TYPE_VEC3, n);
    gltf::addFloatAttribute(model, prim, "TEXCOORD_0", mesh.uvs.data(), sizeof(Eigen::Vector2f),
                            TINYGLTF_TYPE_VEC2, n);
    gltf::addFloatAttribute(model, prim, "TANGENT", mesh.tangents.data(), sizeof(Eigen::Vector4f),
                            TINYGLTF_TYPE_VEC4, n);

    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    model.samplers.push_back(sampler);
    tinygltf::Material material;
    material.name = "pattern";
    material.pbrMetallicRoughness.baseColorTexture.index =
        addPngTexture(model, mesh.baseColour, "base colour");
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.pbrMetallicRoughness.roughnessFactor = kDryRoughness;
    if (mesh.metallicRoughness.width > 0) {
        // The texture holds the roughness itself; glTF multiplies it by the factor.
        material.pbrMetallicRoughness.metallicRoughnessTexture.index =
            addPngTexture(model, mesh.metallicRoughness, "metallic roughness");
        material.pbrMetallicRoughness.roughnessFactor = 1.0;
    }
    material.normalTexture.index = addPngTexture(model, mesh.normalMap, "normal map");
    // Open surfaces show their back.
    material.doubleSided = true;

    // One primitive per material, all on the same vertices and textures:
    // the model's own materials keep what the artist set besides the colour
    // and relief the pattern brings; triangles of none get the exporter's.
    std::vector<std::vector<std::array<std::uint32_t, 3>>> groups(kept.materials.size() + 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::int32_t m = kept.ofTriangle.empty() ? -1 : kept.ofTriangle[t];
        const bool known = m >= 0 && std::size_t(m) < kept.materials.size();
        groups[known ? std::size_t(m) + 1 : 0].push_back(mesh.triangles[t]);
    }
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "surface";
    for (std::size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].empty())
            continue;
        model.materials.push_back(g == 0 ? material
                                         : gltf::withKept(material, kept.materials[g - 1],
                                                          mesh.metallicRoughness.width == 0));
        tinygltf::Primitive part = prim;
        part.material = int(model.materials.size() - 1);
        part.indices = gltf::addAccessor(
            model,
            gltf::addView(model, groups[g].data(), groups[g].size() * sizeof(groups[g][0]),
                          TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 3 * groups[g].size());
        gltfMesh.primitives.push_back(part);
    }
    gltf::writeModel(model, std::move(gltfMesh), tinygltf::Node{}, path);
}

void exportSurfaceGlb(const SurfaceTiles& tiles, const std::vector<float>& height,
                      const std::vector<std::array<std::uint8_t, 4>>& colours,
                      const std::string& path, const SurfaceLook& look) {
    writeTexturedGlb(texturedSurface(tiles, height, colours, look), path);
}

TexturedMesh readTexturedGlb(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    if (!loader.LoadBinaryFromFile(&model, &error, &warning, path))
        throw InputError(path + ": not a readable GLB (" + error + ")");
    if (model.meshes.size() != 1 || model.meshes[0].primitives.empty())
        throw InputError(path + ": expected one mesh");
    const std::vector<tinygltf::Primitive>& prims = model.meshes[0].primitives;
    const tinygltf::Primitive& prim = prims[0];
    for (const tinygltf::Primitive& other : prims)
        if (other.attributes != prim.attributes)
            throw InputError(path + ": the primitives do not share their vertices");
    auto attribute = [&](const char* name) {
        const auto it = prim.attributes.find(name);
        return it == prim.attributes.end() ? -1 : it->second;
    };
    TexturedMesh mesh;
    const std::vector<float> p =
        floats(model, attribute("POSITION"), TINYGLTF_TYPE_VEC3, 3, path, "POSITION");
    const std::vector<float> nrm =
        floats(model, attribute("NORMAL"), TINYGLTF_TYPE_VEC3, 3, path, "NORMAL");
    const std::vector<float> uv =
        floats(model, attribute("TEXCOORD_0"), TINYGLTF_TYPE_VEC2, 2, path, "TEXCOORD_0");
    const std::vector<float> tan =
        floats(model, attribute("TANGENT"), TINYGLTF_TYPE_VEC4, 4, path, "TANGENT");
    const std::size_t n = p.size() / 3;
    if (nrm.size() != 3 * n || uv.size() != 2 * n || tan.size() != 4 * n)
        throw InputError(path + ": the attributes have different vertex counts");
    for (std::size_t i = 0; i < n; ++i) {
        mesh.positions.emplace_back(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
        mesh.normals.emplace_back(nrm[3 * i], nrm[3 * i + 1], nrm[3 * i + 2]);
        mesh.uvs.emplace_back(uv[2 * i], uv[2 * i + 1]);
        mesh.tangents.emplace_back(tan[4 * i], tan[4 * i + 1], tan[4 * i + 2], tan[4 * i + 3]);
    }

    for (const tinygltf::Primitive& part : prims) {
        if (part.indices < 0 || std::size_t(part.indices) >= model.accessors.size())
            throw InputError(path + ": a primitive has no indices");
        const tinygltf::Accessor& ia = model.accessors[std::size_t(part.indices)];
        if (ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || ia.count % 3 != 0 ||
            ia.bufferView < 0 || std::size_t(ia.bufferView) >= model.bufferViews.size())
            throw InputError(path + ": the indices are not uint32 triangles");
        const tinygltf::BufferView& iv = model.bufferViews[std::size_t(ia.bufferView)];
        const std::vector<unsigned char>& data = model.buffers.at(std::size_t(iv.buffer)).data;
        if (iv.byteOffset + ia.byteOffset + ia.count * 4 > data.size() ||
            ia.byteOffset + ia.count * 4 > iv.byteLength)
            throw InputError(path + ": the indices run past their buffer");
        const std::size_t first = mesh.triangles.size();
        mesh.triangles.resize(first + ia.count / 3);
        std::memcpy(mesh.triangles.data() + first, &data[iv.byteOffset + ia.byteOffset],
                    ia.count * 4);
        if (part.material < 0 || std::size_t(part.material) >= model.materials.size())
            throw InputError(path + ": a primitive has no material");
        if (prims.size() > 1) {
            // Several materials: each primitive's, as writeTexturedGlb keeps them.
            mesh.materials.materials.push_back(
                gltf::keptMaterial(model.materials[std::size_t(part.material)]));
            mesh.materials.ofTriangle.resize(mesh.triangles.size(),
                                             std::int32_t(mesh.materials.materials.size() - 1));
        }
    }
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t)
            if (v >= n)
                throw InputError(path + ": vertex index " + std::to_string(v) + " out of range");

    const tinygltf::Material& material = model.materials[std::size_t(prim.material)];
    mesh.baseColour = textureImage(model, material.pbrMetallicRoughness.baseColorTexture.index,
                                   path, "base colour texture");
    mesh.normalMap = textureImage(model, material.normalTexture.index, path, "normal texture");
    if (material.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0)
        mesh.metallicRoughness =
            textureImage(model, material.pbrMetallicRoughness.metallicRoughnessTexture.index, path,
                         "metallic-roughness texture");
    return mesh;
}

} // namespace morphogen
