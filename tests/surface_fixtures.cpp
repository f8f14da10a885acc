#include "surface_fixtures.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/surface/tile_builder.hpp"

namespace morphogen::test {

namespace {

Eigen::Vector3f cubeVertex(int v) {
    return {float(v & 1) * 2 - 1, float((v >> 1) & 1) * 2 - 1, float((v >> 2) & 1) * 2 - 1};
}

// Face t's corners (atlas.hpp, Atlas::cube).
constexpr int kFaces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                              {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};

Eigen::Vector3f onFace(int face, float s, float t) {
    const Eigen::Vector3f c0 = cubeVertex(kFaces[face][0]), c1 = cubeVertex(kFaces[face][1]),
                          c2 = cubeVertex(kFaces[face][2]), c3 = cubeVertex(kFaces[face][3]);
    return (1 - s) * (1 - t) * c0 + s * (1 - t) * c1 + s * t * c2 + (1 - s) * t * c3;
}

} // namespace

SurfaceTiles cubeSphereTiles(int n, float radius, const Eigen::Matrix3f& rotation) {
    SurfaceTiles tiles;
    tiles.atlas = std::make_shared<const Atlas>(Atlas::cube(n));
    const Atlas& atlas = *tiles.atlas;
    for (int v = 0; v < 8; ++v)
        tiles.quadVertices.push_back(rotation * cubeVertex(v).normalized() * radius);
    for (int t = 0; t < 6; ++t) {
        tiles.quads.push_back({kFaces[t][0], kFaces[t][1], kFaces[t][2], kFaces[t][3]});
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const Eigen::Vector3f dir =
                    rotation * onFace(t, float(i) / n, float(j) / n).normalized();
                tiles.gridPositions.push_back(dir * radius);
                tiles.gridNormals.push_back(dir);
            }
    }
    tiles.texelPositions.assign(atlas.cellCount(), Eigen::Vector3f::Zero());
    tiles.texelNormals.assign(atlas.cellCount(), Eigen::Vector3f::Zero());
    for (int t = 0; t < 6; ++t)
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const Eigen::Vector3f dir =
                    rotation * onFace(t, (float(u) + 0.5f) / n, (float(v) + 0.5f) / n).normalized();
                const std::uint32_t cell = atlas.tileCell(t, u, v);
                tiles.texelPositions[cell] = dir * radius;
                tiles.texelNormals[cell] = dir;
            }
    tiles.surfaceArea = 4 * 3.14159265358979 * radius * radius;
    return tiles;
}

std::vector<float> fieldOnTexels(const SurfaceTiles& tiles,
                                 const std::function<float(const Eigen::Vector3f&)>& f) {
    std::vector<float> values(tiles.atlas->cellCount(), 0.0f);
    for (std::size_t c = 0; c < values.size(); ++c)
        if (tiles.atlas->used(std::uint32_t(c)))
            values[c] = f(tiles.texelPositions[c]);
    return values;
}

std::vector<std::array<std::uint8_t, 4>> constantColours(const SurfaceTiles& tiles,
                                                         std::array<std::uint8_t, 4> colour) {
    return std::vector<std::array<std::uint8_t, 4>>(tiles.atlas->cellCount(), colour);
}

std::vector<std::array<std::uint8_t, 4>> rampColours(const std::vector<float>& values) {
    std::vector<std::array<std::uint8_t, 4>> out;
    for (const float v : values) {
        const float t = std::clamp(v, 0.0f, 1.0f);
        const float r = t < 0.5f ? 0.2f + 1.6f * t : 1.0f;
        const float g = t < 0.5f ? 0.3f + 1.4f * t : 1.0f - (t - 0.5f) * 0.9f;
        const float b = t < 0.5f ? 0.8f + 0.4f * t : 1.0f - (t - 0.5f) * 1.8f;
        out.push_back({std::uint8_t(std::lround(r * 255)), std::uint8_t(std::lround(g * 255)),
                       std::uint8_t(std::lround(b * 255)), 255});
    }
    return out;
}

SurfaceTiles buildTiles(const TriangleMesh& mesh, int tiles, int tileSize) {
    TileOptions options;
    options.tileSize = tileSize;
    options.tiles = tiles;
    return buildSurfaceTiles(mesh, options);
}

TriangleMesh equilateralSheet(int m) {
    TriangleMesh mesh;
    const float h = std::sqrt(3.0f) / 2.0f / float(m);
    for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i)
            mesh.positions.emplace_back((float(i) + 0.5f * float(j % 2)) / float(m), float(j) * h,
                                        0.0f);
    const auto id = [&](int i, int j) { return std::uint32_t(j * (m + 1) + i); };
    for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
            if (j % 2 == 0) {
                mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
                if (i + 1 < m)
                    mesh.triangles.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
            } else {
                mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
                mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            }
        }
    return mesh;
}

} // namespace morphogen::test
