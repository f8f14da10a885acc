// OBJ input through tinyobjloader, with the checks it leaves out.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

#include <tiny_obj_loader.h>

#include "core/base/errors.hpp"
#include "core/mesh/mesh_formats.hpp"
#include "core/mesh/polygon_triangulation.hpp"

namespace morphogen::mesh_formats {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

std::string quoted(const char* begin, const char* end) {
    const char* stop = begin;
    while (stop < end && !isBlank(*stop))
        ++stop;
    const std::size_t n = std::size_t(stop - begin);
    return "'" + std::string(begin, std::min<std::size_t>(n, 40)) + (n > 40 ? "...'" : "'");
}

// tinyobjloader reads "nan", "inf" and a missing coordinate as 0, lets a face
// of fewer than three corners through with a warning, and resolves indices
// without range checks. Vertex and face lines are checked here first, so the
// error can name the line. In place, without copies: it reads the whole file.
void checkLines(const std::string& path, const std::string& text) {
    std::size_t lineNumber = 0, vertices = 0;
    long largestIndex = 0;
    std::size_t largestIndexLine = 0;
    const char* const textEnd = text.data() + text.size(); // text.c_str() ends in '\0'
    for (const char* p = text.data(); p < textEnd;) {
        const char* end = static_cast<const char*>(std::memchr(p, '\n', std::size_t(textEnd - p)));
        if (!end)
            end = textEnd;
        ++lineNumber;
        const char* c = p;
        p = end + 1;
        while (c < end && isBlank(*c))
            ++c;
        // "v" or "f" then a blank or the line's end (a bare "v" is a vertex of zeros
        // to tinyobjloader).
        if (c == end || (c[0] != 'v' && c[0] != 'f') || (end - c > 1 && !isBlank(c[1])))
            continue;
        const bool vertex = c[0] == 'v';
        ++c;
        auto at = [&] { return path + ": line " + std::to_string(lineNumber) + ": "; };
        int fields = 0;
        for (;; ++fields) {
            while (c < end && isBlank(*c))
                ++c;
            if (c >= end || (vertex && fields == 3))
                break;
            char* stop = nullptr;
            if (vertex) {
                const double value = std::strtod(c, &stop);
                if (stop == c || (stop < end && !isBlank(*stop)))
                    throw InputError(at() + "vertex coordinate " + quoted(c, end) +
                                     " is not a number");
                if (!std::isfinite(float(value)))
                    throw InputError(at() + "vertex coordinate " + quoted(c, end) +
                                     " is not a finite number (NaN, infinite or beyond float)");
            } else {
                const long index = std::strtol(c, &stop, 10);
                if (stop == c || (stop < end && !isBlank(*stop) && *stop != '/'))
                    throw InputError(at() + "face corner " + quoted(c, end) +
                                     " does not start with a vertex number");
                if (index == 0)
                    throw InputError(at() + "face corner " + quoted(c, end) +
                                     ": OBJ vertex numbers start at 1 (or count back from -1)");
                // A negative index counts back from the vertices read so far.
                // Compared without negating: strtol gives LONG_MIN for a number below it.
                if (index < 0 && index < -static_cast<long>(vertices))
                    throw InputError(at() + "face corner " + quoted(c, end) +
                                     " refers back past the first vertex: only " +
                                     std::to_string(vertices) + " precede it");
                if (index > largestIndex) {
                    largestIndex = index;
                    largestIndexLine = lineNumber;
                }
                while (stop < end && !isBlank(*stop))
                    ++stop; // past "/vt/vn"
            }
            c = stop;
        }
        if (vertex && fields < 3)
            throw InputError(at() + "a vertex needs 3 coordinates, found " +
                             std::to_string(fields) + " (a truncated file?)");
        if (vertex)
            ++vertices;
        if (!vertex && fields < 3)
            throw InputError(at() + "a face needs at least 3 corners, found " +
                             std::to_string(fields) + " (a truncated file?)");
    }
    // Positive indices may refer to vertices further down the file.
    if (largestIndex > long(vertices))
        throw InputError(path + ": line " + std::to_string(largestIndexLine) +
                         ": a face refers to vertex " + std::to_string(largestIndex) +
                         ", but the file has " + std::to_string(vertices) +
                         " vertices (an index out of range, or a truncated file?)");
}

} // namespace

