// Baking into the model's own texture coordinates (core/surface/uv_bake.hpp):
// each covered texel holds the pattern at its point on the surface, islands
// are padded, the rest of the image is empty, and the GLB carries the
// model's vertices and UVs. The pattern here is a smooth made-up field of
// the texels' positions, so what a texel should hold is known.

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "core/mesh/gltf_output.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/surface/surface_glb.hpp"
#include "core/surface/tile_builder.hpp"
#include "core/surface/uv_bake.hpp"
#include "test_support.hpp"
#include "uv_torus_fixture.hpp"

using namespace morphogen;

namespace {

// The made-up pattern: smooth in space, so nearby texels hold nearby values.
std::array<double, 3> field(const Eigen::Vector3f& p) {
    return {127.5 + 100 * std::sin(1.3 * p.x()), 127.5 + 100 * std::cos(1.1 * p.y()),
            127.5 + 100 * std::sin(2.0 * p.z())};
}

struct Baked {
    UvMesh mesh;
    SurfaceTiles tiles;
    TexturedMesh result;
};

// The squeezed UV torus (uv_torus_fixture.hpp) baked at `size`.
Baked bakeTorus(int size) {
    Baked b;
    test::UvTorus torus = test::uvTorus();
    b.mesh = std::move(torus.mesh);
    b.tiles = std::move(torus.tiles);
    SurfaceColours colours;
    const std::size_t cells = b.tiles.atlas->cellCount();
    colours.colours.assign(cells, {0, 0, 0, 255});
    colours.height.assign(cells, 0.0f);
    for (std::size_t i = 0; i < cells; ++i) {
        const std::array<double, 3> f = field(b.tiles.texelPositions[i]);
        for (int k = 0; k < 3; ++k)
            colours.colours[i][std::size_t(k)] = std::uint8_t(std::lround(f[std::size_t(k)]));
        colours.height[i] = float(f[0] / 255.0);
    }
    UvBakeOptions bake;
    bake.size = size;
    b.result = bakeIntoUvs(b.mesh, b.tiles, colours, bake);
    return b;
}

} // namespace

TEST(UvBake, EachTexelHoldsThePatternAtItsPointOnTheSurface) {
    const int size = 256;
    const Baked b = bakeTorus(size);
    ASSERT_EQ(b.result.baseColour.width, size);
    ASSERT_EQ(b.result.positions.size(), b.mesh.positions.size());
    EXPECT_EQ(b.result.uvs, b.mesh.uvs);
    // At each triangle's centroid: the texel there against the field at the
    // centroid's 3D point. Tolerance: the blend spans about 1.5 texels of the
    // tiles (0.06 units here) and the texel centre sits up to half a baked
    // texel from the centroid; the field changes by at most 200 per unit:
    // 0.1 units is 20 of 255.
    int checked = 0;
    double worst = 0;
    for (const auto& t : b.mesh.triangles) {
        const Eigen::Vector2f uv = (b.mesh.uvs[t[0]] + b.mesh.uvs[t[1]] + b.mesh.uvs[t[2]]) / 3;
        const Eigen::Vector3f p =
            (b.mesh.positions[t[0]] + b.mesh.positions[t[1]] + b.mesh.positions[t[2]]) / 3;
        const int x = int(uv.x() * size), y = int(uv.y() * size);
        const auto& texel = b.result.baseColour.texels[std::size_t(y) * size + std::size_t(x)];
        ASSERT_EQ(texel[3], 255) << "an island texel left empty at " << x << ", " << y;
        const std::array<double, 3> want = field(p);
        for (int k = 0; k < 3; ++k)
            worst = std::max(worst, std::abs(double(texel[std::size_t(k)]) - want[std::size_t(k)]));
        ++checked;
    }
    EXPECT_GT(checked, 500);
    EXPECT_LE(worst, 20.0);
    std::printf("largest difference from the field: %.1f of 255 over %d texels\n", worst, checked);
}

