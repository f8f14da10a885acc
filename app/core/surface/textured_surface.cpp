#include "core/surface/textured_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "core/surface/surface_colours.hpp"

namespace morphogen {

namespace {

std::array<std::uint8_t, 4> encodeNormal(const Eigen::Vector3f& n) {
    std::array<std::uint8_t, 4> out{0, 0, 0, 255};
    for (int k = 0; k < 3; ++k)
        out[std::size_t(k)] =
            std::uint8_t(std::lround(std::clamp(n[k] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
    return out;
}

// The height over the used cells mapped to 0..1 (min-max; a flat or
// non-finite field becomes 0), so `bump` means the same for any model.
std::vector<float> normalisedHeight(const Atlas& atlas, const std::vector<float>& height) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (std::size_t c = 0; c < height.size(); ++c)
        if (atlas.used(std::uint32_t(c)) && std::isfinite(height[c])) {
            lo = std::min(lo, height[c]);
            hi = std::max(hi, height[c]);
        }
    const float scale = hi > lo ? 1.0f / (hi - lo) : 0.0f;
    std::vector<float> out(height.size(), 0.0f);
    for (std::size_t c = 0; c < height.size(); ++c)
        if (std::isfinite(height[c]) && scale > 0)
            out[c] = (height[c] - lo) * scale;
    return out;
}

// The vertex tangent at texel corner (i, j) of a tile: the grid's difference
// along u (one-sided on the border) in the tangent plane, w from the side +v
// lies on (glTF's TANGENT).
Eigen::Vector4f gridTangent(const SurfaceTiles& tiles, int tile, int i, int j) {
    const int n = tiles.atlas->tileSize(), side = n + 1;
    const std::size_t base = std::size_t(side) * side * std::size_t(tile);
    auto pos = [&](int ii, int jj) {
        return tiles.gridPositions[base + std::size_t(jj) * side + ii];
    };
    const Eigen::Vector3f normal = tiles.gridNormals[base + std::size_t(j) * side + i].normalized();
    const Eigen::Vector3f du = pos(std::min(i + 1, n), j) - pos(std::max(i - 1, 0), j);
    const Eigen::Vector3f dv = pos(i, std::min(j + 1, n)) - pos(i, std::max(j - 1, 0));
    Eigen::Vector3f tangent = du - normal * normal.dot(du);
    if (tangent.squaredNorm() < 1e-20f) // degenerate: any direction in the plane
        tangent = normal.unitOrthogonal();
    tangent.normalize();
    // The bitangent w * cross(normal, tangent) runs along -v, up the image:
    // glTF's "+Y is up" for normal textures, the frame MikkTSpace builds where
    // TANGENT is ignored (Blender's importer).
    const float w = normal.cross(tangent).dot(dv) < 0 ? 1.0f : -1.0f;
    return {tangent.x(), tangent.y(), tangent.z(), w};
}

} // namespace

RgbaImage bakeNormalMap(const Atlas& atlas, const DisplayAtlas& display,
                        const std::vector<float>& height, const TexelFrames& frames, float relief) {
    // Per cell, the normal's tilt in world space, -relief times the surface
    // gradient g: the least-squares fit h(q) - h(p) = g . (q - p) over the
    // four neighbours q (through the connectivity, across tile edges), with
    // g in the tangent plane and the offsets q - p taken in it. It needs no
    // regular grid: skewed texels and the kinks where tiles meet at an
    // irregular corner are measured, not assumed, and a height linear on the
    // surface gives its exact gradient.
    std::vector<float> tilt(atlas.cellCount() * 3, 0.0f);
    constexpr Direction kDirections[4] = {Direction::PlusX, Direction::PlusY, Direction::MinusX,
                                          Direction::MinusY};
    for (std::uint32_t cell = 0; cell < atlas.cellCount(); ++cell) {
        if (!atlas.used(cell))
            continue;
        const Eigen::Vector3f& T = frames.tangent[cell];
        const Eigen::Vector3f& B = frames.bitangent[cell];
        Eigen::Matrix2f normal = Eigen::Matrix2f::Zero();
        Eigen::Vector2f rhs = Eigen::Vector2f::Zero();
        for (const Direction d : kDirections) {
            const std::uint32_t q = atlas.step(cell, d).cell;
            if (q == cell) // an open edge
                continue;
            const Eigen::Vector3f offset = frames.centre[q] - frames.centre[cell];
            const Eigen::Vector2f x(offset.dot(T), offset.dot(B));
            normal += x * x.transpose();
            rhs += x * (height[q] - height[cell]);
        }
        if (std::abs(normal.determinant()) <= 1e-12f * normal.trace() * normal.trace())
            continue;
        const Eigen::Vector2f g = normal.inverse() * rhs;
        const Eigen::Vector3f t = -relief * (g.x() * T + g.y() * B);
        for (int k = 0; k < 3; ++k)
            tilt[std::size_t(cell) * 3 + std::size_t(k)] = t[k];
    }
    // Padded like the colours, so a gutter texel holds its neighbour's tilt
    // itself, then written in the tile's frame at its nearest texel (the
    // frame the renderer rebuilds from the vertex tangents there): the
    // tangent-space normal is normalize(tilt.tangent, tilt.bitangent, 1).
    const std::vector<float> padded = display.pad(tilt, 3);
    RgbaImage image;
    image.width = display.width();
    image.height = display.height();
    image.texels.assign(display.texelCount(), encodeNormal({0, 0, 1}));
    const int g = display.gutter(), side = display.displayTileSize();
    for (int t = 0; t < display.tileCount(); ++t)
        for (int v = -g; v < side + g; ++v)
            for (int u = -g; u < side + g; ++u) {
                const std::array<int, 2> nearest = display.atlasTexel(u, v);
                const std::uint32_t cell = atlas.tileCell(t, nearest[0], nearest[1]);
                const std::array<int, 2> xy = display.texel(t, u, v);
                const std::size_t p = std::size_t(xy[1]) * image.width + xy[0];
                const Eigen::Vector3f w(padded[p * 3], padded[p * 3 + 1], padded[p * 3 + 2]);
                const Eigen::Vector3f local(w.dot(frames.tangent[cell]),
                                            w.dot(frames.bitangent[cell]), 1.0f);
                image.texels[p] = encodeNormal(local.normalized());
            }
    return image;
}

TexelFrames texelFrames(const SurfaceTiles& tiles) {
    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize(), side = n + 1;
    const std::size_t perTile = std::size_t(side) * side;
    TexelFrames frames;
    const Eigen::Vector3f zero = Eigen::Vector3f::Zero();
    frames.jacobianU.assign(atlas.cellCount(), zero);
    frames.jacobianV.assign(atlas.cellCount(), zero);
    frames.tangent.assign(atlas.cellCount(), zero);
    frames.bitangent.assign(atlas.cellCount(), zero);
    frames.normal.assign(atlas.cellCount(), zero);
    frames.centre.assign(atlas.cellCount(), zero);
    double sum = 0;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const std::size_t base = perTile * std::size_t(t);
        auto at = [&](int i, int j) { return base + std::size_t(j) * side + i; };
        auto pos = [&](int i, int j) { return tiles.gridPositions[at(i, j)]; };
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const std::uint32_t cell = atlas.tileCell(t, u, v);
                // The means of the texel's two edges along u and along v.
                const Eigen::Vector3f pu =
                    0.5f * (pos(u + 1, v) - pos(u, v) + pos(u + 1, v + 1) - pos(u, v + 1));
                const Eigen::Vector3f pv =
                    0.5f * (pos(u, v + 1) - pos(u, v) + pos(u + 1, v + 1) - pos(u + 1, v));
                const Eigen::Vector3f normal =
                    (tiles.gridNormals[at(u, v)] + tiles.gridNormals[at(u + 1, v)] +
                     tiles.gridNormals[at(u, v + 1)] + tiles.gridNormals[at(u + 1, v + 1)])
                        .normalized();
                // The frame the renderer interpolates from the vertex tangents, at the
                // texel's centre, so the baked normals mean the same there.
                const Eigen::Vector4f corners =
                    gridTangent(tiles, t, u, v) + gridTangent(tiles, t, u + 1, v) +
                    gridTangent(tiles, t, u, v + 1) + gridTangent(tiles, t, u + 1, v + 1);
                Eigen::Vector3f tangent =
                    corners.head<3>() - normal * normal.dot(corners.head<3>());
                if (tangent.squaredNorm() < 1e-20f)
                    tangent = normal.unitOrthogonal();
                tangent.normalize();
                Eigen::Vector3f bitangent = normal.cross(tangent);
                if (bitangent.dot(pv) > 0)
                    bitangent = -bitangent;
                frames.jacobianU[cell] = pu;
                frames.jacobianV[cell] = pv;
                frames.tangent[cell] = tangent;
                frames.bitangent[cell] = bitangent;
                frames.normal[cell] = normal;
                frames.centre[cell] =
                    0.25f * (pos(u, v) + pos(u + 1, v) + pos(u, v + 1) + pos(u + 1, v + 1));
                sum += double(pu.norm()) + double(pv.norm());
            }
    }
    frames.meanTexelLength = float(sum / (2.0 * double(n) * n * atlas.tileCount()));
    return frames;
}

int displayScale(const Atlas& atlas, const SurfaceLook& look) {
    if (look.scale > 0)
        return look.scale;
    const int n = std::max(atlas.tileSize(), 1);
    return std::clamp((kDisplayTileTexels + n - 1) / n, 1, 8);
}

namespace {

// texturedSurface on a given display atlas; `mapped`, when not null, the
// base colour per padded texel (SurfaceColours::display), else `colours` are padded.
TexturedMesh texturedOn(const SurfaceTiles& tiles, const DisplayAtlas& display,
                        const std::vector<float>& height,
                        const std::vector<std::array<std::uint8_t, 4>>& colours,
                        const std::vector<std::array<std::uint8_t, 4>>* mapped,
                        const SurfaceLook& look) {
    if (!tiles.atlas)
        throw std::invalid_argument("texturedSurface: the tiles have no atlas");
    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize(), side = n + 1;
    const std::size_t perTile = std::size_t(side) * side;
    if (colours.size() != atlas.cellCount() || (!height.empty() && height.size() != colours.size()))
        throw std::invalid_argument("texturedSurface: " + std::to_string(colours.size()) +
                                    " colours and " + std::to_string(height.size()) +
                                    " heights for an atlas of " +
                                    std::to_string(atlas.cellCount()) + " cells");
    if (tiles.gridPositions.size() != perTile * atlas.tileCount() ||
        tiles.gridNormals.size() != tiles.gridPositions.size())
        throw std::invalid_argument(
            "texturedSurface: " + std::to_string(tiles.gridPositions.size()) +
            " grid positions for " + std::to_string(atlas.tileCount()) +
            " tiles of (n+1)^2 = " + std::to_string(perTile));

    TexturedMesh mesh;
    mesh.positions = tiles.gridPositions;
    mesh.normals.resize(mesh.positions.size());
    mesh.tangents.resize(mesh.positions.size());
    mesh.uvs.resize(mesh.positions.size());
    mesh.triangles.reserve(std::size_t(2) * n * n * atlas.tileCount());
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const std::size_t base = perTile * std::size_t(t);
        auto at = [&](int i, int j) { return base + std::size_t(j) * side + i; };
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const std::size_t k = at(i, j);
                mesh.normals[k] = tiles.gridNormals[k].normalized();
                mesh.tangents[k] = gridTangent(tiles, t, i, j);
                mesh.uvs[k] = display.cornerUv(t, i, j);
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const auto a = std::uint32_t(at(i, j)), b = std::uint32_t(at(i + 1, j)),
                           c = std::uint32_t(at(i + 1, j + 1)), d = std::uint32_t(at(i, j + 1));
                const auto& P = mesh.positions;
                std::array<std::array<std::uint32_t, 3>, 2> pair;
                if ((P[a] - P[c]).squaredNorm() <= (P[b] - P[d]).squaredNorm())
                    pair = {{{a, b, c}, {a, c, d}}};
                else
                    pair = {{{a, b, d}, {b, c, d}}};
                for (std::array<std::uint32_t, 3> tri : pair) {
                    // Wound so the face agrees with the surface normals
                    // (mirrored tiles run clockwise in their own frame).
                    const Eigen::Vector3f face =
                        (P[tri[1]] - P[tri[0]]).cross(P[tri[2]] - P[tri[0]]);
                    const Eigen::Vector3f normal =
                        mesh.normals[tri[0]] + mesh.normals[tri[1]] + mesh.normals[tri[2]];
                    if (face.dot(normal) < 0)
                        std::swap(tri[1], tri[2]);
                    mesh.triangles.push_back(tri);
                }
            }
    }

