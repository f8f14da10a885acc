#include "core/mesh/scan_sample.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

namespace morphogen {

namespace {

// Deterministic lattice noise in [-1, 1].
double latticeValue(int i, int j, int k) {
    std::uint32_t h =
        std::uint32_t(i) * 73856093u ^ std::uint32_t(j) * 19349663u ^ std::uint32_t(k) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return double(h & 0xffffffu) / double(0xffffffu) * 2 - 1;
}

double valueNoise(double x, double y, double z) {
    const int i = int(std::floor(x)), j = int(std::floor(y)), k = int(std::floor(z));
    const auto smooth = [](double t) { return t * t * (3 - 2 * t); };
    const double fx = smooth(x - i), fy = smooth(y - j), fz = smooth(z - k);
    double sum = 0;
    for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b)
            for (int c = 0; c < 2; ++c)
                sum += (a ? fx : 1 - fx) * (b ? fy : 1 - fy) * (c ? fz : 1 - fz) *
                       latticeValue(i + a, j + b, k + c);
    return sum;
}

double blobField(double x, double y, double z, double noise) {
    const double body = std::sqrt(x * x + y * y / 0.7 + z * z / 0.8) - 0.6;
    const double head = std::sqrt((x - 0.5) * (x - 0.5) + (y - 0.35) * (y - 0.35) + z * z) - 0.28;
    const auto ear = [&](double zc) {
        const double dx = x - 0.55, dy = y - 0.75, dz = z - zc;
        const double r = std::sqrt(dx * dx / 0.004 + dz * dz / 0.01);
        return std::max(r - 1.0, std::abs(dy) - 0.3) * 0.06;
    };
    const double d = std::min({body, head, ear(0.1), ear(-0.1)});
    return d + noise * (0.5 * valueNoise(9 * x, 9 * y, 9 * z) +
                        0.25 * valueNoise(40 * x, 40 * y, 40 * z));
}

} // namespace

TriangleMesh scanLikeMesh(int cells, double noise) {
    const double lo = -1.0, hi = 1.2, h = (hi - lo) / cells;
    const int m = cells + 1;
    const auto id = [m](int i, int j, int k) { return (std::size_t(i) * m + j) * m + k; };
    std::vector<double> value(std::size_t(m) * m * m);
    for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
            for (int k = 0; k < m; ++k)
                value[id(i, j, k)] = blobField(lo + i * h, lo + j * h, lo + k * h, noise);
    const auto pointOf = [&](std::size_t g) {
        const std::size_t i = g / (std::size_t(m) * m), j = (g / m) % m, k = g % m;
        return Eigen::Vector3d(lo + h * double(i), lo + h * double(j), lo + h * double(k));
    };

    TriangleMesh mesh;
    std::unordered_map<std::uint64_t, std::uint32_t> onEdge;
    const auto crossing = [&](std::size_t a, std::size_t b) {
        if (a > b)
            std::swap(a, b);
        const std::uint64_t key = std::uint64_t(a) << 32 | b;
        const auto found = onEdge.find(key);
        if (found != onEdge.end())
            return found->second;
        const double t = value[a] / (value[a] - value[b]);
        const Eigen::Vector3d p = pointOf(a) + t * (pointOf(b) - pointOf(a));
        mesh.positions.push_back(p.cast<float>());
        return onEdge[key] = std::uint32_t(mesh.positions.size() - 1);
    };
    // Wound so that the normal points away from `inside`, a grid point in the blob.
    const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::size_t inside) {
        const Eigen::Vector3d pa = mesh.positions[a].cast<double>();
        const Eigen::Vector3d n =
            (mesh.positions[b].cast<double>() - pa).cross(mesh.positions[c].cast<double>() - pa);
        if (n.dot(pointOf(inside) - pa) > 0)
            std::swap(b, c);
        mesh.triangles.push_back({a, b, c});
    };
    // Six tetrahedra round the cube's 0-6 diagonal: neighbouring cubes split
    // their shared faces alike, so the surface closes.
    static constexpr int kTetrahedra[6][4] = {{0, 5, 1, 6}, {0, 1, 2, 6}, {0, 2, 3, 6},
                                              {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}};
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j)
            for (int k = 0; k < cells; ++k) {
                const std::size_t corner[8] = {id(i, j, k),
                                               id(i + 1, j, k),
                                               id(i + 1, j + 1, k),
                                               id(i, j + 1, k),
                                               id(i, j, k + 1),
                                               id(i + 1, j, k + 1),
                                               id(i + 1, j + 1, k + 1),
                                               id(i, j + 1, k + 1)};
                for (const auto& tet : kTetrahedra) {
                    std::vector<std::size_t> in, out;
                    for (int v : tet)
                        (value[corner[v]] < 0 ? in : out).push_back(corner[v]);
                    if (in.size() == 1)
                        emit(crossing(in[0], out[0]), crossing(in[0], out[1]),
                             crossing(in[0], out[2]), in[0]);
                    else if (in.size() == 3)
                        emit(crossing(out[0], in[0]), crossing(out[0], in[1]),
                             crossing(out[0], in[2]), in[0]);
                    else if (in.size() == 2) {
                        const std::uint32_t a = crossing(in[0], out[0]),
                                            b = crossing(in[0], out[1]),
                                            c = crossing(in[1], out[1]),
                                            d = crossing(in[1], out[0]);
                        emit(a, b, c, in[0]);
                        emit(a, c, d, in[0]);
                    }
                }
            }
    return mesh;
}

} // namespace morphogen
