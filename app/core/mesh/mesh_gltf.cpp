// glTF 2.0 input and GLB output through tinygltf. tinygltf parses the JSON and
// the buffers; the accessor bounds, index ranges and node graph are checked
// here, since a broken file must be refused, not read out of bounds.

#include <cmath>
#include <cstdio>
#include <cstring>

#include <Eigen/Geometry>
#include <tiny_gltf.h>

#include "core/mesh/gltf_output.hpp"

#include "core/base/errors.hpp"
#include "core/mesh/mesh_formats.hpp"

namespace morphogen::mesh_formats {

namespace {

using Matrix4 = Eigen::Matrix4d;

// Only geometry matters: images are not decoded (nor their failures reported).
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '.'))
        text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
        text.replace(at, 1, "; ");
    return text;
}

std::size_t componentSize(int type) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

// One component as a double; `normalized` maps integers to [-1, 1] or [0, 1]
// as the specification says (KHR_mesh_quantization stores positions so).
double component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const double v = double(*reinterpret_cast<const std::int8_t*>(p));
        return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? double(*p) / 255.0 : double(*p);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? double(v) / 65535.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    default: {
        float v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    }
}

class Reader {
public:
    Reader(const std::string& path, const tinygltf::Model& model) : m_path(path), m_model(model) {}

