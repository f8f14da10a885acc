// Mesh files: the samples in models/meshes/ load with their genus; OBJ and
// glTF features (polygons, negative indices, strips, fans, node transforms,
// mirroring) come out as they should; and every kind of broken file is refused
// with an InputError that names the file and the reason.

#include <cmath>
#include <filesystem>
#include <fstream>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_report.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "test_support.hpp"

using namespace morphogen;
namespace fs = std::filesystem;

namespace {

const fs::path kMeshes = fs::path(MORPHOGEN_MODELS_DIR) / "meshes";

fs::path work() {
    return test::scratchDir("morphogen_mesh_io_test");
}

std::string write(const std::string& name, const std::string& bytes) {
    const fs::path path = work() / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// loadMesh(path) must throw an InputError whose message holds `path` and `needle`.
void expectRefused(const std::string& path, const std::string& needle) {
    try {
        loadMesh(path);
        ADD_FAILURE() << path << " was accepted; want an error containing '" << needle << "'";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path), std::string::npos) << what;
        EXPECT_NE(what.find(needle), std::string::npos) << "want '" << needle << "' in: " << what;
    }
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size())
            n |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size())
            n |= std::uint8_t(bytes[i + 2]);
        out += digits[n >> 18 & 63];
        out += digits[n >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

template <typename T> void append(std::string& bytes, const std::vector<T>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// A .gltf with one buffer (a data URI): `floats` positions then `indices` as
// uint16, and the given "accessors", "meshes", "nodes" and "scenes" JSON.
std::string gltf(const std::vector<float>& floats, const std::vector<std::uint16_t>& indices,
                 const std::string& rest) {
    std::string bytes;
    append(bytes, floats);
    append(bytes, indices);
    const std::size_t floatBytes = floats.size() * 4;
    return R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": )" +
           std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
           base64(bytes) + R"("}], "bufferViews": [{"buffer": 0, "byteLength": )" +
           std::to_string(floatBytes) + R"(}, {"buffer": 0, "byteOffset": )" +
           std::to_string(floatBytes) + R"(, "byteLength": )" + std::to_string(indices.size() * 2) +
           "}], " + rest + "}";
}

// Positions accessor 0 (count vertices) and index accessor 1 (count indices).
std::string accessors(std::size_t vertices, std::size_t indices) {
    return R"("accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )" +
           std::to_string(vertices) +
           R"(}, {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": )" +
           std::to_string(indices) + "}]";
}

const std::vector<float> kCubeCorners = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                         0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
// Outward, counter-clockwise seen from outside (vertex v at (v & 1, v >> 1 & 1, v >> 2 & 1)).
const std::vector<std::uint16_t> kCubeTriangles = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2,
                                                   2, 6, 7, 2, 7, 3, 0, 1, 5, 0, 5, 4,
                                                   4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};

double signedVolume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
        v += m.positions[t[0]].cast<double>().dot(
                 m.positions[t[1]].cast<double>().cross(m.positions[t[2]].cast<double>())) /
             6.0;
    return v;
}

} // namespace

TEST(MeshIo, SamplesLoadClosedWithTheirGenus) {
    struct Sample {
        const char* file;
        int genus;
        std::size_t vertices;
    };
    for (const Sample& s :
         {Sample{"sphere.obj", 0, 2562}, Sample{"torus.obj", 1, 2048}, Sample{"torus.glb", 1, 2048},
          Sample{"holes.obj", 3, 4348}, Sample{"blob.obj", 0, 2562}}) {
        SCOPED_TRACE(s.file);
        const LoadedMesh loaded = loadMesh((kMeshes / s.file).string());
        const MeshReport r = checkMesh(loaded.mesh);
        ASSERT_EQ(r.components.size(), 1u);
        EXPECT_EQ(r.components[0].genus, s.genus);
        EXPECT_EQ(r.boundaryEdges, 0u);
        EXPECT_EQ(r.vertices, s.vertices);
        EXPECT_EQ(r.components[0].eulerCharacteristic, 2 - 2 * s.genus);
        EXPECT_TRUE(r.manifold());
        EXPECT_EQ(r.zeroAreaTriangles.count, 0u);
        EXPECT_EQ(loaded.reoriented, 0u);
        EXPECT_GT(signedVolume(loaded.mesh), 0.0);
    }
}

