#pragma once
// A TriangleMesh to CGAL and back, for the translation units that use CGAL
// (the alpha wrap, the topology-keeping simplifier): CGAL's headers and its
// -frounding-math stay out of every other file (CMakeLists.txt).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// The mesh as a polygon soup: CGAL's points and index triples.
struct Soup {
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3>> faces;
};
inline Soup soupOf(const TriangleMesh& mesh) {
    Soup soup;
    soup.points.reserve(mesh.positions.size());
    for (const Eigen::Vector3f& p : mesh.positions)
        soup.points.emplace_back(p.x(), p.y(), p.z());
    soup.faces.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        soup.faces.push_back({t[0], t[1], t[2]});
    return soup;
}

// A triangle surface mesh back as a TriangleMesh (its removed elements
// collected first, so vertex indices are dense).
inline TriangleMesh triangleMeshOf(SurfaceMesh& surface) {
    surface.collect_garbage();
    TriangleMesh out;
    out.positions.reserve(surface.number_of_vertices());
    for (const auto v : surface.vertices()) {
        const Point& p = surface.point(v);
        out.positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    }
    out.triangles.reserve(surface.number_of_faces());
    for (const auto f : surface.faces()) {
        std::array<std::uint32_t, 3> t{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(surface.halfedge(f), surface))
            if (k < 3)
                t[std::size_t(k++)] = std::uint32_t(v.idx());
        out.triangles.push_back(t);
    }
    return out;
}

} // namespace morphogen::cgal
