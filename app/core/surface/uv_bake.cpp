#include "core/surface/uv_bake.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/domain/atlas.hpp"

namespace morphogen {

namespace {

// The used texels of the tiled surface in a uniform grid, for the nearest
// one to a point.
class TexelGrid {
public:
    TexelGrid(const SurfaceTiles& tiles) : m_tiles(tiles) {
        const Atlas& atlas = *tiles.atlas;
        std::size_t used = 0;
        Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
        Eigen::Vector3f hi = -lo;
        for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
            if (atlas.used(i)) {
                lo = lo.cwiseMin(tiles.texelPositions[i]);
                hi = hi.cwiseMax(tiles.texelPositions[i]);
                ++used;
            }
        if (used == 0)
            throw std::invalid_argument("bakeIntoUvs: the tiled surface has no texels");
        m_origin = lo.cast<double>();
        // About two texels a cell: a few texels in each.
        m_cell = std::max(2.0 * std::sqrt(tiles.surfaceArea / double(used)),
                          1e-9 * double((hi - lo).norm()) + 1e-30);
        for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
            if (atlas.used(i))
                m_cells[key(cellOf(tiles.texelPositions[i]))].push_back(i);
        const std::array<long long, 3> top = cellOf(hi);
        m_extent = std::max({top[0], top[1], top[2]}) + 1;
    }

    // Up to kSamples used texels nearest to p among those whose normal faces
    // along `normal` (dot > 0), nearest first, as (squared distance, cell);
    // where none faces that way near, the nearest of any facing.
    static constexpr std::size_t kSamples = 12;
    using Sample = std::pair<double, std::uint32_t>;
    std::vector<Sample> nearest(const Eigen::Vector3f& p, const Eigen::Vector3f& normal) const {
        const std::array<long long, 3> c = cellOf(p);
        std::vector<Sample> facing;
        Sample any{std::numeric_limits<double>::max(), UINT32_MAX};
        const auto keep = [&](double d, std::uint32_t i) {
            if (facing.size() == kSamples && d >= facing.back().first)
                return;
            facing.insert(std::upper_bound(facing.begin(), facing.end(), Sample{d, i}),
                          Sample{d, i});
            if (facing.size() > kSamples)
                facing.pop_back();
        };
        for (long long ring = 0; ring <= m_extent + 1; ++ring) {
            for (long long dx = -ring; dx <= ring; ++dx)
                for (long long dy = -ring; dy <= ring; ++dy)
                    for (long long dz = -ring; dz <= ring; ++dz) {
                        if (std::max({std::llabs(dx), std::llabs(dy), std::llabs(dz)}) != ring)
                            continue; // the shell of this ring only
                        const auto it = m_cells.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
                        if (it == m_cells.end())
                            continue;
                        for (std::uint32_t i : it->second) {
                            const double d = (m_tiles.texelPositions[i] - p).squaredNorm();
                            if (d < any.first)
                                any = {d, i};
                            if (m_tiles.texelNormals[i].dot(normal) > 0)
                                keep(d, i);
                        }
                    }
            // Every texel closer than this ring's inner distance has been seen.
            const double seen = double(ring) * m_cell;
            if (facing.size() == kSamples && facing.back().first <= seen * seen)
                return facing;
            // Far past the nearest texel of any facing: what was found will do
            // (a surface seen edge-on, or fewer texels than kSamples).
            if (any.second != UINT32_MAX && seen > 2.0 * std::sqrt(any.first) + 2.0 * m_cell)
                break;
        }
        if (facing.empty() && any.second != UINT32_MAX)
            facing.push_back(any);
        return facing;
    }

    // About the spacing of neighbouring texels.
    double spacing() const { return m_cell / 2; }

private:
    std::array<long long, 3> cellOf(const Eigen::Vector3f& p) const {
        const Eigen::Vector3d c = (p.cast<double>() - m_origin) / m_cell;
        return {(long long)std::floor(c.x()), (long long)std::floor(c.y()),
                (long long)std::floor(c.z())};
    }
    static std::uint64_t key(const std::array<long long, 3>& c) {
        return (std::uint64_t(c[0]) * 73856093u) ^ (std::uint64_t(c[1]) * 19349663u) ^
               (std::uint64_t(c[2]) * 83492791u);
    }

