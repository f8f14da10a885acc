#include "core/mesh/mesh_samples.hpp"
#include "core/mesh/scan_sample.hpp"

#include <cmath>
#include <map>
#include <utility>

#include "core/base/errors.hpp"

namespace morphogen {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTorusRadius = 1.0;
constexpr double kTubeRadius = 0.4;

using Vec3 = Eigen::Vector3d;

struct QuadMesh {
    std::vector<Vec3> points;
    std::vector<std::array<std::uint32_t, 4>> quads;
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

// One round of Catmull-Clark on a closed quad mesh: new points are the old
// vertices, then one per edge, then one per face; each quad becomes four with
// its winding.
QuadMesh catmullClark(const QuadMesh& in) {
    const std::size_t nv = in.points.size(), nf = in.quads.size();
    std::map<std::uint64_t, std::uint32_t> edgeIds;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edgeEnds;
    std::vector<std::vector<std::uint32_t>> edgeFaces;
    std::vector<std::array<std::uint32_t, 4>> faceEdges(nf);
    for (std::size_t f = 0; f < nf; ++f)
        for (int k = 0; k < 4; ++k) {
            const std::uint32_t a = in.quads[f][k], b = in.quads[f][(k + 1) % 4];
            const auto [it, added] = edgeIds.emplace(edgeKey(a, b), edgeEnds.size());
            if (added) {
                edgeEnds.emplace_back(a, b);
                edgeFaces.emplace_back();
            }
            edgeFaces[it->second].push_back(std::uint32_t(f));
            faceEdges[f][k] = it->second;
        }
    const std::size_t ne = edgeEnds.size();

    std::vector<Vec3> facePoints(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        Vec3 sum = Vec3::Zero();
        for (std::uint32_t v : in.quads[f])
            sum += in.points[v];
        facePoints[f] = sum / 4.0;
    }
    QuadMesh out;
    out.points.resize(nv + ne + nf);
    std::vector<Vec3> faceSum(nv, Vec3::Zero()), midSum(nv, Vec3::Zero());
    std::vector<int> valence(nv, 0);
    for (std::size_t e = 0; e < ne; ++e) {
        const auto [a, b] = edgeEnds[e];
        const Vec3 f = (facePoints[edgeFaces[e][0]] + facePoints[edgeFaces[e][1]]) / 2.0;
        const Vec3 mid = (in.points[a] + in.points[b]) / 2.0;
        out.points[nv + e] = (mid + f) / 2.0;
        for (std::uint32_t v : {a, b}) {
            midSum[v] += mid;
            ++valence[v];
        }
    }
    for (std::size_t f = 0; f < nf; ++f)
        for (std::uint32_t v : in.quads[f])
            faceSum[v] += facePoints[f];
    for (std::size_t v = 0; v < nv; ++v) {
        const double n = valence[v];
        // (F + 2R + (n - 3) P) / n with F, R the averages of the face points and edge midpoints.
        out.points[v] = (faceSum[v] / n + 2.0 * midSum[v] / n + (n - 3.0) * in.points[v]) / n;
    }
    for (std::size_t f = 0; f < nf; ++f) {
        out.points[nv + ne + f] = facePoints[f];
        const std::uint32_t centre = std::uint32_t(nv + ne + f);
        for (int k = 0; k < 4; ++k)
            out.quads.push_back({in.quads[f][k], std::uint32_t(nv + faceEdges[f][k]), centre,
                                 std::uint32_t(nv + faceEdges[f][(k + 3) % 4])});
    }
    return out;
}

// Each quad as two triangles, split along its shorter diagonal.
TriangleMesh triangulate(const QuadMesh& q) {
    TriangleMesh mesh;
    for (const Vec3& p : q.points)
        mesh.positions.push_back(p.cast<float>());
    for (const auto& quad : q.quads) {
        const auto [a, b, c, d] = quad;
        if ((q.points[a] - q.points[c]).squaredNorm() <=
            (q.points[b] - q.points[d]).squaredNorm()) {
            mesh.triangles.push_back({a, b, c});
            mesh.triangles.push_back({a, c, d});
        } else {
            mesh.triangles.push_back({a, b, d});
            mesh.triangles.push_back({b, c, d});
        }
    }
    return mesh;
}

Vec3 torusPoint(double u, double v) {
    return Vec3((kTorusRadius + kTubeRadius * std::cos(v)) * std::cos(u),
                (kTorusRadius + kTubeRadius * std::cos(v)) * std::sin(u),
                kTubeRadius * std::sin(v));
}

void checkDetail(const std::string& name, int detail, int low, int high) {
    if (detail < low || detail > high)
        throw InputError("mesh-gen " + name + ": --detail " + std::to_string(detail) +
                         " is outside " + std::to_string(low) + ".." + std::to_string(high));
}

} // namespace

TriangleMesh icosphere(int level) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& p : points)
        p.normalize();
    std::vector<std::array<std::uint32_t, 3>> tris = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < level; ++l) {
        std::map<std::uint64_t, std::uint32_t> midpoints;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto [it, added] = midpoints.emplace(edgeKey(a, b), points.size());
            if (added)
                points.push_back((points[a] + points[b]).normalized());
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> next;
        for (const auto& [a, b, c] : tris) {
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.push_back({a, ab, ca});
            next.push_back({b, bc, ab});
            next.push_back({c, ca, bc});
            next.push_back({ab, bc, ca});
        }
        tris = std::move(next);
    }
    TriangleMesh mesh;
    for (const Vec3& p : points)
        mesh.positions.push_back(p.cast<float>());
    mesh.triangles = std::move(tris);
    return mesh;
}

