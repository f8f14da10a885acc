// Fuzz target: the mesh readers (OBJ, glTF, GLB), through loadMesh as
// `mesh-info` and the surface tiles read a mesh: read, weld, repair, orient
// (not the alpha wrap, below); then the
// report (checkMesh, its text and JSON) that mesh-info prints. The readers
// pick the format by the file's extension, so the input is written under the
// extension its content suggests: GLB's magic "glTF" first, .gltf when the
// first non-blank byte opens a JSON object, .obj otherwise. The seeds are
// then plain mesh files that mesh-info reads as they are.
//
// Found and failed on: a crash, hang or sanitizer report, an exception other
// than InputError, and an accepted mesh that breaks what loadMesh promises
// (a triangle naming a vertex that is not there, a coordinate not finite).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_report.hpp"
#include "fuzz_support.hpp"

namespace {

namespace fuzz = morphogen::fuzz;

std::string describe(const std::exception& e) {
    return std::string(typeid(e).name()) + ": " + e.what();
}

const char* extensionOf(const std::uint8_t* data, std::size_t size) {
    if (size >= 4 && std::memcmp(data, "glTF", 4) == 0)
        return ".glb";
    for (std::size_t i = 0; i < size; ++i) {
        const char c = char(data[i]);
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        return c == '{' ? ".gltf" : ".obj";
    }
    return ".obj";
}

void checkLoaded(const morphogen::LoadedMesh& m) {
    const std::size_t vertices = m.mesh.positions.size();
    if (m.mesh.triangles.empty())
        fuzz::fail("loadMesh accepted a mesh without triangles");
    for (const auto& t : m.mesh.triangles)
        for (int c = 0; c < 3; ++c)
            if (std::size_t(t[c]) >= vertices)
                fuzz::fail("loadMesh accepted a triangle naming vertex " + std::to_string(t[c]) +
                           " of " + std::to_string(vertices));
    for (const auto& p : m.mesh.positions)
        if (!p.allFinite())
            fuzz::fail("loadMesh accepted a coordinate that is not finite");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path =
        fuzz::writeInput(data, size, std::string("mesh") + extensionOf(data, size));
    try {
        // Without the alpha wrap: CGAL's wrap of a soup takes time in
        // proportion to the surface it makes (seconds under the sanitizers
        // for a few dozen loose triangles spread wide), which the fuzzer's
        // hang limit would report; mesh_wrap_test runs it under them.
        morphogen::RepairOptions repair;
        repair.wrap = morphogen::WrapMode::Never;
        const morphogen::LoadedMesh m = morphogen::loadMesh(path, repair);
        checkLoaded(m);
        const morphogen::MeshReport r = morphogen::checkMesh(m.mesh);
        (void)morphogen::meshReportText(m, r);
        (void)morphogen::meshReportJson(m, r).dump();
        try {
            morphogen::requireManifold(r, path);
        } catch (const morphogen::InputError&) {
            // Refused for tiles, with a message: what mesh-info reports.
        }
    } catch (const morphogen::InputError&) {
    } catch (const std::exception& e) {
        fuzz::fail("reading the mesh threw " + describe(e) + " instead of an InputError");
    }
    return 0;
}