TEST(MeshIo, SampleFilesMatchTheirGenerator) {
    // Regenerating gives the committed files' meshes (to the six decimals written).
    const LoadedMesh holesFile = loadMesh((kMeshes / "holes.obj").string());
    const TriangleMesh generated = holes(3);
    ASSERT_EQ(holesFile.mesh.positions.size(), generated.positions.size());
    ASSERT_EQ(holesFile.mesh.triangles, generated.triangles);
    for (std::size_t i = 0; i < generated.positions.size(); ++i)
        ASSERT_LT((holesFile.mesh.positions[i] - generated.positions[i]).norm(), 2e-6f) << i;
}

TEST(MeshIo, GlbTorusWeldsItsSeamsAndAppliesTheNodeRotation) {
    const LoadedMesh glb = loadMesh((kMeshes / "torus.glb").string());
    EXPECT_EQ(glb.file.format, "GLB");
    EXPECT_EQ(glb.file.vertices, 65u * 33u); // seams stored twice
    EXPECT_EQ(glb.weld.verticesBefore, 65u * 33u);
    EXPECT_EQ(glb.weld.verticesAfter, 64u * 32u);
    EXPECT_EQ(glb.file.parts, 1u);
    // The node turns the torus's axis from z to y.
    const MeshReport r = checkMesh(glb.mesh);
    EXPECT_NEAR(r.bounds.max.y() - r.bounds.min.y(), 0.8f, 1e-5f);
    EXPECT_NEAR(r.bounds.max.z() - r.bounds.min.z(), 2.8f, 1e-5f);
    const LoadedMesh obj = loadMesh((kMeshes / "torus.obj").string());
    EXPECT_NEAR(r.area, checkMesh(obj.mesh).area, 1e-4);
    EXPECT_EQ(glb.mesh.triangles.size(), obj.mesh.triangles.size());
}

TEST(MeshIo, WrittenObjAndGlbReadBack) {
    const TriangleMesh t = torus(10);
    const std::string obj = (work() / "written.obj").string();
    const std::string glb = (work() / "written.glb").string();
    writeObj(t, obj, {"a comment"});
    writeGlb(t, {}, glb);
    for (const std::string& path : {obj, glb}) {
        const LoadedMesh back = loadMesh(path);
        EXPECT_EQ(back.mesh.triangles, t.triangles) << path;
        ASSERT_EQ(back.mesh.positions.size(), t.positions.size());
        for (std::size_t i = 0; i < t.positions.size(); ++i)
            EXPECT_LT((back.mesh.positions[i] - t.positions[i]).norm(), 2e-6f);
    }
    EXPECT_FALSE(fs::exists(obj + ".tmp"));
}

TEST(MeshIo, ObjPolygonsNegativeIndicesAndSeamsLoad) {
    // A cube of quads with texture coordinates and normals, written with
    // relative (negative) indices for the last face: 6 quads, 12 triangles.
    std::string text = "mtllib missing.mtl\no cube\n";
    for (int v = 0; v < 8; ++v)
        text += "v " + std::to_string(v & 1) + " " + std::to_string(v >> 1 & 1) + " " +
                std::to_string(v >> 2 & 1) + "\n";
    text += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n";
    text += "f 2/1/1 4/2/1 8/3/1 6/4/1\nf 1/1/1 5/2/1 7/3/1 3/4/1\nf 3/1/1 7/2/1 8/3/1 4/4/1\n"
            "f 1 2 6 5\ng top\nf 5/1 6/2 8/3 7/4\nf -8 -6 -5 -7\nl 1 2\n";
    const std::string path = write("quads.obj", text);
    const LoadedMesh m = loadMesh(path);
    EXPECT_EQ(m.file.triangles, 12u);
    EXPECT_EQ(m.file.parts, 2u);
    const MeshReport r = checkMesh(m.mesh);
    EXPECT_EQ(r.vertices, 8u);
    EXPECT_EQ(r.boundaryEdges, 0u);
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_EQ(r.components[0].genus, 0);
    EXPECT_NEAR(signedVolume(m.mesh), 1.0, 1e-9);
    // A pentagon splits into three triangles.
    EXPECT_EQ(loadMesh(write("pentagon.obj", "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 1.5 0\n"
                                             "v -0.5 1 0\nf 1 2 3 4 5\n"))
                  .mesh.triangles.size(),
              3u);
}