    // `components` values per element (3 for VEC3, 1 for SCALAR), checked
    // against the accessor's type; every byte read is inside its buffer.
    std::vector<double> accessor(int index, int type, const std::string& what) const {
        const auto& accessors = m_model.accessors;
        if (index < 0 || std::size_t(index) >= accessors.size())
            fail(what + " uses accessor " + std::to_string(index) + ", but the file has " +
                 std::to_string(accessors.size()));
        const tinygltf::Accessor& a = accessors[std::size_t(index)];
        const std::string name = what + " (accessor " + std::to_string(index) + ")";
        const int components = type == TINYGLTF_TYPE_VEC3 ? 3 : type == TINYGLTF_TYPE_VEC2 ? 2 : 1;
        if (a.type != type)
            fail(name + " has the wrong type: want " +
                 (components == 3   ? std::string("VEC3")
                  : components == 2 ? std::string("VEC2")
                                    : std::string("SCALAR")));
        const std::size_t size = componentSize(a.componentType);
        if (size == 0 ||
            (components > 1 && a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
            fail(name + " has an unsupported component type " + std::to_string(a.componentType));
        if (a.sparse.isSparse)
            fail(name + " is sparse, which is not supported");
        if (a.count > kMaxMeshElements)
            fail(name + " has " + std::to_string(a.count) + " elements, more than the " +
                 std::to_string(kMaxMeshElements) + " accepted");
        if (a.count == 0 ||
            a.bufferView < 0) // no buffer view: all zeros, as the specification says
            return std::vector<double>(a.count * std::size_t(components), 0.0);

        const auto& views = m_model.bufferViews;
        if (std::size_t(a.bufferView) >= views.size())
            fail(name + " uses buffer view " + std::to_string(a.bufferView) +
                 ", but the file has " + std::to_string(views.size()));
        const tinygltf::BufferView& view = views[std::size_t(a.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= m_model.buffers.size())
            fail("buffer view " + std::to_string(a.bufferView) + " uses buffer " +
                 std::to_string(view.buffer) + ", but the file has " +
                 std::to_string(m_model.buffers.size()));
        const std::vector<unsigned char>& data = m_model.buffers[std::size_t(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail("buffer view " + std::to_string(a.bufferView) + " (" +
                 std::to_string(view.byteLength) + " bytes at " + std::to_string(view.byteOffset) +
                 ") runs past the end of its buffer (" + std::to_string(data.size()) +
                 " bytes): a truncated file?");
        const std::size_t element = size * std::size_t(components);
        const std::size_t stride = view.byteStride > 0 ? view.byteStride : element;
        if (stride < element)
            fail("buffer view " + std::to_string(a.bufferView) + " has a byte stride of " +
                 std::to_string(stride) + ", less than the " + std::to_string(element) +
                 " bytes of one element of " + name);
        // count <= byteLength keeps the product below from overflowing.
        if (a.count > view.byteLength || a.byteOffset > view.byteLength ||
            stride * (a.count - 1) + element > view.byteLength - a.byteOffset)
            fail(name + " (" + std::to_string(a.count) + " elements at byte " +
                 std::to_string(a.byteOffset) + ") runs past the end of buffer view " +
                 std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
        std::vector<double> values(a.count * std::size_t(components));
        const unsigned char* base = data.data() + view.byteOffset + a.byteOffset;
        for (std::size_t i = 0; i < a.count; ++i)
            for (int k = 0; k < components; ++k)
                values[i * components + std::size_t(k)] = component(
                    base + i * stride + std::size_t(k) * size, a.componentType, a.normalized);
        return values;
    }

    [[noreturn]] void fail(const std::string& why) const { throw InputError(m_path + ": " + why); }

private:
    const std::string& m_path;
    const tinygltf::Model& m_model;
};

Matrix4 localTransform(const tinygltf::Node& node) {
    Matrix4 m = Matrix4::Identity();
    if (node.matrix.size() == 16) {
        for (int i = 0; i < 16; ++i)
            m(i % 4, i / 4) = node.matrix[std::size_t(i)]; // column-major
        return m;
    }
    Eigen::Affine3d a = Eigen::Affine3d::Identity();
    if (node.translation.size() == 3)
        a.translate(Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        a.rotate(Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1],
                                    node.rotation[2])
                     .normalized());
    if (node.scale.size() == 3)
        a.scale(Eigen::Vector3d(node.scale[0], node.scale[1], node.scale[2]));
    return a.matrix();
}

// Adds one primitive's triangles to `out`. With `texcoords`: its vertices'
// TEXCOORD_0 appended in step with out.positions, or `texcoords` set to null
// when it has none (the model then has no complete UV layout).
void addPrimitive(const Reader& reader, const tinygltf::Model& model, int meshIndex,
                  std::size_t primitiveIndex, const Matrix4& transform, TriangleMesh& out,
                  MeshFileInfo& info, std::vector<Eigen::Vector2f>*& texcoords) {
    const tinygltf::Primitive& prim =
        model.meshes[std::size_t(meshIndex)].primitives[primitiveIndex];
    const std::string what =
        "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(primitiveIndex);
    const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ++info.skippedParts; // points and lines are not a surface
        return;
    }
    const auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end())
        reader.fail(what + " has no POSITION attribute");
    const std::vector<double> xyz =
        reader.accessor(position->second, TINYGLTF_TYPE_VEC3, what + "'s POSITION");
    const std::size_t count = xyz.size() / 3;
    for (std::size_t i = 0; i < count; ++i)
        if (!std::isfinite(float(xyz[3 * i])) || !std::isfinite(float(xyz[3 * i + 1])) ||
            !std::isfinite(float(xyz[3 * i + 2]))) {
            char at[96];
            std::snprintf(at, sizeof at, "(%g, %g, %g)", xyz[3 * i], xyz[3 * i + 1],
                          xyz[3 * i + 2]);
            reader.fail(what + ": POSITION " + std::to_string(i) + " is " + at +
                        ": coordinates must be finite numbers (no NaN or infinity)");
        }

    std::vector<std::uint32_t> indices;
    if (prim.indices >= 0) {
        const std::vector<double> raw =
            reader.accessor(prim.indices, TINYGLTF_TYPE_SCALAR, what + "'s indices");
        indices.reserve(raw.size());
        for (std::size_t i = 0; i < raw.size(); ++i) {
            // Signed or float index accessors (invalid glTF, which tinygltf
            // reads all the same) can hold negative values and NaN: refused
            // here, and printed as the double they are, since converting them
            // to an unsigned integer is undefined behaviour.
            if (!(raw[i] >= 0 && raw[i] < double(count))) {
                char value[32];
                std::snprintf(value, sizeof value, "%.17g", raw[i]);
                reader.fail(what + ": index " + std::to_string(i) + " is " + value +
                            ", but there are " + std::to_string(count) + " vertices");
            }
            indices.push_back(std::uint32_t(raw[i]));
        }
    } else {
        for (std::size_t i = 0; i < count; ++i)
            indices.push_back(std::uint32_t(i));
    }

    // Nodes may place one mesh many times: cap what they add up to.
    if (out.positions.size() + count > kMaxMeshElements ||
        out.triangles.size() + indices.size() > kMaxMeshElements)
        reader.fail("the scene places more than " + std::to_string(kMaxMeshElements) +
                    " vertices or triangles, more than accepted (simplify the model first)");
    if (texcoords) {
        const auto uv = prim.attributes.find("TEXCOORD_0");
        if (uv == prim.attributes.end()) {
            texcoords = nullptr;
        } else {
            const std::vector<double> st =
                reader.accessor(uv->second, TINYGLTF_TYPE_VEC2, what + "'s TEXCOORD_0");
            if (st.size() != 2 * count)
                reader.fail(what + "'s TEXCOORD_0 has " + std::to_string(st.size() / 2) +
                            " elements for " + std::to_string(count) + " vertices");
            for (std::size_t i = 0; i < count; ++i)
                texcoords->emplace_back(float(st[2 * i]), float(st[2 * i + 1]));
        }
    }
    const std::uint32_t base = std::uint32_t(out.positions.size());
    for (std::size_t i = 0; i < count; ++i) {
        const Eigen::Vector4d p =
            transform * Eigen::Vector4d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], 1.0);
        out.positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    }
    // A mirroring transform turns the surface inside out: swap the winding back.
    const bool mirrored = transform.topLeftCorner<3, 3>().determinant() < 0;
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (mirrored)
            std::swap(b, c);
        out.triangles.push_back({base + a, base + b, base + c});
    };
    const std::size_t before = out.triangles.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
            add(indices[i], indices[i + 1], indices[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
            if (i % 2 == 0)
                add(indices[i], indices[i + 1], indices[i + 2]);
            else
                add(indices[i + 1], indices[i], indices[i + 2]);
        }
    } else {
        for (std::size_t i = 1; i + 1 < indices.size(); ++i)
            add(indices[0], indices[i], indices[i + 1]);
    }
    info.vertices += count;
    info.triangles += out.triangles.size() - before;
    ++info.parts;
}

} // namespace

