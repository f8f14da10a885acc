#pragma once

#include <cstdint>

namespace morphogen {

// Start noise in texture units (uniform in [-1, 1)): independent values on a
// lattice one model unit apart, sampled bilinearly at cell centres. At one
// cell per unit the samples are the lattice values, so a session keeps its
// start at its own size; at another size it gets the same noise field at
// that resolution, and with it the same layout. Without a cell size (0) every
// cell draws its own value, as sessions did before they had a length.
class NoiseField {
public:
    // cellSize: model units per cell (h); periodic: the lattice wraps with
    // the grid.
    NoiseField(std::uint64_t seed, int width, int height, double cellSize, bool periodic);

    std::uint64_t seed() const { return m_seed; }
    // The value of noise stream `stream` at cell (x, y).
    double at(std::uint64_t stream, int x, int y) const;

private:
    double lattice(std::uint64_t stream, long long i, long long j) const;

    std::uint64_t m_seed;
    int m_width;
    double m_cellSize; // 0: per cell
    bool m_periodic;
    long long m_latticeWidth = 0;
    long long m_latticeHeight = 0;
};

} // namespace morphogen
