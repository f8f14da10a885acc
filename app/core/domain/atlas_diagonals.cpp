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

std::vector<std::array<int, 4>>
diagonalMirrors(const Atlas& atlas, const std::vector<std::array<std::uint32_t, 8>>& d) {
    const auto& n = atlas.neighbours();
    const auto single = [&](std::uint32_t cell, int s) {
        const std::uint32_t j = d[cell][std::size_t(s)];
        if (!atlas.used(cell) || j != d[cell][std::size_t(s + 4)] || j == cell)
            return false;
        for (std::uint32_t k : n[cell])
            if (k == j)
                return false;
        return true;
    };
    std::vector<std::array<int, 4>> mirror(d.size(), {-1, -1, -1, -1});
    for (std::uint32_t cell = 0; cell < d.size(); ++cell)
        for (int s = 0; s < 4; ++s) {
            if (!single(cell, s))
                continue;
            const std::uint32_t j = d[cell][std::size_t(s)];
            int back = -1, count = 0;
            for (int t = 0; t < 4; ++t)
                if (single(j, t) && d[j][std::size_t(t)] == cell) {
                    back = t;
                    ++count;
                }
            if (count == 1)
                mirror[cell][std::size_t(s)] = back;
        }
    return mirror;
}

} // namespace morphogen
