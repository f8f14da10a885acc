#include "core/surface/mesh_projector.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

namespace morphogen {

namespace {

// Plain double arithmetic: closest points need no exact predicates, and this
// kernel keeps CGAL header-only (no GMP at run time).
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Ray = Kernel::Ray_3;
using Vector = Kernel::Vector_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Eigen::Vector3f& p) {
    return Point(p.x(), p.y(), p.z());
}

// Barycentric weights of p (on or near triangle abc) for a, b, c, clamped to
// the triangle; a degenerate triangle gives its nearest vertex's weights.
Eigen::Vector3d barycentricOf(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d v0 = b - a, v1 = c - a, v2 = p - a;
    const double d00 = v0.dot(v0), d01 = v0.dot(v1), d11 = v1.dot(v1);
    const double d20 = v2.dot(v0), d21 = v2.dot(v1);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 1e-30 * (d00 * d11 + 1e-300))) {
        const double da = (p - a).squaredNorm(), db = (p - b).squaredNorm(),
                     dc = (p - c).squaredNorm();
        if (da <= db && da <= dc)
            return {1, 0, 0};
        return db <= dc ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(0, 0, 1);
    }
    double v = (d11 * d20 - d01 * d21) / denom;
    double w = (d00 * d21 - d01 * d20) / denom;
    double u = 1 - v - w;
    u = std::max(u, 0.0);
    v = std::max(v, 0.0);
    w = std::max(w, 0.0);
    const double sum = u + v + w;
    return Eigen::Vector3d(u, v, w) / sum;
}

} // namespace

struct MeshProjector::Impl {
    std::vector<Triangle> triangles;
    std::vector<Eigen::Vector3d> corners; // 3 per triangle
    Tree tree;
};

MeshProjector::MeshProjector(const TriangleMesh& mesh) : m_impl(std::make_unique<Impl>()) {
    if (mesh.triangles.empty())
        throw std::invalid_argument("MeshProjector: the mesh has no triangles");
    Impl& m = *m_impl;
    m.triangles.reserve(mesh.triangles.size());
    m.corners.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3f& a = mesh.positions[t[0]];
        const Eigen::Vector3f& b = mesh.positions[t[1]];
        const Eigen::Vector3f& c = mesh.positions[t[2]];
        m.triangles.emplace_back(toPoint(a), toPoint(b), toPoint(c));
        m.corners.push_back(a.cast<double>());
        m.corners.push_back(b.cast<double>());
        m.corners.push_back(c.cast<double>());
    }
    m.tree.insert(m.triangles.cbegin(), m.triangles.cend());
    m.tree.build();
    m.tree.accelerate_distance_queries();
    // CGAL builds the search hints lazily on the first query; make that happen
    // here, on one thread, so later queries only read.
    m.tree.closest_point(toPoint(mesh.positions[mesh.triangles[0][0]]));
}

MeshProjector::~MeshProjector() = default;

SurfacePoint MeshProjector::closest(const Eigen::Vector3f& query) const {
    const Impl& m = *m_impl;
    const auto [point, id] = m.tree.closest_point_and_primitive(toPoint(query));
    SurfacePoint s;
    s.triangle = std::uint32_t(id - m.triangles.cbegin());
    const Eigen::Vector3d p(point.x(), point.y(), point.z());
    s.position = p.cast<float>();
    const Eigen::Vector3d* c = &m.corners[3 * std::size_t(s.triangle)];
    s.barycentric = barycentricOf(p, c[0], c[1], c[2]).cast<float>();
    return s;
}

bool MeshProjector::alongLine(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                              float maxDistance, SurfacePoint& out) const {
    const Impl& m = *m_impl;
    const Eigen::Vector3d o = origin.cast<double>();
    const Eigen::Vector3d d = direction.cast<double>().normalized();
    if (!d.allFinite())
        return false;
    double best = double(maxDistance);
    bool found = false;
    Eigen::Vector3d bestPoint;
    std::uint32_t bestTriangle = 0;
    for (double sign : {1.0, -1.0}) {
        const Ray ray(Point(o.x(), o.y(), o.z()), Vector(sign * d.x(), sign * d.y(), sign * d.z()));
        const auto hit = m.tree.first_intersection(ray);
        if (!hit)
            continue;
        const Point* p = boost::get<Point>(&hit->first);
        if (!p)
            continue; // the ray runs in a triangle's plane: no single point
        const Eigen::Vector3d at(p->x(), p->y(), p->z());
        const double distance = (at - o).norm();
        if (distance <= best) {
            best = distance;
            bestPoint = at;
            bestTriangle = std::uint32_t(hit->second - m.triangles.cbegin());
            found = true;
        }
    }
    if (!found)
        return false;
    out.triangle = bestTriangle;
    out.position = bestPoint.cast<float>();
    const Eigen::Vector3d* c = &m.corners[3 * std::size_t(bestTriangle)];
    out.barycentric = barycentricOf(bestPoint, c[0], c[1], c[2]).cast<float>();
    return true;
}

} // namespace morphogen
