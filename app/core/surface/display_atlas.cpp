#include "core/surface/display_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace morphogen {

namespace {

constexpr int kMaxSide = 65536;

// The walk straight out of a tile from border texel `start`: `x` steps in
// direction dx and `y` in dy, x first or y first.
std::uint32_t walkOut(const Atlas& atlas, std::uint32_t start, Direction dx, int x, Direction dy,
                      int y, bool xFirst) {
    std::vector<Direction> path;
    for (int k = 0; k < (xFirst ? x : y); ++k)
        path.push_back(xFirst ? dx : dy);
    for (int k = 0; k < (xFirst ? y : x); ++k)
        path.push_back(xFirst ? dy : dx);
    return atlas.walk(start, path);
}

} // namespace

DisplayAtlas::DisplayAtlas(const Atlas& atlas, int gutter, int scale)
    : m_tileSize(atlas.tileSize()), m_gutter(gutter), m_scale(scale),
      m_tileCount(atlas.tileCount()), m_tilesPerRow(atlas.tilesPerRow()) {
    if (gutter < 1)
        throw std::invalid_argument("DisplayAtlas: gutter " + std::to_string(gutter) +
                                    " must be at least 1 texel");
    if (scale < 1)
        throw std::invalid_argument("DisplayAtlas: scale " + std::to_string(scale) +
                                    " must be at least 1 texel per atlas texel");
    const int padded = paddedTileSize();
    const int rows = (m_tileCount + m_tilesPerRow - 1) / m_tilesPerRow;
    const long long width = (long long)(m_tilesPerRow)*padded;
    const long long height = (long long)(rows)*padded;
    if (width >= kMaxSide || height >= kMaxSide)
        throw std::invalid_argument("DisplayAtlas: the padded atlas would be " +
                                    std::to_string(width) + " x " + std::to_string(height) +
                                    " texels; at most " + std::to_string(kMaxSide - 1) +
                                    " on a side");
    m_width = int(width);
    m_height = int(height);
    if (m_scale > 1) {
        interpolate(atlas);
        return;
    }

    // Per padded texel its sources, gathered per tile then laid out row-major.
    std::vector<std::vector<Source>> perTexel(texelCount());
    const int n = m_tileSize, g = m_gutter;
    for (int t = 0; t < m_tileCount; ++t)
        for (int v = -g; v < n + g; ++v)
            for (int u = -g; u < n + g; ++u) {
                const std::array<int, 2> xy = texel(t, u, v);
                std::vector<Source>& out = perTexel[std::size_t(xy[1]) * m_width + xy[0]];
                const int bu = std::clamp(u, 0, n - 1), bv = std::clamp(v, 0, n - 1);
                const std::uint32_t start = atlas.tileCell(t, bu, bv);
                const int sx = std::abs(u - bu), sy = std::abs(v - bv);
                const Direction dx = u < 0 ? Direction::MinusX : Direction::PlusX;
                const Direction dy = v < 0 ? Direction::MinusY : Direction::PlusY;
                if (sx == 0 || sy == 0) {
                    out.push_back({walkOut(atlas, start, dx, sx, dy, sy, true), 1.0f});
                    continue;
                }
                const std::uint32_t xThenY = walkOut(atlas, start, dx, sx, dy, sy, true);
                const std::uint32_t yThenX = walkOut(atlas, start, dx, sx, dy, sy, false);
                if (sx > 1 || sy > 1) {
                    out.push_back({xThenY, 0.5f});
                    out.push_back({yThenX, 0.5f});
                    continue;
                }
                // The texel diagonally off a tile corner. Bilinear filtering at
                // the corner vertex reads it with the corner texel a and its
                // two direct neighbours b, c (weights 1/4 each). Where k = 3,
                // 4 or 5 tiles meet, the corner texels round the vertex are
                // exactly {a, b, c, xThenY, yThenX} (two of them equal for 3,
                // the last two equal for 4, atlas.hpp), so with
                // d = 4 mean(S) - a - b - c the vertex gets mean(S) from every
                // tile around it: no colour step at irregular corners.
                const std::uint32_t b = atlas.step(start, dx).cell;
                const std::uint32_t c = atlas.step(start, dy).cell;
                std::vector<std::uint32_t> set = {start, b, c, xThenY, yThenX};
                std::sort(set.begin(), set.end());
                set.erase(std::unique(set.begin(), set.end()), set.end());
                for (const std::uint32_t cell : set) {
                    float w = 4.0f / float(set.size());
                    for (const std::uint32_t minus : {start, b, c})
                        if (minus == cell)
                            w -= 1.0f;
                    if (w != 0.0f)
                        out.push_back({cell, w});
                }
            }

    m_first.reserve(texelCount() + 1);
    m_first.push_back(0);
    for (const std::vector<Source>& s : perTexel) {
        m_sources.insert(m_sources.end(), s.begin(), s.end());
        m_first.push_back(std::uint32_t(m_sources.size()));
    }
}