TriangleMesh readGltf(const std::string& path, bool binary, MeshFileInfo& info, UvMesh* uvs) {
    info.format = binary ? "GLB" : "glTF";
    tinygltf::Model model;
    std::string err, warn;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                    : loader.LoadASCIIFromFile(&model, &err, &warn, path);
    } catch (const std::exception& e) {
        err = e.what();
    }
    if (!ok)
        throw InputError(path + ": not a readable " + info.format +
                         " file: " + (err.empty() ? std::string("unknown error") : oneLine(err)));
    for (const std::string& extension : model.extensionsRequired)
        if (extension == "KHR_draco_mesh_compression" || extension == "EXT_meshopt_compression")
            throw InputError(path + ": needs the extension " + extension +
                             " (compressed geometry), which is not supported; export it "
                             "without compression");

    const Reader reader(path, model);
    TriangleMesh mesh;
    std::vector<Eigen::Vector2f> texcoordValues;
    std::vector<Eigen::Vector2f>* texcoords = uvs ? &texcoordValues : nullptr;
    // Each triangle's material, for the bake into the model's UVs.
    std::vector<std::int32_t> triangleMaterial;
    const auto add = [&](int meshIndex, std::size_t p, const Matrix4& transform) {
        addPrimitive(reader, model, meshIndex, p, transform, mesh, info, texcoords);
        const int material = model.meshes[std::size_t(meshIndex)].primitives[p].material;
        const bool known = material >= 0 && std::size_t(material) < model.materials.size();
        triangleMaterial.resize(mesh.triangles.size(), known ? material : -1);
    };
    const std::size_t nodeCount = model.nodes.size();
    // Nodes form trees (glTF forbids a node two parents): a node reached twice
    // is a cycle or a shared child, refused before it could multiply the work.
    // Depth-first with an explicit stack, so a deep chain cannot overflow it.
    std::vector<std::uint8_t> reached(nodeCount, 0);
    auto visit = [&](int root) {
        std::vector<std::pair<int, Matrix4>> stack = {{root, Matrix4::Identity()}};
        while (!stack.empty()) {
            const auto [n, parent] = stack.back();
            stack.pop_back();
            if (n < 0 || std::size_t(n) >= nodeCount)
                reader.fail("node " + std::to_string(n) + " is named, but the file has " +
                            std::to_string(nodeCount) + " nodes");
            if (reached[std::size_t(n)]++)
                reader.fail("node " + std::to_string(n) +
                            " is reached twice (a cycle, or a node with two parents): glTF "
                            "nodes must form trees");
            const tinygltf::Node& node = model.nodes[std::size_t(n)];
            const Matrix4 transform = parent * localTransform(node);
            if (node.mesh >= 0) {
                if (std::size_t(node.mesh) >= model.meshes.size())
                    reader.fail("node " + std::to_string(n) + " uses mesh " +
                                std::to_string(node.mesh) + ", but the file has " +
                                std::to_string(model.meshes.size()));
                for (std::size_t p = 0; p < model.meshes[std::size_t(node.mesh)].primitives.size();
                     ++p)
                    add(node.mesh, p, transform);
            }
            // Reversed, so children come out of the stack in file order.
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
                stack.emplace_back(*child, transform);
        }
    };

    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene
                           : model.scenes.empty()  ? -1
                                                   : 0;
    if (sceneIndex >= int(model.scenes.size()))
        reader.fail("the default scene is " + std::to_string(sceneIndex) + ", but the file has " +
                    std::to_string(model.scenes.size()));
    if (sceneIndex >= 0) {
        for (int root : model.scenes[std::size_t(sceneIndex)].nodes)
            visit(root);
    } else if (nodeCount > 0) {
        // No scene: every node that is no other's child is a root.
        std::vector<std::uint8_t> isChild(nodeCount, 0);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children)
                if (child >= 0 && std::size_t(child) < nodeCount)
                    isChild[std::size_t(child)] = 1;
        for (std::size_t n = 0; n < nodeCount; ++n)
            if (!isChild[n])
                visit(int(n));
    } else {
        // No scene and no nodes: the meshes as they are.
        for (std::size_t m = 0; m < model.meshes.size(); ++m)
            for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p)
                add(int(m), p, Matrix4::Identity());
    }
    // Every primitive had its texture coordinates: glTF's vertices are
    // already one per (position, texture coordinate), and its v runs down.
    if (texcoords && texcoordValues.size() == mesh.positions.size() && !mesh.triangles.empty()) {
        uvs->positions = mesh.positions;
        uvs->uvs = std::move(texcoordValues);
        uvs->triangles = mesh.triangles;
        if (!model.materials.empty()) {
            for (const tinygltf::Material& m : model.materials)
                uvs->materials.materials.push_back(gltf::keptMaterial(m));
            uvs->materials.ofTriangle = std::move(triangleMaterial);
        }
    }
    return mesh;
}

} // namespace morphogen::mesh_formats

