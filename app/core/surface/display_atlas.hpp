#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/domain/atlas.hpp"

namespace morphogen {

// The atlas as a texture to draw with: every tile of n texels gets a gutter of
// g texels on each side (n + 2g per padded tile, laid out with the atlas's
// tiles per row), filled from the tiles across its glued edges through
// Atlas::step, so bilinear filtering and the first log2(g) mipmap levels read
// the neighbouring tile's texels instead of a seam.
//
// Gutter texel (u, v) of a tile (u or v outside 0..n-1) takes the texel
// reached by walking from the nearest border texel straight out of the tile
// (Atlas::walk carries the frame across rotated and mirrored gluings; an
// unglued edge clamps to the border). In the corner blocks the two walk orders
// (x then y, y then x) differ where k != 4 tiles meet; there the texel is the
// average of both, except the texel diagonally next to the tile corner, which
// is chosen so that bilinear filtering at the tile-corner vertex gives the
// mean of the k corner texels around it, the same value from every tile (for
// k = 3, 4, 5; see the .cpp).
//
// With a scale s > 1 each atlas texel is s x s texels of the image (n s + 2g
// per padded tile): a display texel is the bilinear interpolation, at its
// centre, of the atlas texels round it (the gutter's ones across the edges),
// so a colour map applied to the interpolated values draws sharp contours
// where s = 1 would draw texel-sized steps, and the gutter is a smaller share
// of the texture (4 x 4 tiles: 75% at s = 1, 36% at s = 4 with g = 2).
//
// Row 0 of the padded image is the atlas's row 0 (texture coordinate v = 0):
// the first row uploaded to GL and the top row of a PNG, which is where glTF
// puts v = 0, so one UV serves both.
class DisplayAtlas {
public:
    // Throws std::invalid_argument for gutter < 1, scale < 1 or a padded
    // image 65536 texels or more on a side.
    explicit DisplayAtlas(const Atlas& atlas, int gutter = 2, int scale = 1);

    int tileSize() const { return m_tileSize; } // atlas texels
    int gutter() const { return m_gutter; }     // display texels
    int scale() const { return m_scale; }
    // Display texels on a tile's side, gutter excluded.
    int displayTileSize() const { return m_tileSize * m_scale; }
    int paddedTileSize() const { return displayTileSize() + 2 * m_gutter; }
    int tileCount() const { return m_tileCount; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    std::size_t texelCount() const { return std::size_t(m_width) * std::size_t(m_height); }

    // The padded texel of display texel (u, v) of a tile (u, v in -g .. ns - 1 + g),
    // in the tile's own frame.
    std::array<int, 2> texel(int tile, int u, int v) const;
    // The tile's atlas texel nearest to display texel (u, v) (clamped to the tile).
    std::array<int, 2> atlasTexel(int u, int v) const;
    // Texture coordinate in [0, 1]^2 of atlas texel corner (i, j), i, j in 0..n,
    // of a tile (the corner between atlas texels i - 1 and i).
    Eigen::Vector2f cornerUv(int tile, int i, int j) const;
    // The tile's padded rectangle (gutter included) in texture coordinates:
    // {u0, v0, u1, v1}.
    std::array<float, 4> paddedRect(int tile) const;

    // Per-cell values (channels floats per atlas cell) to the padded image
    // (channels floats per padded texel; texels of no tile are 0).
    std::vector<float> pad(const std::vector<float>& cells, int channels) const;
    // The same for 8-bit RGBA (rounded to nearest, clamped).
    std::vector<std::array<std::uint8_t, 4>>
    pad(const std::vector<std::array<std::uint8_t, 4>>& cells) const;

    // Per padded texel, the atlas cells it is made of and their weights
    // (summing to 1; a weight may be negative at an irregular corner): for
    // tests and for callers padding their own types.
    struct Source {
        std::uint32_t cell;
        float weight;
    };
    std::vector<Source> sources(std::size_t paddedTexel) const;
    // Whether the padded texel belongs to a tile (has sources).
    bool covered(std::size_t paddedTexel) const {
        return m_first[paddedTexel + 1] > m_first[paddedTexel];
    }

private:
    void interpolate(const Atlas& atlas);

    int m_tileSize, m_gutter, m_scale, m_tileCount, m_tilesPerRow, m_width, m_height;
    // Compressed rows: the sources of padded texel p are m_sources[m_first[p] .. m_first[p+1]).
    std::vector<std::uint32_t> m_first;
    std::vector<Source> m_sources;
};

} // namespace morphogen
