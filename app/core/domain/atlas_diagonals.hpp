#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace morphogen {

class Atlas;

// The 9-point Laplacian's diagonals on an atlas. The diagonal (sx, sy) of a
// texel is "neighbour of neighbour in the same frame", taken in both orders
// (x then y, y then x) and averaged. Inside a tile, across one edge and at
// valence-4 corners the two orders reach the same texel, so this is the
// grid's 9-point stencil there. At an irregular corner they differ (see
// Atlas::walk): at valence 3 the average is of the two direct neighbours
// across the corner, at valence 5 of the two corner texels that are not
// direct neighbours. Either way every weight is mirrored (a's share in b's
// diagonal equals b's in a's), so diffusion still conserves mass.
//
// Per cell, 8 cells: the diagonals (-x,-y), (+x,-y), (-x,+y), (+x,+y), first
// reached x then y, then the same four reached y then x. Unused cells point
// at themselves.
std::vector<std::array<std::uint32_t, 8>> atlasDiagonals(const Atlas& atlas);

// For the GPU: 4 uint32 per texel (RGBA32UI), the diagonals of one order
// (0: x then y, 1: y then x) packed x | y << 16.
std::vector<std::uint32_t>
packedDiagonals(const Atlas& atlas, const std::vector<std::array<std::uint32_t, 8>>& d, int order);

// Per cell and diagonal slot s (0..3, the order above), the slot of the
// diagonal texel j that leads back to the cell, or -1 where the slot is no
// single distinct diagonal: the two orders disagree (an irregular corner),
// it ends on the cell itself or on one of its four direct neighbours (an
// open edge), or j has not exactly one such slot back. What a weighted
// 9-point stencil needs to give each diagonal pair one flux.
std::vector<std::array<int, 4>> diagonalMirrors(const Atlas& atlas,
                                                const std::vector<std::array<std::uint32_t, 8>>& d);

} // namespace morphogen