TEST(UvBake, IslandsArePaddedAndTheRestIsEmpty) {
    const int size = 256;
    const Baked b = bakeTorus(size);
    const auto texel = [&](double u, double v) {
        return b.result.baseColour.texels[std::size_t(v * size) * size + std::size_t(u * size)];
    };
    // Three texels right of the island's edge (u = 0.6): padded.
    EXPECT_EQ(texel(0.6 + 3.5 / size, 0.45)[3], 255);
    EXPECT_EQ(texel(0.1 - 3.5 / size, 0.45)[3], 255);
    // Far from it: empty.
    EXPECT_EQ(texel(0.9, 0.9)[3], 0);
    EXPECT_EQ(texel(0.9, 0.05)[3], 0);
    // The normal map: flat where nothing is, tilted somewhere on the island.
    const auto& n = b.result.normalMap;
    ASSERT_EQ(n.width, size);
    EXPECT_EQ(n.texels[std::size_t(0.9 * size) * size + std::size_t(0.9 * size)][2], 255);
    bool tilted = false;
    for (const auto& t : n.texels)
        tilted = tilted || t[0] < 120 || t[0] > 136;
    EXPECT_TRUE(tilted);
}

TEST(UvBake, TheGlbHoldsTheModelsVerticesAndUvs) {
    const Baked b = bakeTorus(64);
    const std::string path =
        (test::scratchDir("morphogen_uv_bake_test") / "torus_baked.glb").string();
    writeTexturedGlb(b.result, path);
    const TexturedMesh again = readTexturedGlb(path);
    EXPECT_EQ(again.positions.size(), b.mesh.positions.size());
    EXPECT_EQ(again.triangles.size(), b.mesh.triangles.size());
    ASSERT_EQ(again.uvs.size(), b.mesh.uvs.size());
    for (std::size_t i = 0; i < again.uvs.size(); ++i)
        ASSERT_TRUE(again.uvs[i].isApprox(b.mesh.uvs[i], 1e-6f)) << i;
    EXPECT_EQ(again.baseColour.width, 64);
    EXPECT_EQ(again.normalMap.width, 64);
}