TEST(MeshIo, GltfNodesStripsAndFansAreApplied) {
    // Mesh 0: the cube as triangles; mesh 1: a square as a strip; mesh 2: the same square
    // as a fan. A parent node scales by 2 and mirrors x; its child moves by (10, 0, 0).
    std::vector<std::uint16_t> indices = kCubeTriangles;
    for (std::uint16_t i : {0, 1, 2, 3, 0, 1, 3, 2})
        indices.push_back(i);
    const std::string rest =
        R"("accessors": [
          {"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": 8},
          {"bufferView": 1, "componentType": 5123, "type": "SCALAR", "count": 36},
          {"bufferView": 1, "byteOffset": 72, "componentType": 5123, "type": "SCALAR", "count": 4},
          {"bufferView": 1, "byteOffset": 80, "componentType": 5123, "type": "SCALAR", "count": 4}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1},
                                   {"attributes": {"POSITION": 0}, "indices": 1, "mode": 1}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "mode": 5}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "indices": 3, "mode": 6}]}],
        "nodes": [{"scale": [-2, 2, 2], "mesh": 0, "children": [1]},
                  {"translation": [10, 0, 0], "mesh": 1, "children": [2]},
                  {"mesh": 2}, {"mesh": 0}],
        "scenes": [{"nodes": [3]}, {"nodes": [0]}], "scene": 1)";
    const std::string path = write("nodes.gltf", gltf(kCubeCorners, indices, rest));
    MeshFileInfo info;
    const TriangleMesh raw = readMeshFile(path, &info);
    EXPECT_EQ(info.format, "glTF");
    EXPECT_EQ(info.parts, 3u);        // the cube, the strip, the fan (scene 1 only)
    EXPECT_EQ(info.skippedParts, 1u); // the lines
    EXPECT_EQ(info.triangles, 12u + 2u + 2u);
    // The cube: scaled and mirrored, yet still wound outward.
    TriangleMesh cube{raw.positions, {raw.triangles.begin(), raw.triangles.begin() + 12}};
    EXPECT_NEAR(signedVolume(cube), 8.0, 1e-6); // outward
    const Bounds box = boundsOf({raw.positions.begin(), raw.positions.begin() + 8});
    EXPECT_TRUE(box.min.isApprox(Eigen::Vector3f(-2, 0, 0)));
    EXPECT_TRUE(box.max.isApprox(Eigen::Vector3f(0, 2, 2)));
    // Strip and fan: the child's translation is applied before the parent's scale:
    // x = -2 * (corner x + 10).
    for (std::size_t i = 8; i < raw.positions.size(); ++i)
        EXPECT_LE(raw.positions[i].x(), -20.0f);
    const LoadedMesh loaded = loadMesh(path);
    const MeshReport r = checkMesh(loaded.mesh);
    EXPECT_EQ(r.components.size(), 2u); // the cube; strip and fan weld into one square
    EXPECT_EQ(r.duplicateTriangles.count, 0u);
}