namespace morphogen {

void writeGlb(const TriangleMesh& mesh, const MeshAttributes& attributes, const std::string& path,
              const Eigen::Vector4d& rotation, double scale) {
    const std::size_t n = mesh.positions.size();
    if (!attributes.normals.empty() && attributes.normals.size() != n)
        throw std::invalid_argument("writeGlb: one normal per position");
    if (!attributes.texcoords.empty() && attributes.texcoords.size() != n)
        throw std::invalid_argument("writeGlb: one texture coordinate per position");

    tinygltf::Model model = gltf::newModel();
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    const int indexView = gltf::addView(model, mesh.triangles.data(),
                                        mesh.triangles.size() * sizeof(mesh.triangles[0]),
                                        TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    prim.indices = gltf::addAccessor(model, indexView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                     TINYGLTF_TYPE_SCALAR, 3 * mesh.triangles.size());
    gltf::addPositions(model, prim, mesh.positions);
    if (!attributes.normals.empty())
        gltf::addFloatAttribute(model, prim, "NORMAL", attributes.normals.data(),
                                sizeof(Eigen::Vector3f), TINYGLTF_TYPE_VEC3, n);
    if (!attributes.texcoords.empty())
        gltf::addFloatAttribute(model, prim, "TEXCOORD_0", attributes.texcoords.data(),
                                sizeof(Eigen::Vector2f), TINYGLTF_TYPE_VEC2, n);

    tinygltf::Mesh m;
    m.primitives.push_back(prim);
    tinygltf::Node node;
    if (rotation != Eigen::Vector4d(0, 0, 0, 1))
        node.rotation = {rotation[0], rotation[1], rotation[2], rotation[3]};
    if (scale != 1.0)
        node.scale = {scale, scale, scale};
    gltf::writeModel(model, std::move(m), std::move(node), path);
}

} // namespace morphogen