    const SurfaceTiles& m_tiles;
    Eigen::Vector3d m_origin;
    double m_cell = 1;
    long long m_extent = 0;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;
};

// Per vertex: the normal (area-weighted over the triangles at its position,
// so UV seams do not crease the shading) and glTF's tangent from the UVs'
// derivatives (Lengyel's method), orthogonalised against the normal.
void vertexFrames(const UvMesh& mesh, std::vector<Eigen::Vector3f>& normals,
                  std::vector<Eigen::Vector4f>& tangents) {
    const std::size_t n = mesh.positions.size();
    std::map<std::array<float, 3>, Eigen::Vector3f> byPosition;
    std::vector<Eigen::Vector3f> tan1(n, Eigen::Vector3f::Zero()), tan2(n, Eigen::Vector3f::Zero());
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3f &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                              &p2 = mesh.positions[t[2]];
        const Eigen::Vector3f faceNormal = (p1 - p0).cross(p2 - p0); // |.| = twice the area
        for (std::uint32_t v : t) {
            const Eigen::Vector3f& p = mesh.positions[v];
            auto [it, added] = byPosition.emplace(std::array<float, 3>{p.x(), p.y(), p.z()},
                                                  Eigen::Vector3f::Zero());
            it->second += faceNormal;
        }
        const Eigen::Vector2f &w0 = mesh.uvs[t[0]], &w1 = mesh.uvs[t[1]], &w2 = mesh.uvs[t[2]];
        const Eigen::Vector3f e1 = p1 - p0, e2 = p2 - p0;
        const float du1 = w1.x() - w0.x(), dv1 = w1.y() - w0.y();
        const float du2 = w2.x() - w0.x(), dv2 = w2.y() - w0.y();
        const float det = du1 * dv2 - du2 * dv1;
        if (std::abs(det) < 1e-20f)
            continue;
        const Eigen::Vector3f sdir = (e1 * dv2 - e2 * dv1) / det;
        const Eigen::Vector3f tdir = (e2 * du1 - e1 * du2) / det;
        for (std::uint32_t v : t) {
            tan1[v] += sdir;
            tan2[v] += tdir;
        }
    }
    normals.resize(n);
    tangents.resize(n);
    for (std::size_t v = 0; v < n; ++v) {
        const Eigen::Vector3f& p = mesh.positions[v];
        Eigen::Vector3f nv = byPosition[{p.x(), p.y(), p.z()}];
        nv = nv.norm() > 0 ? nv.normalized() : Eigen::Vector3f::UnitZ();
        normals[v] = nv;
        Eigen::Vector3f t = tan1[v] - nv * nv.dot(tan1[v]);
        if (!(t.norm() > 1e-12f))
            t = nv.unitOrthogonal();
        t.normalize();
        // The bitangent w * cross(n, t) runs along -v, up the image: glTF's
        // "+Y is up" for normal textures, and the frame MikkTSpace builds from
        // the UVs where TANGENT is ignored (Blender's importer).
        const float w = nv.cross(t).dot(tan2[v]) < 0 ? 1.0f : -1.0f;
        tangents[v] = Eigen::Vector4f(t.x(), t.y(), t.z(), w);
    }
}

} // namespace

bool bakeableUvs(const UvMesh& mesh) {
    return std::all_of(mesh.uvs.begin(), mesh.uvs.end(), [](const Eigen::Vector2f& uv) {
        return uv.allFinite() && uv.x() >= -1e-4f && uv.x() <= 1.0001f && uv.y() >= -1e-4f &&
               uv.y() <= 1.0001f;
    });
}

