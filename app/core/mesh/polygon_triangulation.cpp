#include "core/mesh/polygon_triangulation.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace morphogen {

namespace {

std::vector<std::array<int, 3>> fan(int n) {
    std::vector<std::array<int, 3>> triangles;
    for (int k = 1; k + 1 < n; ++k)
        triangles.push_back({0, k, k + 1});
    return triangles;
}

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Whether p lies inside or on triangle abc (counter-clockwise).
bool inTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c) {
    return cross2(b - a, p - a) >= 0 && cross2(c - b, p - b) >= 0 && cross2(a - c, p - c) >= 0;
}

} // namespace

std::vector<std::array<int, 3>> triangulatePolygon(const std::vector<Eigen::Vector3f>& corners) {
    const int n = int(corners.size());
    if (n <= 3)
        return fan(n);
    // Newell's normal: the polygon's plane, and its winding in that plane.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d a = corners[std::size_t(i)].cast<double>();
        const Eigen::Vector3d b = corners[std::size_t((i + 1) % n)].cast<double>();
        normal +=
            Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                            (a.x() - b.x()) * (a.y() + b.y()));
    }
    if (!(normal.norm() > 0))
        return fan(n);
    normal.normalize();
    const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
    // In the plane, the polygon runs counter-clockwise (Newell's normal points
    // to the side it is wound about).
    std::vector<Eigen::Vector2d> p(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d c = corners[std::size_t(i)].cast<double>();
        p[std::size_t(i)] = {c.dot(u), c.dot(v)};
    }
    std::vector<int> left(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        left[std::size_t(i)] = i;
    std::vector<std::array<int, 3>> triangles;
    int guard = 0;
    while (left.size() > 3) {
        const std::size_t m = left.size();
        bool clipped = false;
        for (std::size_t i = 0; i < m && !clipped; ++i) {
            const int ia = left[(i + m - 1) % m], ib = left[i], ic = left[(i + 1) % m];
            const Eigen::Vector2d &a = p[std::size_t(ia)], &b = p[std::size_t(ib)],
                                  &c = p[std::size_t(ic)];
            if (cross2(b - a, c - b) <= 0)
                continue; // a reflex (or straight) corner is no ear
            bool empty = true;
            for (std::size_t k = 0; k < m && empty; ++k) {
                const int j = left[k];
                if (j == ia || j == ib || j == ic)
                    continue;
                empty = !inTriangle(p[std::size_t(j)], a, b, c);
            }
            if (!empty)
                continue;
            triangles.push_back({ia, ib, ic});
            left.erase(left.begin() + std::ptrdiff_t(i));
            clipped = true;
        }
        if (!clipped || ++guard > n)
            return fan(n); // not a simple polygon
    }
    triangles.push_back({left[0], left[1], left[2]});
    return triangles;
}

} // namespace morphogen