TriangleMesh readObj(const std::string& path, const std::string& text, MeshFileInfo& info,
                     UvMesh* uvs) {
    info.format = "OBJ";
    checkLines(path, text);

    tinyobj::ObjReaderConfig config;
    config.triangulate = false; // polygons are split below, after the index checks
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // From a string: `mtllib` is ignored, so no material files are looked for.
    if (!reader.ParseFromString(text, "", config))
        throw InputError(path + ": not a readable OBJ file: " + reader.Error());

    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    TriangleMesh mesh;
    const std::size_t vertexCount = attrib.vertices.size() / 3;
    mesh.positions.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i)
        mesh.positions[i] = Eigen::Vector3f(attrib.vertices[3 * i], attrib.vertices[3 * i + 1],
                                            attrib.vertices[3 * i + 2]);
    info.vertices = vertexCount;

    // With `uvs`: per triangle corner, its (position, texture coordinate) pair.
    std::vector<std::array<std::pair<int, int>, 3>> uvCorners;
    bool everyCornerHasUv = uvs != nullptr;
    const std::size_t texcoordCount = attrib.texcoords.size() / 2;
    std::size_t faceNumber = 0;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        if (!shape.lines.indices.empty() || !shape.points.indices.empty())
            ++info.skippedParts;
        if (shape.mesh.num_face_vertices.empty())
            continue;
        ++info.parts;
        std::size_t offset = 0;
        for (const unsigned int corners : shape.mesh.num_face_vertices) {
            ++faceNumber;
            const tinyobj::index_t* idx = shape.mesh.indices.data() + offset;
            offset += corners;
            if (offset > shape.mesh.indices.size())
                throw InputError(path + ": face " + std::to_string(faceNumber) +
                                 " is cut short (a truncated file?)");
            for (unsigned int k = 0; k < corners; ++k)
                if (idx[k].vertex_index < 0 || std::size_t(idx[k].vertex_index) >= vertexCount)
                    throw InputError(
                        path + ": face " + std::to_string(faceNumber) + " refers to vertex " +
                        std::to_string(long(idx[k].vertex_index) + 1) + ", but the file has " +
                        std::to_string(vertexCount) + " vertices");
            // A concave face's fan would overlap itself: ear clipping covers it exactly.
            std::vector<Eigen::Vector3f> points(corners);
            for (unsigned int k = 0; k < corners; ++k)
                points[k] = mesh.positions[std::size_t(idx[k].vertex_index)];
            for (const std::array<int, 3>& t : triangulatePolygon(points)) {
                mesh.triangles.push_back({std::uint32_t(idx[t[0]].vertex_index),
                                          std::uint32_t(idx[t[1]].vertex_index),
                                          std::uint32_t(idx[t[2]].vertex_index)});
                if (!everyCornerHasUv)
                    continue;
                std::array<std::pair<int, int>, 3> corner;
                for (int k = 0; k < 3; ++k) {
                    const tinyobj::index_t& c = idx[t[std::size_t(k)]];
                    everyCornerHasUv = everyCornerHasUv && c.texcoord_index >= 0 &&
                                       std::size_t(c.texcoord_index) < texcoordCount;
                    corner[std::size_t(k)] = {c.vertex_index, c.texcoord_index};
                }
                uvCorners.push_back(corner);
            }
        }
    }
    info.triangles = mesh.triangles.size();
    if (everyCornerHasUv) {
        std::map<std::pair<int, int>, std::uint32_t> vertexOf;
        for (const auto& corners : uvCorners) {
            std::array<std::uint32_t, 3> t{};
            for (int k = 0; k < 3; ++k) {
                const auto [v, vt] = corners[std::size_t(k)];
                const auto [it, added] =
                    vertexOf.emplace(corners[std::size_t(k)], std::uint32_t(uvs->positions.size()));
                if (added) {
                    uvs->positions.push_back(mesh.positions[std::size_t(v)]);
                    // OBJ's v runs up from the image's bottom row; glTF's down from its top.
                    uvs->uvs.emplace_back(attrib.texcoords[2 * std::size_t(vt)],
                                          1.0f - attrib.texcoords[2 * std::size_t(vt) + 1]);
                }
                t[std::size_t(k)] = it->second;
            }
            uvs->triangles.push_back(t);
        }
    }
    return mesh;
}

} // namespace morphogen::mesh_formats