UvTexels sampleIntoUvs(const UvMesh& mesh, const SurfaceTiles& tiles, const SurfaceColours& colours,
                       const UvBakeOptions& options, const std::vector<float>* value) {
    if (mesh.uvs.size() != mesh.positions.size() || options.size < 1 || options.padding < 0)
        throw std::invalid_argument("sampleIntoUvs: inconsistent mesh or options");
    const Atlas& atlas = *tiles.atlas;
    if (colours.colours.size() != atlas.cellCount() || colours.height.size() != atlas.cellCount() ||
        (value && value->size() != atlas.cellCount()))
        throw std::invalid_argument("sampleIntoUvs: colours do not match the atlas");
    const int size = options.size;
    const std::size_t texels = std::size_t(size) * std::size_t(size);
    UvTexels out;
    out.size = size;
    out.colour.assign(texels, {0, 0, 0, 0});
    out.height.assign(texels, 0.0f);
    if (value)
        out.value.assign(texels, 0.0f);
    out.worldPerTexel.assign(texels, 0.0f);
    out.covered.assign(texels, 0);
    const TexelGrid grid(tiles);

    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3f &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                              &p2 = mesh.positions[t[2]];
        const Eigen::Vector2d a = mesh.uvs[t[0]].cast<double>() * size;
        const Eigen::Vector2d b = mesh.uvs[t[1]].cast<double>() * size;
        const Eigen::Vector2d c = mesh.uvs[t[2]].cast<double>() * size;
        const double area = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
        if (std::abs(area) < 1e-12)
            continue;
        const Eigen::Vector3f faceNormal = (p1 - p0).cross(p2 - p0);
        const float scale =
            float(std::sqrt(0.5 * double(faceNormal.norm()) / (0.5 * std::abs(area))));
        const int x0 = std::max(0, int(std::floor(std::min({a.x(), b.x(), c.x()}))));
        const int x1 = std::min(size - 1, int(std::ceil(std::max({a.x(), b.x(), c.x()}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y(), b.y(), c.y()}))));
        const int y1 = std::min(size - 1, int(std::ceil(std::max({a.y(), b.y(), c.y()}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const Eigen::Vector2d q(x + 0.5, y + 0.5);
                // Barycentric weights; a texel centre on a shared edge counts for both.
                const double l1 = ((q - a).x() * (c - a).y() - (q - a).y() * (c - a).x()) / area;
                const double l2 = ((b - a).x() * (q - a).y() - (b - a).y() * (q - a).x()) / area;
                const double l0 = 1.0 - l1 - l2;
                constexpr double kEdge = -1e-9;
                if (l0 < kEdge || l1 < kEdge || l2 < kEdge)
                    continue;
                const Eigen::Vector3f point = float(l0) * p0 + float(l1) * p1 + float(l2) * p2;
                // The texels round the point, blended by distance: the pattern
                // as smooth as the tiles resolve it, not a mosaic of texels.
                const std::vector<TexelGrid::Sample> near = grid.nearest(point, faceNormal);
                // A fixed reach keeps the blend continuous from texel to texel
                // (a reach that followed the nearest texel would step where it
                // changes, and the normal map would show the steps).
                const double reach =
                    std::max(1.5 * grid.spacing(), 1.01 * std::sqrt(near.front().first));
                double weightSum = 0, rgb[3] = {0, 0, 0}, h = 0, v = 0;
                for (const auto& [d2, cell] : near) {
                    const double f = std::max(0.0, 1.0 - std::sqrt(d2) / reach);
                    const double w = f * f + 1e-12;
                    for (int k = 0; k < 3; ++k)
                        rgb[k] += w * colours.colours[cell][std::size_t(k)];
                    h += w * colours.height[cell];
                    if (value)
                        v += w * (*value)[cell];
                    weightSum += w;
                }
                const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
                for (int k = 0; k < 3; ++k)
                    out.colour[i][std::size_t(k)] = std::uint8_t(std::lround(rgb[k] / weightSum));
                out.colour[i][3] = 255;
                out.height[i] = float(h / weightSum);
                if (value)
                    out.value[i] = float(v / weightSum);
                out.worldPerTexel[i] = scale;
                out.covered[i] = 1;
            }
    }

    // Dilation: each ring of empty texels next to covered ones takes their mean.
    for (int ring = 0; ring < options.padding; ++ring) {
        std::vector<std::size_t> filled;
        std::vector<std::array<std::uint8_t, 4>> newColour;
        std::vector<float> newHeight, newValue, newScale;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(size) + std::size_t(x);
                if (out.covered[i])
                    continue;
                double sum[4] = {0, 0, 0, 0}, h = 0, v = 0, s = 0;
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= size || ny >= size)
                            continue;
                        const std::size_t j = std::size_t(ny) * std::size_t(size) + std::size_t(nx);
                        if (!out.covered[j])
                            continue;
                        for (int k = 0; k < 4; ++k)
                            sum[k] += out.colour[j][std::size_t(k)];
                        h += out.height[j];
                        if (value)
                            v += out.value[j];
                        s += out.worldPerTexel[j];
                        ++count;
                    }
                if (count == 0)
                    continue;
                filled.push_back(i);
                std::array<std::uint8_t, 4> mean;
                for (int k = 0; k < 4; ++k)
                    mean[std::size_t(k)] = std::uint8_t(std::lround(sum[k] / count));
                newColour.push_back(mean);
                newHeight.push_back(float(h / count));
                newValue.push_back(float(v / count));
                newScale.push_back(float(s / count));
            }
        if (filled.empty())
            break;
        for (std::size_t k = 0; k < filled.size(); ++k) {
            out.colour[filled[k]] = newColour[k];
            out.height[filled[k]] = newHeight[k];
            if (value)
                out.value[filled[k]] = newValue[k];
            out.worldPerTexel[filled[k]] = newScale[k];
            out.covered[filled[k]] = 1;
        }
    }
    return out;
}

