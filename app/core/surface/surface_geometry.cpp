#include "core/surface/surface_geometry.hpp"

#include <atomic>
#include <cmath>

#include <Eigen/Geometry>

#include "core/mesh/edge_table.hpp"
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
    Sampler(const TriangleMesh& full, const MeshProjector& projector)
        : m_mesh(full), m_projector(projector), m_normals(areaWeightedVertexNormals(full)),
          m_curvature(vertexMeanCurvature(full, m_normals)) {}

    // The closest point of the full mesh.
    Projected at(const Eigen::Vector3f& p) const { return describe(m_projector.closest(p)); }

    // The nearest point of the full mesh along the line through p in `direction`,
    // within `reach`; the closest point if the line finds none.
    Projected along(const Eigen::Vector3f& p, const Eigen::Vector3f& direction, float reach) const {
        SurfacePoint s;
        if (!m_projector.alongLine(p, direction, reach, s))
            s = m_projector.closest(p);
        return describe(s);
    }

private:
    Projected describe(const SurfacePoint& s) const {
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

    const TriangleMesh& m_mesh;
    const MeshProjector& m_projector;
    std::vector<Eigen::Vector3f> m_normals;
    std::vector<float> m_curvature;
};

// Where a tile's points start before they are projected: on the simplified
// triangle, pushed out towards the surface by Phong tessellation (Boubekeur and
// Alexa 2008) with the full mesh's normals at the triangle's vertices. A planar
// point can lie far off a curved surface when the simplified triangles are as
// large as its features; its closest point then bunches up (or folds over) in
// concave places. The Phong point is much nearer. It then moves onto the full
// mesh along the Phong normal (the vertex normals interpolated), not to its
// closest point: on a piecewise flat mesh whose facets are larger than texels
// the closest-point map squeezes the wedge outside every convex crease onto
// the crease line (texels of zero area, a huge diffusion coefficient) and
// stretches the wedge inside a concave one, while a line along a smooth
// direction field crosses the facets smoothly. Points on a tile's border are computed from the
// border's two quad vertices in a fixed order (lower id first), so tiles sharing an edge compute
// bit-identical points and the surface drawn from the grid has no cracks.
struct StartPoint {
    Eigen::Vector3f position;
    Eigen::Vector3f direction; // unit, or zero where the normals cancel
};

class TilePoints {
public:
    TilePoints(const SurfaceTiles& tiles, const Sampler& sampler)
        : m_tiles(tiles), m_edges(tiles.simplified), m_nv(int(tiles.simplified.positions.size())),
          m_ne(int(m_edges.edgeCount())) {
        m_normals.reserve(tiles.simplified.positions.size());
        for (const Eigen::Vector3f& p : tiles.simplified.positions)
            m_normals.push_back(sampler.at(p).normal);
    }

    // Texel corner (i, j) of a tile, 0 <= i, j <= n.
    StartPoint corner(int tile, int n, int i, int j) const {
        const auto& q = m_tiles.quads[std::size_t(tile)];
        const std::uint32_t tri = m_tiles.tileTriangle[std::size_t(tile)];
        if (j == 0)
            return along(tri, q[0], q[1], i, n);
        if (i == n)
            return along(tri, q[1], q[2], j, n);
        if (j == n)
            return along(tri, q[3], q[2], i, n);
        if (i == 0)
            return along(tri, q[0], q[3], j, n);
        return inside(tile, float(i) / float(n), float(j) / float(n));
    }

    // The point (s, t) of a tile's square, bilinear on its quad.
    StartPoint inside(int tile, float s, float t) const {
        const auto& q = m_tiles.quads[std::size_t(tile)];
        const std::uint32_t tri = m_tiles.tileTriangle[std::size_t(tile)];
        const float w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
        Eigen::Vector3f planar = Eigen::Vector3f::Zero();
        Eigen::Vector3f bary = Eigen::Vector3f::Zero();
        for (int k = 0; k < 4; ++k) {
            planar += w[k] * m_tiles.quadVertices[std::size_t(q[k])];
            bary += w[k] * barycentric(tri, q[k]);
        }
        return phong(tri, planar, bary);
    }

private:
    static constexpr float kAlpha = 0.75f; // Boubekeur and Alexa's shape factor