    mesh.baseColour.width = display.width();
    mesh.baseColour.height = display.height();
    mesh.baseColour.texels = mapped ? *mapped : display.pad(colours);
    const TexelFrames frames = texelFrames(tiles);
    mesh.normalMap =
        bakeNormalMap(atlas, display,
                      height.empty() ? std::vector<float>(atlas.cellCount(), 0.0f)
                                     : normalisedHeight(atlas, height),
                      frames, height.empty() ? 0.0f : look.bump * frames.meanTexelLength);
    return mesh;
}

} // namespace

TexturedMesh texturedSurface(const SurfaceTiles& tiles, const std::vector<float>& height,
                             const std::vector<std::array<std::uint8_t, 4>>& colours,
                             const SurfaceLook& look) {
    if (!tiles.atlas)
        throw std::invalid_argument("texturedSurface: the tiles have no atlas");
    const DisplayAtlas display(*tiles.atlas, look.gutter, displayScale(*tiles.atlas, look));
    return texturedOn(tiles, display, height, colours, nullptr, look);
}

TexturedMesh texturedSurface(const SurfaceTiles& tiles, const SurfaceColours& colours,
                             const SurfaceLook& look) {
    if (!tiles.atlas)
        throw std::invalid_argument("texturedSurface: the tiles have no atlas");
    const Atlas& atlas = *tiles.atlas;
    const int scale = displayScale(atlas, look);
    std::shared_ptr<const DisplayAtlas> display = colours.displayAtlas;
    const bool mapped = display && display->gutter() == look.gutter && display->scale() == scale &&
                        display->tileCount() == atlas.tileCount() &&
                        colours.display.size() == display->texelCount();
    if (!mapped)
        display = std::make_shared<const DisplayAtlas>(atlas, look.gutter, scale);
    SurfaceLook scaled = look;
    scaled.bump = look.bump * colours.relief;
    TexturedMesh mesh = texturedOn(tiles, *display, colours.height, colours.colours,
                                   mapped ? &colours.display : nullptr, scaled);
    if (colours.wetness.empty())
        return mesh;
    if (colours.wetness.size() != atlas.cellCount())
        throw std::invalid_argument("texturedSurface: " + std::to_string(colours.wetness.size()) +
                                    " wetness values for " + std::to_string(atlas.cellCount()) +
                                    " atlas cells");
    std::vector<std::array<std::uint8_t, 4>> roughness(atlas.cellCount());
    for (std::size_t i = 0; i < roughness.size(); ++i) {
        const float wet = std::clamp(colours.wetness[i], 0.0f, 1.0f);
        const float r = kDryRoughness + (kWetRoughness - kDryRoughness) * wet;
        roughness[i] = {255, std::uint8_t(std::lround(r * 255.0f)), 0, 255};
    }
    mesh.metallicRoughness.width = display->width();
    mesh.metallicRoughness.height = display->height();
    mesh.metallicRoughness.texels = display->pad(roughness);
    return mesh;
}

BoundingSphere boundingSphere(const std::vector<Eigen::Vector3f>& positions) {
    BoundingSphere sphere;
    if (positions.empty())
        return sphere;
    const Bounds box = boundsOf(positions);
    sphere.centre = (box.min + box.max) * 0.5f;
    for (const Eigen::Vector3f& p : positions)
        sphere.radius = std::max(sphere.radius, (p - sphere.centre).norm());
    return sphere;
}

} // namespace morphogen