void DisplayAtlas::interpolate(const Atlas& atlas) {
    // The unscaled padded atlas with enough gutter for the bilinear
    // footprint of every display texel, gutter included: display texel u's
    // centre lies at atlas coordinate (u + 0.5) / s - 0.5, whose lower
    // neighbour is at least -(ceil(g / s) + 1).
    const int s = m_scale, n = m_tileSize, g = m_gutter;
    const DisplayAtlas base(atlas, (g + s - 1) / s + 1, 1);
    std::vector<std::vector<Source>> perTexel(texelCount());
    for (int t = 0; t < m_tileCount; ++t)
        for (int v = -g; v < n * s + g; ++v)
            for (int u = -g; u < n * s + g; ++u) {
                const float x = (float(u) + 0.5f) / float(s) - 0.5f;
                const float y = (float(v) + 0.5f) / float(s) - 0.5f;
                const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
                const float fx = x - float(x0), fy = y - float(y0);
                const std::array<int, 2> xy = texel(t, u, v);
                std::vector<Source>& out = perTexel[std::size_t(xy[1]) * m_width + xy[0]];
                const float weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy,
                                          fx * fy};
                for (int k = 0; k < 4; ++k) {
                    if (weights[k] == 0.0f)
                        continue;
                    const std::array<int, 2> b = base.texel(t, x0 + (k & 1), y0 + (k >> 1));
                    const std::size_t p = std::size_t(b[1]) * base.width() + b[0];
                    for (std::uint32_t q = base.m_first[p]; q < base.m_first[p + 1]; ++q) {
                        const Source& src = base.m_sources[q];
                        const auto same =
                            std::find_if(out.begin(), out.end(),
                                         [&](const Source& o) { return o.cell == src.cell; });
                        if (same != out.end())
                            same->weight += weights[k] * src.weight;
                        else
                            out.push_back({src.cell, weights[k] * src.weight});
                    }
                }
            }
    m_first.reserve(texelCount() + 1);
    m_first.push_back(0);
    for (const std::vector<Source>& sources : perTexel) {
        m_sources.insert(m_sources.end(), sources.begin(), sources.end());
        m_first.push_back(std::uint32_t(m_sources.size()));
    }
}

std::array<int, 2> DisplayAtlas::atlasTexel(int u, int v) const {
    const auto nearest = [&](int d) {
        return std::clamp(int(std::floor(float(d) / float(m_scale))), 0, m_tileSize - 1);
    };
    return {nearest(u), nearest(v)};
}

std::array<int, 2> DisplayAtlas::texel(int tile, int u, int v) const {
    const int padded = paddedTileSize();
    return {(tile % m_tilesPerRow) * padded + m_gutter + u,
            (tile / m_tilesPerRow) * padded + m_gutter + v};
}

Eigen::Vector2f DisplayAtlas::cornerUv(int tile, int i, int j) const {
    const std::array<int, 2> xy = texel(tile, i * m_scale, j * m_scale);
    return {float(xy[0]) / float(m_width), float(xy[1]) / float(m_height)};
}

std::array<float, 4> DisplayAtlas::paddedRect(int tile) const {
    const std::array<int, 2> lo = texel(tile, -m_gutter, -m_gutter);
    const int padded = paddedTileSize();
    return {float(lo[0]) / float(m_width), float(lo[1]) / float(m_height),
            float(lo[0] + padded) / float(m_width), float(lo[1] + padded) / float(m_height)};
}

std::vector<DisplayAtlas::Source> DisplayAtlas::sources(std::size_t paddedTexel) const {
    return {m_sources.begin() + m_first[paddedTexel], m_sources.begin() + m_first[paddedTexel + 1]};
}

std::vector<float> DisplayAtlas::pad(const std::vector<float>& cells, int channels) const {
    std::vector<float> out(texelCount() * std::size_t(channels), 0.0f);
    for (std::size_t p = 0; p < texelCount(); ++p)
        for (std::uint32_t s = m_first[p]; s < m_first[p + 1]; ++s)
            for (int k = 0; k < channels; ++k)
                out[p * channels + k] +=
                    m_sources[s].weight * cells[std::size_t(m_sources[s].cell) * channels + k];
    return out;
}

std::vector<std::array<std::uint8_t, 4>>
DisplayAtlas::pad(const std::vector<std::array<std::uint8_t, 4>>& cells) const {
    std::vector<std::array<std::uint8_t, 4>> out(texelCount(), {0, 0, 0, 0});
    for (std::size_t p = 0; p < texelCount(); ++p) {
        float sum[4] = {0, 0, 0, 0};
        for (std::uint32_t s = m_first[p]; s < m_first[p + 1]; ++s)
            for (int k = 0; k < 4; ++k)
                sum[k] += m_sources[s].weight * float(cells[m_sources[s].cell][k]);
        for (int k = 0; k < 4; ++k)
            out[p][k] = std::uint8_t(std::lround(std::clamp(sum[k], 0.0f, 255.0f)));
    }
    return out;
}

} // namespace morphogen
