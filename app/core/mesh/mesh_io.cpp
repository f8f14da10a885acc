#include "core/mesh/mesh_io.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/io/output_files.hpp"
#include "core/mesh/mesh_formats.hpp"

namespace morphogen {

namespace fs = std::filesystem;

namespace {

constexpr const char* kAccepted = "accepted: .obj, .gltf, .glb";

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot be read: " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad())
        throw InputError(path + ": reading failed: " + std::strerror(errno));
    return text.str();
}

std::string point(const Eigen::Vector3f& p) {
    char text[96];
    std::snprintf(text, sizeof text, "(%g, %g, %g)", p.x(), p.y(), p.z());
    return text;
}

} // namespace

namespace {

// readMeshFile's work, with the texture coordinates when `uvs` is given.
TriangleMesh readMeshFileWithUvs(const std::string& path, MeshFileInfo* infoOut, UvMesh* uvs) {
    MeshFileInfo info;
    info.path = path;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status))
        throw InputError(path + ": no such mesh file");
    if (fs::is_directory(status))
        throw InputError(path + ": is a folder, not a mesh file (" + kAccepted + ")");
    if (!fs::is_regular_file(status))
        throw InputError(path + ": is not a regular file (" + kAccepted + ")");
    const std::string ext = lowerExtension(path);
    if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
        throw InputError(path + ": unsupported mesh format '" + ext + "' (" + kAccepted + ")");
    if (fs::file_size(path, ec) == 0 && !ec)
        throw InputError(path + ": the file is empty");

    TriangleMesh mesh = ext == ".obj" ? mesh_formats::readObj(path, readWholeFile(path), info, uvs)
                                      : mesh_formats::readGltf(path, ext == ".glb", info, uvs);

    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (std::uint32_t v : mesh.triangles[t])
            if (v >= mesh.positions.size()) // the readers refuse these first, with more context
                throw InputError(path + ": triangle " + std::to_string(t + 1) +
                                 " refers to vertex " + std::to_string(v + 1) + " of " +
                                 std::to_string(mesh.positions.size()));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        if (!mesh.positions[i].allFinite())
            throw InputError(path + ": vertex " + std::to_string(i + 1) + " is " +
                             point(mesh.positions[i]) +
                             ": coordinates must be finite numbers (no NaN or infinity)");
    if (mesh.triangles.empty()) {
        std::string what = std::to_string(info.vertices) + " vertices and no faces";
        if (info.skippedParts > 0)
            what += "; only points or lines";
        throw InputError(path + ": has no triangles (" + what + "), nothing to grow a pattern on");
    }
    if (infoOut)
        *infoOut = std::move(info);
    return mesh;
}

} // namespace

TriangleMesh readMeshFile(const std::string& path, MeshFileInfo* infoOut) {
    return readMeshFileWithUvs(path, infoOut, nullptr);
}

std::optional<UvMesh> readUvMesh(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
        return std::nullopt; // a generated sample ("sample:torus") has no file
    UvMesh uvs;
    readMeshFileWithUvs(path, nullptr, &uvs);
    if (uvs.triangles.empty())
        return std::nullopt;
    return uvs;
}

LoadedMesh loadMesh(const std::string& path, const RepairOptions& repair) {
    LoadedMesh loaded;
    loaded.mesh = readMeshFile(path, &loaded.file);
    loaded.weld = weldVertices(loaded.mesh);
    if (loaded.mesh.triangles.empty())
        throw InputError(path + ": all " + std::to_string(loaded.file.triangles) +
                         " triangles collapse to a line or point once equal vertices are "
                         "merged, nothing to grow a pattern on");
    // A soup is wrapped whole, as welded: the repair would drop its smallest
    // fragments as specks. Pieces that touch only at corners are one piece
    // welded and many once the repair cuts them apart: that is a soup too.
    const bool automatic = repair.wrap == WrapMode::Automatic && repair.enabled;
    // The wrap replaces `mesh` and is repaired in turn; where CGAL cannot
    // make one the mesh stays as it was and the report says why.
    const auto wrap = [&](TriangleMesh& mesh) {
        try {
            mesh = alphaWrap(mesh, kWrapAlpha, kWrapOffset, &loaded.wrap);
            return true;
        } catch (const std::exception& e) {
            loaded.wrap.failed = e.what();
            return false;
        }
    };
    if (repair.wrap == WrapMode::Always || (automatic && looksLikeSoup(loaded.mesh))) {
        wrap(loaded.mesh);
        loaded.repair = repairMesh(loaded.mesh, repair);
    } else if (automatic) {
        TriangleMesh welded = loaded.mesh;
        loaded.repair = repairMesh(loaded.mesh, repair);
        if (looksLikeSoup(loaded.mesh)) {
            const std::size_t pieces = meshPieces(loaded.mesh);
            if (wrap(welded)) {
                loaded.mesh = std::move(welded);
                loaded.wrap.componentsBefore = pieces;
                loaded.repair = repairMesh(loaded.mesh, repair);
            }
        }
    } else {
        loaded.repair = repairMesh(loaded.mesh, repair);
    }
    if (loaded.mesh.triangles.empty())
        throw InputError(path + ": no triangle is left once duplicates and collapsed ones are "
                                "removed, nothing to grow a pattern on");
    loaded.reoriented = orientConsistently(loaded.mesh);
    return loaded;
}

void writeObj(const TriangleMesh& mesh, const std::string& path,
              const std::vector<std::string>& comment) {
    std::string text;
    text.reserve(mesh.positions.size() * 32 + mesh.triangles.size() * 24);
    for (const std::string& line : comment)
        text += "# " + line + "\n";
    char buffer[128];
    for (const Eigen::Vector3f& p : mesh.positions) {
        // Six decimals: sub-micrometre on a model a few units across, and short lines.
        const int n =
            std::snprintf(buffer, sizeof buffer, "v %.6f %.6f %.6f\n", p.x(), p.y(), p.z());
        text.append(buffer, std::size_t(n));
    }
    for (const auto& t : mesh.triangles) {
        const int n =
            std::snprintf(buffer, sizeof buffer, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
        text.append(buffer, std::size_t(n));
    }
    writeFileAtomically(path, text);
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
    // Through the output-safety writer: a staged temporary is written in
    // place, messages name the final path, and a short write is caught.
    writeTextAtomically(path, bytes);
}

} // namespace morphogen
