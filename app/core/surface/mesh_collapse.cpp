#include "core/surface/mesh_collapse.hpp"

#include <array>
#include <vector>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Constrained_placement.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/LindstromTurk_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include "core/mesh/cgal_surface_mesh.hpp"

namespace morphogen {

namespace {

using CgalMesh = cgal::SurfaceMesh;

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
    const cgal::Soup soup = cgal::soupOf(mesh);
    if (!PMP::is_polygon_soup_a_polygon_mesh(soup.faces))
        return mesh;

    CgalMesh surface;
    PMP::polygon_soup_to_polygon_mesh(soup.points, soup.faces, surface);
    // The predicate counts edges: a closed triangle mesh has 3/2 as many as triangles.
    SMS::Count_stop_predicate<CgalMesh> stop(targetTriangles * 3 / 2);
    const BorderEdges border{&surface};
    // Next to a border edge the collapsed vertex stays on it.
    const SMS::Constrained_placement<SMS::LindstromTurk_placement<CgalMesh>, BorderEdges> placement(
        border);
    SMS::edge_collapse(surface, stop,
                       CGAL::parameters::edge_is_constrained_map(border).get_placement(placement));
    return cgal::triangleMeshOf(surface);
}

} // namespace morphogen