TEST(UvBake, UvsAreReadFromObjFaces) {
    const std::filesystem::path dir = test::freshScratchDir("morphogen_uv_bake_test", "obj");
    // A square of two triangles; its corners share positions but not UVs at one seam.
    std::ofstream(dir / "square.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                         "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n";
    const std::optional<UvMesh> uvs = readUvMesh((dir / "square.obj").string());
    ASSERT_TRUE(uvs.has_value());
    EXPECT_EQ(uvs->triangles.size(), 2u);
    EXPECT_EQ(uvs->positions.size(), 5u); // vertex 1 twice: two texture coordinates
    // OBJ's v up becomes glTF's v down.
    EXPECT_TRUE(uvs->uvs[0].isApprox(Eigen::Vector2f(0, 1)));
    EXPECT_TRUE(bakeableUvs(*uvs));
    // A face without texture coordinates: no layout to bake into.
    std::ofstream(dir / "bare.obj")
        << "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 1 3 2\n";
    EXPECT_FALSE(readUvMesh((dir / "bare.obj").string()).has_value());
    // A tiled layout (UVs past 1) is not baked.
    UvMesh tiled = *uvs;
    tiled.uvs[0].x() = 3.0f;
    EXPECT_FALSE(bakeableUvs(tiled));
}

TEST(UvBake, UvsAreReadFromGlbPrimitives) {
    MeshAttributes attributes;
    const TriangleMesh torus = torusWithSeams(16, attributes);
    const std::string path =
        (test::freshScratchDir("morphogen_uv_bake_test", "glb") / "torus.glb").string();
    writeGlb(torus, attributes, path);
    const std::optional<UvMesh> uvs = readUvMesh(path);
    ASSERT_TRUE(uvs.has_value());
    ASSERT_EQ(uvs->positions.size(), torus.positions.size());
    EXPECT_EQ(uvs->triangles, torus.triangles);
    for (std::size_t i = 0; i < uvs->uvs.size(); ++i)
        ASSERT_TRUE(uvs->uvs[i].isApprox(attributes.texcoords[i])) << i;
    // Without TEXCOORD_0: nothing to bake into.
    writeGlb(torus, {}, path);
    EXPECT_FALSE(readUvMesh(path).has_value());
}

// glTF's normal textures have +Y up the image, and where TANGENT is ignored
// (Blender's importer) the frame is MikkTSpace's from the UVs, its bitangent
// up the image too: the baked tangents' bitangent must point up the image
// (towards -v), and the normal map lean against the height's slope that way.
TEST(UvBake, TheNormalMapAndTangentsFollowGltfsYUp) {
    const Baked b = bakeTorus(128);
    // Per triangle, where +v runs on the surface (Lengyel's tdir); the
    // bitangent w * cross(n, t) of each of its vertices against it.
    int against = 0, along = 0;
    for (const auto& t : b.mesh.triangles) {
        const Eigen::Vector3f &p0 = b.mesh.positions[t[0]], &p1 = b.mesh.positions[t[1]],
                              &p2 = b.mesh.positions[t[2]];
        const Eigen::Vector2f &w0 = b.mesh.uvs[t[0]], &w1 = b.mesh.uvs[t[1]],
                              &w2 = b.mesh.uvs[t[2]];
        const float du1 = w1.x() - w0.x(), dv1 = w1.y() - w0.y();
        const float du2 = w2.x() - w0.x(), dv2 = w2.y() - w0.y();
        const float det = du1 * dv2 - du2 * dv1;
        if (std::abs(det) < 1e-12f)
            continue;
        const Eigen::Vector3f alongV = ((p2 - p0) * du1 - (p1 - p0) * du2) / det;
        for (std::uint32_t v : t) {
            const Eigen::Vector4f& tan = b.result.tangents[v];
            const Eigen::Vector3f bitangent = tan.w() * b.result.normals[v].cross(tan.head<3>());
            (bitangent.dot(alongV) < 0 ? against : along) += 1;
        }
    }
    EXPECT_GT(against, 20 * std::max(along, 1)) << against << " against +v, " << along << " along";
}

// A glTF with two materials on its primitives: the bake keeps each one (its
// name, metalness, roughness, emission, alpha mode, sidedness) with the
// pattern's textures, on the triangles that had it.
TEST(UvBake, TheModelsGltfMaterialsAreKept) {
    test::UvTorus torus = test::uvTorus();
    const UvMesh& source = torus.mesh;
    const std::size_t half = source.triangles.size() / 2;
    const std::string dir = test::freshScratchDir("morphogen_uv_bake_test", "materials").string();
    {
        // Written with tinygltf itself: two primitives on the torus's
        // vertices, triangles [0, half) of "bark" and the rest of "leaf".
        tinygltf::Model model = gltf::newModel();
        tinygltf::Primitive base;
        base.mode = TINYGLTF_MODE_TRIANGLES;
        gltf::addPositions(model, base, source.positions);
        gltf::addFloatAttribute(model, base, "TEXCOORD_0", source.uvs.data(),
                                sizeof(Eigen::Vector2f), TINYGLTF_TYPE_VEC2, source.uvs.size());
        tinygltf::Material bark;
        bark.name = "bark";
        bark.pbrMetallicRoughness.metallicFactor = 0.1;
        bark.pbrMetallicRoughness.roughnessFactor = 0.3;
        bark.pbrMetallicRoughness.baseColorFactor = {0.5, 0.2, 0.1, 0.8};
        bark.emissiveFactor = {0.2, 0.0, 0.05};
        bark.alphaMode = "MASK";
        bark.alphaCutoff = 0.25;
        bark.doubleSided = false;
        tinygltf::Material leaf;
        leaf.name = "leaf";
        leaf.doubleSided = true;
        model.materials = {bark, leaf};
        tinygltf::Mesh mesh;
        for (int part = 0; part < 2; ++part) {
            const auto first = source.triangles.begin() + (part == 0 ? 0 : std::ptrdiff_t(half));
            const auto last = part == 0 ? source.triangles.begin() + std::ptrdiff_t(half)
                                        : source.triangles.end();
            const std::vector<std::array<std::uint32_t, 3>> tris(first, last);
            tinygltf::Primitive prim = base;
            prim.material = part;
            prim.indices = gltf::addAccessor(
                model,
                gltf::addView(model, tris.data(), tris.size() * sizeof(tris[0]),
                              TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, 3 * tris.size());
            mesh.primitives.push_back(prim);
        }
        gltf::writeModel(model, mesh, tinygltf::Node{}, dir + "/two_materials.glb");
    }
    const std::optional<UvMesh> read = readUvMesh(dir + "/two_materials.glb");
    ASSERT_TRUE(read.has_value());
    ASSERT_EQ(read->materials.materials.size(), 2u);
    ASSERT_EQ(read->materials.ofTriangle.size(), source.triangles.size());
    for (std::size_t t = 0; t < source.triangles.size(); ++t)
        ASSERT_EQ(read->materials.ofTriangle[t], t < half ? 0 : 1) << t;
    EXPECT_EQ(read->materials.materials[0].name, "bark");
    EXPECT_EQ(read->materials.materials[0].alphaMode, "MASK");

    SurfaceColours colours;
    const std::size_t cells = torus.tiles.atlas->cellCount();
    colours.colours.assign(cells, {90, 160, 30, 255});
    colours.height.assign(cells, 0.0f);
    UvBakeOptions bake;
    bake.size = 64;
    const std::string out = dir + "/baked.glb";
    writeTexturedGlb(bakeIntoUvs(*read, torus.tiles, colours, bake), out);

    tinygltf::Model written;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&written, &error, &warning, out)) << error;
    ASSERT_EQ(written.meshes.size(), 1u);
    const auto& prims = written.meshes[0].primitives;
    ASSERT_EQ(prims.size(), 2u);
    std::size_t indices = 0;
    for (const tinygltf::Primitive& prim : prims)
        indices += written.accessors.at(std::size_t(prim.indices)).count;
    EXPECT_EQ(indices, 3 * source.triangles.size());
    const tinygltf::Material& b = written.materials.at(std::size_t(prims[0].material));
    const tinygltf::Material& l = written.materials.at(std::size_t(prims[1].material));
    EXPECT_EQ(b.name, "bark");
    EXPECT_EQ(l.name, "leaf");
    EXPECT_DOUBLE_EQ(b.pbrMetallicRoughness.metallicFactor, 0.1);
    EXPECT_DOUBLE_EQ(b.pbrMetallicRoughness.roughnessFactor, 0.3);
    // The pattern is the colour: the factor's colour is white, its alpha kept.
    EXPECT_EQ(b.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{1, 1, 1, 0.8}));
    EXPECT_EQ(b.emissiveFactor, (std::vector<double>{0.2, 0.0, 0.05}));
    EXPECT_EQ(b.alphaMode, "MASK");
    EXPECT_DOUBLE_EQ(b.alphaCutoff, 0.25);
    EXPECT_FALSE(b.doubleSided);
    EXPECT_TRUE(l.doubleSided);
    EXPECT_DOUBLE_EQ(l.pbrMetallicRoughness.roughnessFactor, 1.0); // glTF's default, as it was
    // Both on the one baked pair of textures.
    EXPECT_GE(b.pbrMetallicRoughness.baseColorTexture.index, 0);
    EXPECT_EQ(b.pbrMetallicRoughness.baseColorTexture.index,
              l.pbrMetallicRoughness.baseColorTexture.index);
    EXPECT_EQ(b.normalTexture.index, l.normalTexture.index);
    EXPECT_EQ(written.images.size(), 2u);

    const TexturedMesh again = readTexturedGlb(out);
    EXPECT_EQ(again.triangles.size(), source.triangles.size());
    ASSERT_EQ(again.materials.materials.size(), 2u);
    EXPECT_EQ(again.materials.materials[1].name, "leaf");
}