    // k/n of the way from quad vertex a to quad vertex b, computed from the lower id.
    StartPoint along(std::uint32_t tri, int a, int b, int k, int n) const {
        if (a > b) {
            std::swap(a, b);
            k = n - k;
        }
        const Eigen::Vector3f& pa = m_tiles.quadVertices[std::size_t(a)];
        const Eigen::Vector3f& pb = m_tiles.quadVertices[std::size_t(b)];
        const float f = float(k) / float(n);
        const Eigen::Vector3f planar = k == 0   ? pa
                                       : k == n ? pb
                                                : Eigen::Vector3f(pa + f * (pb - pa));
        const Eigen::Vector3f bary =
            k == 0   ? barycentric(tri, a)
            : k == n ? barycentric(tri, b)
                     : Eigen::Vector3f((1 - f) * barycentric(tri, a) + f * barycentric(tri, b));
        return phong(tri, planar, bary);
    }

    // A quad vertex's barycentric coordinates in simplified triangle tri.
    Eigen::Vector3f barycentric(std::uint32_t tri, int id) const {
        const auto& t = m_tiles.simplified.triangles[tri];
        const auto slot = [&](std::uint32_t v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; };
        Eigen::Vector3f b = Eigen::Vector3f::Zero();
        if (id < m_nv) {
            b[slot(std::uint32_t(id))] = 1;
        } else if (id < m_nv + m_ne) {
            const std::size_t e = std::size_t(id - m_nv);
            b[slot(m_edges.lowVertex(e))] = 0.5f;
            b[slot(m_edges.highVertex(e))] = 0.5f;
        } else if (!m_tiles.splitBarycentric.empty()) {
            b = m_tiles.splitBarycentric[tri];
        } else {
            b.setConstant(1.0f / 3.0f);
        }
        return b;
    }

    StartPoint phong(std::uint32_t tri, const Eigen::Vector3f& p,
                     const Eigen::Vector3f& bary) const {
        const auto& t = m_tiles.simplified.triangles[tri];
        Eigen::Vector3f sum = Eigen::Vector3f::Zero();
        Eigen::Vector3f normal = Eigen::Vector3f::Zero();
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3f& x = m_tiles.simplified.positions[t[k]];
            const Eigen::Vector3f& nk = m_normals[t[k]];
            sum += bary[k] * Eigen::Vector3f(p - (p - x).dot(nk) * nk);
            normal += bary[k] * nk;
        }
        const float len = normal.norm();
        return {(1 - kAlpha) * p + kAlpha * sum,
                len > 1e-6f ? Eigen::Vector3f(normal / len) : Eigen::Vector3f::Zero()};
    }

    const SurfaceTiles& m_tiles;
    EdgeTable m_edges;
    int m_nv;
    int m_ne;
    std::vector<Eigen::Vector3f> m_normals; // the full mesh's, at the simplified vertices
};

// Texels of a tile's projected grid that are folded over or nearly collapsed:
// signed area (by the mean of their corners' normals) under 5% of the tile's
// mean texel area. They occur where a simplified triangle spans a feature
// smaller than itself.
int badTexels(const Eigen::Vector3f* grid, const Eigen::Vector3f* normals, int n) {
    double total = 0;
    std::vector<double> signedArea(std::size_t(n) * std::size_t(n));
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n; ++u) {
            const int c00 = v * (n + 1) + u, c10 = c00 + 1, c01 = c00 + n + 1, c11 = c01 + 1;
            const Eigen::Vector3f ju = 0.5f * ((grid[c10] - grid[c00]) + (grid[c11] - grid[c01]));
            const Eigen::Vector3f jv = 0.5f * ((grid[c01] - grid[c00]) + (grid[c11] - grid[c10]));
            const Eigen::Vector3f normal =
                normals[c00] + normals[c10] + normals[c01] + normals[c11];
            const Eigen::Vector3f cross = ju.cross(jv);
            signedArea[std::size_t(v * n + u)] = double(cross.dot(normal.normalized()));
            total += double(cross.norm());
        }
    const double floor = 0.05 * total / double(n * n);
    int bad = 0;
    for (double a : signedArea)
        bad += a <= floor ? 1 : 0;
    return bad;
}