double uvRelief(const SurfaceTiles& tiles, float bump) {
    const Atlas& atlas = *tiles.atlas;
    double texelLength = 0;
    std::size_t used = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            texelLength += std::sqrt(double(tiles.texelArea[i]));
            ++used;
        }
    return double(bump) * (used ? texelLength / double(used) : 0);
}

RgbaImage uvNormalMap(const UvTexels& texels, const std::vector<float>& height, double relief,
                      bool yDown) {
    const int size = texels.size;
    const std::size_t count = std::size_t(size) * std::size_t(size);
    if (height.size() != count || texels.covered.size() != count)
        throw std::invalid_argument("uvNormalMap: the height does not match the texels");
    RgbaImage normals{size, size,
                      std::vector<std::array<std::uint8_t, 4>>(count, {128, 128, 255, 255})};
    const auto at = [&](int x, int y) {
        return std::size_t(std::clamp(y, 0, size - 1)) * std::size_t(size) +
               std::size_t(std::clamp(x, 0, size - 1));
    };
    const std::vector<char>& covered = texels.covered;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const std::size_t i = at(x, y);
            const float perTexel = texels.worldPerTexel[i];
            if (!covered[i] || !(perTexel > 0))
                continue;
            // Central differences over the covered neighbours (one-sided at an
            // island's padded rim).
            const auto slope = [&](std::size_t minus, std::size_t plus) {
                const std::size_t lo = covered[minus] ? minus : i, hi = covered[plus] ? plus : i;
                const double steps = (lo == minus ? 1.0 : 0.0) + (hi == plus ? 1.0 : 0.0);
                return steps > 0 ? (double(height[hi]) - double(height[lo])) / steps : 0.0;
            };
            const double gx = slope(at(x - 1, y), at(x + 1, y)) * relief / perTexel;
            const double gDown = slope(at(x, y - 1), at(x, y + 1)) * relief / perTexel;
            const double gy = yDown ? gDown : -gDown;
            const Eigen::Vector3d n = Eigen::Vector3d(-gx, -gy, 1.0).normalized();
            for (int k = 0; k < 3; ++k)
                normals.texels[i][std::size_t(k)] =
                    std::uint8_t(std::lround(std::clamp((n[k] * 0.5 + 0.5) * 255.0, 0.0, 255.0)));
        }
    return normals;
}

TexturedMesh bakeIntoUvs(const UvMesh& mesh, const SurfaceTiles& tiles,
                         const SurfaceColours& colours, const UvBakeOptions& options) {
    UvTexels texels = sampleIntoUvs(mesh, tiles, colours, options);
    // The tangents' bitangent runs up the image, and so does the normal map's y.
    RgbaImage normals =
        uvNormalMap(texels, texels.height, uvRelief(tiles, options.bump) * colours.relief, false);
    return uvBakedMesh(mesh, RgbaImage{texels.size, texels.size, std::move(texels.colour)},
                       std::move(normals));
}

TexturedMesh uvBakedMesh(const UvMesh& mesh, RgbaImage baseColour, RgbaImage normalMap) {
    if (mesh.uvs.size() != mesh.positions.size())
        throw std::invalid_argument("uvBakedMesh: every vertex needs a UV");
    TexturedMesh out;
    out.positions = mesh.positions;
    out.uvs = mesh.uvs;
    out.triangles = mesh.triangles;
    out.materials = mesh.materials;
    vertexFrames(mesh, out.normals, out.tangents);
    out.baseColour = std::move(baseColour);
    out.normalMap = std::move(normalMap);
    return out;
}

} // namespace morphogen
