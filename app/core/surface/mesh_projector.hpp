#pragma once

#include <cstdint>
#include <memory>

#include <Eigen/Core>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// The point of a mesh nearest to a query point, and where it lies: the
// triangle and the barycentric weights of its three vertices (in the
// triangle's vertex order, each in [0, 1], summing to 1).
struct SurfacePoint {
    Eigen::Vector3f position = Eigen::Vector3f::Zero();
    std::uint32_t triangle = 0;
    Eigen::Vector3f barycentric = Eigen::Vector3f(1, 0, 0);
};

// Closest-point queries on a fixed triangle mesh: CGAL's AABB tree, built once
// (O(F log F)); each query is O(log F) on a well-shaped mesh. closest() is
// safe to call from several threads at once (the tree and its search hints
// are built in the constructor, queries only read them); so is alongLine(). The mesh must have
// at least one triangle and outlive nothing: the projector keeps a copy.
class MeshProjector {
public:
    explicit MeshProjector(const TriangleMesh& mesh);
    ~MeshProjector();
    MeshProjector(const MeshProjector&) = delete;
    MeshProjector& operator=(const MeshProjector&) = delete;

    SurfacePoint closest(const Eigen::Vector3f& query) const;

    // The nearest point of the mesh on the line through `origin` along
    // `direction` (either way), if one lies within maxDistance of the origin.
    // Returns false (out untouched) when the line misses the mesh within that
    // distance or only grazes it (runs inside a triangle's plane).
    bool alongLine(const Eigen::Vector3f& origin, const Eigen::Vector3f& direction,
                   float maxDistance, SurfacePoint& out) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace morphogen