TEST(MeshIo, BrokenFilesAreRefusedWithTheReason) {
    const std::string goodObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    expectRefused((work() / "none.obj").string(), "no such mesh file");
    expectRefused(work().string(), "is a folder, not a mesh file");
    expectRefused(write("model.stl", "solid x\n"), "unsupported mesh format '.stl'");
    expectRefused(write("empty.obj", ""), "the file is empty");
    expectRefused(write("empty.glb", ""), "the file is empty");
    expectRefused(write("no_faces.obj", goodObj), "has no triangles (3 vertices and no faces)");
    expectRefused(write("lines.obj", goodObj + "l 1 2 3\n"), "only points or lines");
    expectRefused(write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"),
                  "line 2: vertex coordinate 'nan' is not a finite number");
    expectRefused(write("inf.obj", "v 0 0 0\nv 1 1e39 0\nv 0 1 0\nf 1 2 3\n"),
                  "line 2: vertex coordinate '1e39' is not a finite number");
    expectRefused(write("bare.obj", goodObj + "v\nf 1 2 4\n"),
                  "line 4: a vertex needs 3 coordinates, found 0");
    expectRefused(write("word.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n"),
                  "line 2: vertex coordinate 'x' is not a number");
    expectRefused(write("range.obj", goodObj + "f 1 2 9\n"),
                  "line 4: a face refers to vertex 9, but the file has 3 vertices");
    expectRefused(write("back.obj", goodObj + "f 1 2 -4\n"),
                  "line 4: face corner '-4' refers back past the first vertex: only 3 precede it");
    // Below LONG_MIN strtol saturates; negating that was undefined (found by mesh_fuzzer).
    expectRefused(write("far_back.obj", goodObj + "f 1 2 -99999999999999999999\n"),
                  "line 4: face corner '-99999999999999999999' refers back past the first vertex");
    expectRefused(write("zero.obj", goodObj + "f 0 1 2\n"), "OBJ vertex numbers start at 1");
    expectRefused(write("collapsed.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n"),
                  "all 1 triangles collapse");

    // Truncated OBJ: cut inside a face line, or inside a vertex line.
    const std::string torusObj = readBytes(kMeshes / "torus.obj");
    const std::size_t lastFace = torusObj.rfind("\nf ");
    const std::size_t secondSpace = torusObj.find(' ', torusObj.find(' ', lastFace + 3) + 1);
    expectRefused(write("cut_face.obj", torusObj.substr(0, secondSpace)),
                  "a face needs at least 3 corners, found 2 (a truncated file?)");
    const std::size_t vertexLine = torusObj.find("\nv ", 1000);
    expectRefused(write("cut_vertex.obj", torusObj.substr(0, vertexLine + 12)),
                  "a vertex needs 3 coordinates, found 1 (a truncated file?)");

    // Truncated GLB and glTF.
    const std::string torusGlb = readBytes(kMeshes / "torus.glb");
    expectRefused(write("half.glb", torusGlb.substr(0, torusGlb.size() / 2)),
                  "not a readable GLB file");
    expectRefused(write("header.glb", torusGlb.substr(0, 12)), "not a readable GLB file");
    expectRefused(write("text.glb", "{\"asset\": {\"version\": \"2.0\"}}"),
                  "not a readable GLB file");
    const std::string square =
        gltf(kCubeCorners, kCubeTriangles, accessors(8, 36) + R"(, "meshes": [{"primitives": [
        {"attributes": {"POSITION": 0}, "indices": 1}]}], "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}])");
    ASSERT_NO_THROW(loadMesh(write("cube.gltf", square)));
    expectRefused(write("cut.gltf", square.substr(0, square.size() - 40)),
                  "not a readable glTF file");
}