TriangleMesh torus(int ring) {
    const int tube = ring / 2;
    TriangleMesh mesh;
    for (int j = 0; j < tube; ++j)
        for (int i = 0; i < ring; ++i)
            mesh.positions.push_back(
                torusPoint(2 * kPi * i / ring, 2 * kPi * j / tube).cast<float>());
    auto id = [&](int i, int j) { return std::uint32_t((j % tube) * ring + i % ring); };
    // (u, v) -> (i, j): d/du x d/dv points out of the tube, so this winding is outward.
    for (int j = 0; j < tube; ++j)
        for (int i = 0; i < ring; ++i) {
            mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return mesh;
}

TriangleMesh torusWithSeams(int ring, MeshAttributes& attributes) {
    const int tube = ring / 2;
    const TriangleMesh closed = torus(ring);
    TriangleMesh mesh;
    attributes = {};
    for (int j = 0; j <= tube; ++j)
        for (int i = 0; i <= ring; ++i) {
            // The seam copies take the position of the vertex they copy, bit for bit.
            mesh.positions.push_back(closed.positions[std::size_t((j % tube) * ring + i % ring)]);
            const double u = 2 * kPi * i / ring, v = 2 * kPi * j / tube;
            attributes.normals.emplace_back(float(std::cos(v) * std::cos(u)),
                                            float(std::cos(v) * std::sin(u)), float(std::sin(v)));
            attributes.texcoords.emplace_back(float(i) / float(ring), float(j) / float(tube));
        }
    auto id = [&](int i, int j) { return std::uint32_t(j * (ring + 1) + i); };
    for (int j = 0; j < tube; ++j)
        for (int i = 0; i < ring; ++i) {
            mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return mesh;
}

TriangleMesh holes(int levels) {
    // Cells of a 7 x 3 grid; cells (1, 1), (3, 1) and (5, 1) are the holes.
    constexpr int nx = 7, ny = 3;
    constexpr double halfThickness = 0.6;
    auto solid = [](int i, int j) {
        return i >= 0 && i < nx && j >= 0 && j < ny && !(j == 1 && i % 2 == 1);
    };
    QuadMesh cage;
    auto vertex = [](int i, int j, bool top) {
        return std::uint32_t((top ? 0 : (nx + 1) * (ny + 1)) + j * (nx + 1) + i);
    };
    for (int top = 1; top >= 0; --top)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i)
                cage.points.emplace_back(i - nx / 2.0, j - ny / 2.0,
                                         top ? halfThickness : -halfThickness);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            if (!solid(i, j))
                continue;
            // Counter-clockwise seen from +z on top, the other way round below.
            const std::array<std::array<int, 2>, 4> corners = {
                {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};
            cage.quads.push_back({vertex(i, j, true), vertex(i + 1, j, true),
                                  vertex(i + 1, j + 1, true), vertex(i, j + 1, true)});
            cage.quads.push_back({vertex(i, j + 1, false), vertex(i + 1, j + 1, false),
                                  vertex(i + 1, j, false), vertex(i, j, false)});
            // A wall where the neighbour across a side is empty (outside or a hole):
            // it runs along the top edge against the top face's direction.
            const std::array<std::array<int, 2>, 4> across = {
                {{i, j - 1}, {i + 1, j}, {i, j + 1}, {i - 1, j}}};
            for (int k = 0; k < 4; ++k) {
                if (solid(across[k][0], across[k][1]))
                    continue;
                const auto [ax, ay] = corners[k];
                const auto [bx, by] = corners[(k + 1) % 4];
                cage.quads.push_back({vertex(bx, by, true), vertex(ax, ay, true),
                                      vertex(ax, ay, false), vertex(bx, by, false)});
            }
        }
    for (int l = 0; l < levels; ++l)
        cage = catmullClark(cage);
    return triangulate(cage);
}

TriangleMesh blob(int level) {
    TriangleMesh mesh = icosphere(level);
    struct Lobe {
        Vec3 direction;
        double amplitude, width;
    };
    const Lobe lobes[] = {
        {Vec3(1, 0.5, 0).normalized(), 0.6, 0.06},        // head
        {Vec3(-1, 0.3, 0).normalized(), 0.7, 0.02},       // tail
        {Vec3(0.5, -0.85, 0.4).normalized(), 0.9, 0.025}, // legs
        {Vec3(0.5, -0.85, -0.4).normalized(), 0.9, 0.025},
        {Vec3(-0.5, -0.85, 0.4).normalized(), 0.9, 0.025},
        {Vec3(-0.5, -0.85, -0.4).normalized(), 0.9, 0.025},
    };
    const Vec3 body(1.3, 0.7, 0.6);
    for (Eigen::Vector3f& p : mesh.positions) {
        const Vec3 d = p.cast<double>().normalized();
        double r =
            1.0 + 0.03 * std::sin(7 * d.x()) * std::sin(5 * d.y() + 1) * std::sin(6 * d.z() + 2);
        for (const Lobe& lobe : lobes)
            r += lobe.amplitude * std::exp((d.dot(lobe.direction) - 1.0) / lobe.width);
        p = (r * d).cwiseProduct(body).cast<float>();
    }
    return mesh;
}

const std::vector<SampleKind>& sampleKinds() {
    static const std::vector<SampleKind> kinds = {
        {"sphere", 4, "subdivision level of the icosahedron (20 * 4^level triangles)"},
        {"torus", 64, "segments around the ring, half as many around the tube"},
        {"holes", 3, "Catmull-Clark rounds on the cage (136 * 4^rounds triangles)"},
        {"blob", 4, "subdivision level of its icosphere (20 * 4^level triangles)"},
        {"scan", 60, "cells per side of the marching tetrahedra (60: about 30k triangles)"},
    };
    return kinds;
}

TriangleMesh sampleMesh(const std::string& name, int detail) {
    for (const SampleKind& kind : sampleKinds())
        if (name == kind.name) {
            if (detail <= 0)
                detail = kind.detail;
            if (name == "sphere" || name == "blob") {
                checkDetail(name, detail, 0, 8);
                return name == "sphere" ? icosphere(detail) : blob(detail);
            }
            if (name == "scan") {
                checkDetail(name, detail, 8, 160);
                return scanLikeMesh(detail, 0.02);
            }
            if (name == "torus") {
                checkDetail(name, detail, 6, 2000);
                return torus(detail);
            }
            checkDetail(name, detail, 0, 7);
            return holes(detail);
        }
    std::string names;
    for (const SampleKind& kind : sampleKinds())
        names += (names.empty() ? "" : ", ") + std::string(kind.name);
    throw InputError("mesh-gen: unknown kind '" + name + "' (accepted: " + names + ")");
}

} // namespace morphogen