// Untangles a tile with bad texels: its interior grid points move to the mean of
// their four neighbours and back onto the surface (along their mean normal),
// up to 2n sweeps or until no texel is bad. The border stays, so the tile still
// meets its neighbours point for point. Returns whether it changed anything.
bool untangle(Eigen::Vector3f* grid, Eigen::Vector3f* normals, int n, const Sampler& sampler,
              float reach) {
    if (badTexels(grid, normals, n) == 0)
        return false;
    const int w = n + 1;
    for (int sweep = 0; sweep < 2 * n; ++sweep) {
        for (int j = 1; j < n; ++j)
            for (int i = 1; i < n; ++i) {
                const int c = j * w + i;
                const Eigen::Vector3f mean =
                    0.25f * (grid[c - 1] + grid[c + 1] + grid[c - w] + grid[c + w]);
                const Eigen::Vector3f direction =
                    (normals[c - 1] + normals[c + 1] + normals[c - w] + normals[c + w])
                        .normalized();
                const Projected p = sampler.along(mean, direction, reach);
                grid[c] = p.position;
                normals[c] = p.normal;
            }
        if (badTexels(grid, normals, n) == 0)
            break;
    }
    return true;
}

} // namespace

void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const std::function<void(double)>& progress) {
    const MeshProjector projector(full);
    computeSurfaceGeometry(tiles, full, projector, progress);
}

void computeSurfaceGeometry(SurfaceTiles& tiles, const TriangleMesh& full,
                            const MeshProjector& projector,
                            const std::function<void(double)>& progress) {
    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize();
    const int tileCount = atlas.tileCount();
    const std::size_t corners = std::size_t(n + 1) * std::size_t(n + 1);
    const Sampler sampler(full, projector);
    const TilePoints points(tiles, sampler);
    // How far along its line a point may move onto the surface: half the simplified
    // mesh's mean edge (the same everywhere, so tiles sharing an edge agree).
    double edgeSum = 0;
    const EdgeTable coarseEdges(tiles.simplified);
    for (std::size_t e = 0; e < coarseEdges.edgeCount(); ++e)
        edgeSum += (tiles.simplified.positions[coarseEdges.highVertex(e)] -
                    tiles.simplified.positions[coarseEdges.lowVertex(e)])
                       .norm();
    const float reach =
        coarseEdges.edgeCount() > 0 ? float(0.5 * edgeSum / double(coarseEdges.edgeCount())) : 0.0f;

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
        Eigen::Vector3f* grid = &tiles.gridPositions[std::size_t(t) * corners];
        Eigen::Vector3f* gridN = &tiles.gridNormals[std::size_t(t) * corners];
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const StartPoint start = points.corner(t, n, i, j);
                const Projected p = sampler.along(start.position, start.direction, reach);
                grid[j * (n + 1) + i] = p.position;
                gridN[j * (n + 1) + i] = p.normal;
            }
        const bool smoothed = untangle(grid, gridN, n, sampler, reach);
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const std::uint32_t c = atlas.tileCell(t, u, v);
                const Eigen::Vector3f& c00 = grid[v * (n + 1) + u];
                const Eigen::Vector3f& c10 = grid[v * (n + 1) + u + 1];
                const Eigen::Vector3f& c01 = grid[(v + 1) * (n + 1) + u];
                const Eigen::Vector3f& c11 = grid[(v + 1) * (n + 1) + u + 1];
                // A smoothed tile's centres come from its corners, so the two agree.
                const StartPoint start =
                    smoothed ? StartPoint{0.25f * (c00 + c10 + c01 + c11),
                                          (gridN[v * (n + 1) + u] + gridN[v * (n + 1) + u + 1] +
                                           gridN[(v + 1) * (n + 1) + u] +
                                           gridN[(v + 1) * (n + 1) + u + 1])
                                              .normalized()}
                             : points.inside(t, (u + 0.5f) / float(n), (v + 0.5f) / float(n));
                const Projected p = sampler.along(start.position, start.direction, reach);
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