TEST(MeshIo, BrokenGltfContentIsRefusedWithTheReason) {
    const std::string meshes =
        R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
           "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}])";
    const std::vector<float> tri = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    expectRefused(write("index.gltf", gltf(tri, {0, 1, 7}, accessors(3, 3) + ", " + meshes)),
                  "mesh 0 primitive 0: index 2 is 7, but there are 3 vertices");
    // Signed indices (invalid glTF, read all the same): -1 is refused as -1
    // (mesh_fuzzer found its conversion to an unsigned integer undefined).
    std::string signedIndices = accessors(3, 3);
    signedIndices.replace(signedIndices.rfind("5123"), 4, "5122");
    expectRefused(write("signed.gltf", gltf(tri, {0, 1, 0xFFFF}, signedIndices + ", " + meshes)),
                  "mesh 0 primitive 0: index 2 is -1, but there are 3 vertices");
    expectRefused(
        write("long.gltf", gltf(tri, {0, 1, 2}, accessors(5, 3) + ", " + meshes)),
        "POSITION (accessor 0) (5 elements at byte 0) runs past the end of buffer view 0");
    const float nan = std::nanf("");
    expectRefused(write("nan.gltf", gltf({0, 0, 0, 1, nan, 0, 0, 1, 0}, {0, 1, 2},
                                         accessors(3, 3) + ", " + meshes)),
                  "mesh 0 primitive 0: POSITION 1 is (1, nan, 0): coordinates must be finite");
    expectRefused(write("accessor.gltf",
                        gltf(tri, {0, 1, 2},
                             accessors(3, 3) +
                                 R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 4}}]}],
                                    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}])")),
                  "uses accessor 4, but the file has 2");
    expectRefused(write("cycle.gltf", gltf(tri, {0, 1, 2},
                                           accessors(3, 3) +
                                               R"(, "meshes": [{"primitives": [
                  {"attributes": {"POSITION": 0}, "indices": 1}]}],
                  "nodes": [{"mesh": 0, "children": [1]}, {"children": [0]}],
                  "scenes": [{"nodes": [0]}])")),
                  "node 0 is reached twice (a cycle, or a node with two parents)");
    expectRefused(
        write("draco.gltf", gltf(tri, {0, 1, 2},
                                 accessors(3, 3) + ", " + meshes +
                                     R"(, "extensionsUsed": ["KHR_draco_mesh_compression"],
                  "extensionsRequired": ["KHR_draco_mesh_compression"])")),
        "needs the extension KHR_draco_mesh_compression");
    expectRefused(write("no_mesh.gltf", gltf(tri, {0, 1, 2}, accessors(3, 3))), "has no triangles");
    // An index written by the GLB writer past the vertices (the writer does not check).
    TriangleMesh bad{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 99}}};
    const std::string path = (work() / "bad_index.glb").string();
    writeGlb(bad, {}, path);
    expectRefused(path, "index 2 is 99, but there are 3 vertices");
}

TEST(MeshIo, NonManifoldFileIsRepairedOrWithoutRepairRefusedForTiles) {
    const std::string path = write("fin.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                                              "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
    {
        // Loaded as surface tiles load it: the fin's sheets cut apart.
        const LoadedMesh repaired = loadMesh(path);
        EXPECT_EQ(repaired.repair.nonManifoldEdges, 1u);
        EXPECT_GE(repaired.repair.splitVertices, 2u);
        const MeshReport r = checkMesh(repaired.mesh);
        EXPECT_TRUE(r.usableForTiles());
        const std::string text = meshReportText(repaired, r);
        EXPECT_NE(text.find("found: 1 non-manifold edge (more than two triangles)"),
                  std::string::npos)
            << text;
        EXPECT_NE(text.find("repaired: "), std::string::npos) << text;
        EXPECT_EQ(meshReportJson(repaired, r)["usable"], true);
    }
    RepairOptions off;
    off.enabled = false;
    const LoadedMesh m = loadMesh(path, off);
    const MeshReport r = checkMesh(m.mesh);
    EXPECT_EQ(r.nonManifoldEdges.count, 1u);
    try {
        requireManifold(r, path);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path + ": not a manifold surface"), std::string::npos);
    }
    const std::string text = meshReportText(m, r);
    EXPECT_NE(text.find("non-manifold edges (more than two triangles): 1, the first at (0.5, 0, "
                        "0) (refused)"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("usable for surface tiles: no"), std::string::npos);
    EXPECT_EQ(meshReportJson(m, r)["problems"]["non_manifold_edges"]["count"], 1);
    EXPECT_EQ(meshReportJson(m, r)["usable"], false);
}

TEST(MeshIo, ReportNamesGenusAndBoundaries) {
    const std::string path = write("sheet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const LoadedMesh m = loadMesh(path);
    const MeshReport r = checkMesh(m.mesh);
    const std::string text = meshReportText(m, r);
    EXPECT_NE(text.find("boundary: 1 loop of 3 edges"), std::string::npos) << text;
    EXPECT_NE(text.find("  1: genus 0, 1 boundary loop, 3 vertices, 1 triangle, area 0.5"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("problems: none"), std::string::npos) << text;
    const nlohmann::json j = meshReportJson(m, r);
    EXPECT_EQ(j["components"][0]["genus"], 0);
    EXPECT_EQ(j["boundary"]["loops"], 1);
    EXPECT_EQ(j["weld"]["vertices_after"], 3);
    EXPECT_EQ(j["usable"], true);
}
