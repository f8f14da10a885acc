#include "core/base/noise_field.hpp"

#include <algorithm>
#include <cmath>

#include "core/base/random.hpp"

namespace morphogen {

NoiseField::NoiseField(std::uint64_t seed, int width, int height, double cellSize, bool periodic)
    : m_seed(seed), m_width(width), m_cellSize(cellSize), m_periodic(periodic) {
    if (m_cellSize > 0) {
        m_latticeWidth = std::max(1LL, std::llround(width * cellSize));
        m_latticeHeight = std::max(1LL, std::llround(height * cellSize));
    }
}

double NoiseField::lattice(std::uint64_t stream, long long i, long long j) const {
    if (m_periodic) {
        i = ((i % m_latticeWidth) + m_latticeWidth) % m_latticeWidth;
        j = ((j % m_latticeHeight) + m_latticeHeight) % m_latticeHeight;
    } else {
        i = std::clamp(i, 0LL, m_latticeWidth - 1);
        j = std::clamp(j, 0LL, m_latticeHeight - 1);
    }
    // Indexed as cells of a grid m_latticeWidth wide: at one cell per unit the
    // same numbers as the per-cell draw.
    return uniformSigned(m_seed, stream, std::uint64_t(j * m_latticeWidth + i));
}

double NoiseField::at(std::uint64_t stream, int x, int y) const {
    if (m_cellSize <= 0)
        return uniformSigned(m_seed, stream, std::uint64_t(y) * m_width + x);
    // Lattice point i sits at (i + 0.5) units: the centre of cell i at one cell per unit.
    const double u = (x + 0.5) * m_cellSize - 0.5;
    const double v = (y + 0.5) * m_cellSize - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double tu = u - fu, tv = v - fv;
    const long long i = (long long)fu, j = (long long)fv;
    if (tu == 0.0 && tv == 0.0)
        return lattice(stream, i, j);
    const double top = (1 - tu) * lattice(stream, i, j) + tu * lattice(stream, i + 1, j);
    const double bottom = (1 - tu) * lattice(stream, i, j + 1) + tu * lattice(stream, i + 1, j + 1);
    return (1 - tv) * top + tv * bottom;
}

} // namespace morphogen
