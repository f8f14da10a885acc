#include "core/domain/atlas_diagonals.hpp"

#include "core/domain/atlas.hpp"

namespace morphogen {

std::vector<std::array<std::uint32_t, 8>> atlasDiagonals(const Atlas& atlas) {
    std::vector<std::array<std::uint32_t, 8>> d(atlas.cellCount());
    const Direction xs[2] = {Direction::MinusX, Direction::PlusX};
    const Direction ys[2] = {Direction::MinusY, Direction::PlusY};
    for (std::uint32_t cell = 0; cell < atlas.cellCount(); ++cell)
        for (int i = 0; i < 4; ++i) {
            const Direction x = xs[i % 2], y = ys[i / 2];
            d[cell][std::size_t(i)] = atlas.used(cell) ? atlas.walk(cell, {x, y}) : cell;
            d[cell][std::size_t(4 + i)] = atlas.used(cell) ? atlas.walk(cell, {y, x}) : cell;
        }
    return d;
}

std::vector<std::uint32_t>
packedDiagonals(const Atlas& atlas, const std::vector<std::array<std::uint32_t, 8>>& d, int order) {
    const auto w = std::uint32_t(atlas.width());
    std::vector<std::uint32_t> map(d.size() * 4);
    for (std::size_t c = 0; c < d.size(); ++c)
        for (std::size_t i = 0; i < 4; ++i) {
            const std::uint32_t cell = d[c][std::size_t(4 * order) + i];
            map[c * 4 + i] = (cell % w) | ((cell / w) << 16);
        }
    return map;
}

} // namespace morphogen
