#include "core/surface/mesh_collapse.hpp"

#include <array>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Constrained_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace morphogen {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point>;

// The mesh's border edges, as CGAL's edge_is_constrained_map: a scan's open
// edges (an ear cut open, a hole) stay where they are, as meshoptimizer's
// LockBorder keeps them; collapsing them would pull the tiles back from the
// model's edge.
struct BorderEdges {
    using key_type = CgalMesh::Edge_index;
    using value_type = bool;
    using reference = bool;
    using category = boost::readable_property_map_tag;
    const CgalMesh* mesh = nullptr;
    friend bool get(const BorderEdges& map, key_type e) { return map.mesh->is_border(e); }
};

} // namespace

TriangleMesh collapseKeepingTopology(const TriangleMesh& mesh, std::size_t targetTriangles) {
    namespace PMP = CGAL::Polygon_mesh_processing;
    namespace SMS = CGAL::Surface_mesh_simplification;
    if (mesh.triangles.size() <= targetTriangles)
        return mesh;
    std::vector<Point> points;
    points.reserve(mesh.positions.size());
    for (const Eigen::Vector3f& p : mesh.positions)
        points.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::array<std::size_t, 3>> faces;
    faces.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        faces.push_back({t[0], t[1], t[2]});
    if (!PMP::is_polygon_soup_a_polygon_mesh(faces))
        return mesh;

    CgalMesh surface;
    PMP::polygon_soup_to_polygon_mesh(points, faces, surface);
    // The predicate counts edges: a closed triangle mesh has 3/2 as many as triangles.
    SMS::Count_stop_predicate<CgalMesh> stop(targetTriangles * 3 / 2);
    const BorderEdges border{&surface};
    // Next to a border edge the collapsed vertex stays on it.
    const SMS::Constrained_placement<SMS::LindstromTurk_placement<CgalMesh>, BorderEdges> placement(
        border);
    SMS::edge_collapse(surface, stop,
                       CGAL::parameters::edge_is_constrained_map(border).get_placement(placement));
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
                t[k++] = std::uint32_t(v.idx());
        out.triangles.push_back(t);
    }
    return out;
}

} // namespace morphogen
