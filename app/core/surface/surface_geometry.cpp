#include "core/surface/surface_geometry.hpp"

#include <atomic>
#include <cmath>

#include <Eigen/Geometry>

#include "core/surface/mesh_curvature.hpp"
#include "core/surface/mesh_projector.hpp"

namespace morphogen {

namespace {

struct Projected {
    Eigen::Vector3f position;
    Eigen::Vector3f normal;
    float curvature;
};

class Sampler {
public:
    explicit Sampler(const TriangleMesh& full)
        : m_mesh(full), m_projector(full), m_normals(areaWeightedVertexNormals(full)),
          m_curvature(vertexMeanCurvature(full, m_normals)) {}

    Projected at(const Eigen::Vector3f& p) const {
        const SurfacePoint s = m_projector.closest(p);
        const auto& tri = m_mesh.triangles[s.triangle];
        Eigen::Vector3f n = Eigen::Vector3f::Zero();
        float h = 0;
        for (int k = 0; k < 3; ++k) {
            n += s.barycentric[k] * m_normals[tri[k]];
            h += s.barycentric[k] * m_curvature[tri[k]];
        }
        // Opposite normals across a sharp crease can cancel; the face's own normal then.
        if (n.norm() < 1e-6f)
            n = doubleAreaVector(m_mesh, s.triangle).cast<float>();
        const float len = n.norm();
        return {s.position, len > 0 ? Eigen::Vector3f(n / len) : Eigen::Vector3f(0, 0, 1), h};
    }

private:
    const TriangleMesh& m_mesh;
    MeshProjector m_projector;
    std::vector<Eigen::Vector3f> m_normals;
    std::vector<float> m_curvature;
};

Eigen::Vector3f bilinear(const SurfaceTiles& tiles, const std::array<int, 4>& q, float s, float t) {
    return (1 - s) * (1 - t) * tiles.quadVertices[q[0]] + s * (1 - t) * tiles.quadVertices[q[1]] +
           s * t * tiles.quadVertices[q[2]] + (1 - s) * t * tiles.quadVertices[q[3]];
}

// The planar point of texel corner (i, j) of a quad. Corners on the quad's
// border are interpolated along the edge from its lower vertex id to the
// higher, so the two tiles sharing an edge compute bit-identical points (and
// therefore the same projections).
Eigen::Vector3f planarCorner(const SurfaceTiles& tiles, const std::array<int, 4>& q, int n, int i,
                             int j) {
    const auto along = [&](int a, int b, int k) -> Eigen::Vector3f {
        // k/n of the way from quad vertex a to quad vertex b.
        if (a > b) {
            std::swap(a, b);
            k = n - k;
        }
        if (k == 0)
            return tiles.quadVertices[a];
        if (k == n)
            return tiles.quadVertices[b];
        const float f = float(k) / float(n);
        return tiles.quadVertices[a] + f * (tiles.quadVertices[b] - tiles.quadVertices[a]);
    };
    if (j == 0)
        return along(q[0], q[1], i);
    if (i == n)
        return along(q[1], q[2], j);
    if (j == n)
        return along(q[3], q[2], i);
    if (i == 0)
        return along(q[0], q[3], j);
    return bilinear(tiles, q, float(i) / float(n), float(j) / float(n));
}

} // namespace

void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const std::function<void(double)>& progress) {
    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize();
    const int tileCount = atlas.tileCount();
    const std::size_t corners = std::size_t(n + 1) * std::size_t(n + 1);
    const Sampler sampler(full);

    tiles.gridPositions.assign(std::size_t(tileCount) * corners, Eigen::Vector3f::Zero());
    tiles.gridNormals.assign(tiles.gridPositions.size(), Eigen::Vector3f::Zero());
    const std::size_t cells = atlas.cellCount();
    tiles.texelPositions.assign(cells, Eigen::Vector3f::Zero());
    tiles.texelNormals.assign(cells, Eigen::Vector3f::Zero());
    tiles.jacobianU.assign(cells, Eigen::Vector3f::Zero());
    tiles.jacobianV.assign(cells, Eigen::Vector3f::Zero());
    tiles.texelArea.assign(cells, 0.0f);
    tiles.meanCurvature.assign(cells, 0.0f);
    tiles.surfaceArea = surfaceArea(full);

    std::atomic<int> done{0};
#pragma omp parallel for schedule(dynamic, 4)
    for (int t = 0; t < tileCount; ++t) {
        const auto& q = tiles.quads[std::size_t(t)];
        Eigen::Vector3f* grid = &tiles.gridPositions[std::size_t(t) * corners];
        Eigen::Vector3f* gridN = &tiles.gridNormals[std::size_t(t) * corners];
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const Projected p = sampler.at(planarCorner(tiles, q, n, i, j));
                grid[j * (n + 1) + i] = p.position;
                gridN[j * (n + 1) + i] = p.normal;
            }
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const std::uint32_t c = atlas.tileCell(t, u, v);
                const Projected p =
                    sampler.at(bilinear(tiles, q, (u + 0.5f) / float(n), (v + 0.5f) / float(n)));
                const Eigen::Vector3f& c00 = grid[v * (n + 1) + u];
                const Eigen::Vector3f& c10 = grid[v * (n + 1) + u + 1];
                const Eigen::Vector3f& c01 = grid[(v + 1) * (n + 1) + u];
                const Eigen::Vector3f& c11 = grid[(v + 1) * (n + 1) + u + 1];
                const Eigen::Vector3f ju = 0.5f * ((c10 - c00) + (c11 - c01));
                const Eigen::Vector3f jv = 0.5f * ((c01 - c00) + (c11 - c10));
                tiles.texelPositions[c] = p.position;
                tiles.texelNormals[c] = p.normal;
                tiles.jacobianU[c] = ju;
                tiles.jacobianV[c] = jv;
                tiles.texelArea[c] = ju.cross(jv).norm();
                tiles.meanCurvature[c] = p.curvature;
            }
        const int finished = ++done;
        if (progress && (finished % 64 == 0 || finished == tileCount)) {
#pragma omp critical(morphogen_surface_progress)
            progress(double(finished) / tileCount);
        }
    }
}

} // namespace morphogen
