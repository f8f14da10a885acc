#include "core/surface/mesh_curvature.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/Sparse>

#include "core/mesh/edge_table.hpp"

namespace morphogen {

std::vector<Eigen::Vector3f> areaWeightedVertexNormals(const TriangleMesh& mesh) {
    std::vector<Eigen::Vector3d> sum(mesh.positions.size(), Eigen::Vector3d::Zero());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3d n = doubleAreaVector(mesh, t);
        for (std::uint32_t v : mesh.triangles[t])
            sum[v] += n;
    }
    std::vector<Eigen::Vector3f> normals(sum.size());
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const double len = sum[v].norm();
        normals[v] =
            len > 0 ? Eigen::Vector3f((sum[v] / len).cast<float>()) : Eigen::Vector3f(0, 0, 1);
    }
    return normals;
}

std::vector<float> vertexMeanCurvature(const TriangleMesh& mesh,
                                       const std::vector<Eigen::Vector3f>& normals) {
    const auto nv = Eigen::Index(mesh.positions.size());
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(12 * mesh.triangles.size());
    std::vector<double> mixedArea(mesh.positions.size(), 0.0);
    // A needle triangle's cotangents grow without bound; past this they add
    // noise, not curvature.
    constexpr double kMaxCot = 1e4;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        Eigen::Vector3d p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = mesh.positions[tri[k]].cast<double>();
        const double area2 = (p[1] - p[0]).cross(p[2] - p[0]).norm();
        if (!(area2 > 0))
            continue;
        double cot[3];
        bool obtuse[3];
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
            cot[k] = std::clamp(a.dot(b) / area2, -kMaxCot, kMaxCot);
            obtuse[k] = a.dot(b) < 0;
        }
        for (int k = 0; k < 3; ++k) {
            // The edge opposite corner k joins i and j; its weight is half the cotangent.
            const Eigen::Index i = tri[(k + 1) % 3], j = tri[(k + 2) % 3];
            const double w = 0.5 * cot[k];
            entries.emplace_back(i, j, w);
            entries.emplace_back(j, i, w);
            entries.emplace_back(i, i, -w);
            entries.emplace_back(j, j, -w);
        }
        const double area = 0.5 * area2;
        if (obtuse[0] || obtuse[1] || obtuse[2]) {
            for (int k = 0; k < 3; ++k)
                mixedArea[tri[k]] += obtuse[k] ? area / 2 : area / 4;
        } else {
            // Voronoi region: corner k gets 1/8 (|e_kj|^2 cot(opposite) + |e_kl|^2 cot(...)).
            for (int k = 0; k < 3; ++k) {
                const int j = (k + 1) % 3, l = (k + 2) % 3;
                mixedArea[tri[k]] +=
                    ((p[j] - p[k]).squaredNorm() * cot[l] + (p[l] - p[k]).squaredNorm() * cot[j]) /
                    8;
            }
        }
    }
    Eigen::SparseMatrix<double> laplacian(nv, nv);
    laplacian.setFromTriplets(entries.begin(), entries.end());
    Eigen::MatrixX3d x(nv, 3);
    for (Eigen::Index v = 0; v < nv; ++v)
        x.row(v) = mesh.positions[std::size_t(v)].cast<double>().transpose();
    const Eigen::MatrixX3d lx = laplacian * x;

    // Boundary vertices: the ends of edges used by one triangle.
    const EdgeTable edges(mesh);
    std::vector<char> boundary(mesh.positions.size(), 0);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e)
        if (edges.useCount(e) == 1)
            boundary[edges.lowVertex(e)] = boundary[edges.highVertex(e)] = 1;

    std::vector<float> h(mesh.positions.size(), 0.0f);
    for (Eigen::Index v = 0; v < nv; ++v) {
        if (boundary[std::size_t(v)] || !(mixedArea[std::size_t(v)] > 0))
            continue;
        const Eigen::Vector3d lb = lx.row(v).transpose() / mixedArea[std::size_t(v)];
        const double magnitude = 0.5 * lb.norm();
        h[std::size_t(v)] =
            float(lb.dot(normals[std::size_t(v)].cast<double>()) > 0 ? -magnitude : magnitude);
    }
    std::vector<double> sum(mesh.positions.size(), 0.0);
    std::vector<int> count(mesh.positions.size(), 0);
    for (std::size_t e = 0; e < edges.edgeCount(); ++e) {
        const std::uint32_t a = edges.lowVertex(e), b = edges.highVertex(e);
        if (boundary[a] && !boundary[b]) {
            sum[a] += h[b];
            ++count[a];
        }
        if (boundary[b] && !boundary[a]) {
            sum[b] += h[a];
            ++count[b];
        }
    }
    for (std::size_t v = 0; v < h.size(); ++v)
        if (boundary[v])
            h[v] = count[v] > 0 ? float(sum[v] / count[v]) : 0.0f;
    return h;
}

} // namespace morphogen
