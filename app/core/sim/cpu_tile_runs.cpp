// Batched sweeps on the CPU, blocked by tile. The tiles of a tiled grid
// exchange nothing, so n steps of the whole grid are n steps of each tile on
// its own. One pass of the row kernels over all tiles per step streams the
// whole state through the cache every step; a tile of a sweep (64^2 to 128^2
// cells, two chemicals) fits in L2, so advancing it all n steps at once, tiles
// spread over the threads, is faster (measured: `morphogen bench`, sweep rows)
// and gives the same bits as running the tiles one by one, which it is.

#include <cstring>

#include "core/sim/cpu_simulator.hpp"
#include "core/sim/sweep.hpp"

namespace morphogen {

namespace {

// Copies tile (column, row) of `tiled` (row 0 at the bottom, as sweep.hpp
// numbers tiles) to or from a tile-sized state, plane by plane.
void copyTile(const Domain& domain, int column, int row, State& tiled, State& tile, bool out) {
    const int tw = domain.tileWidth(), th = domain.tileHeight();
    const int x0 = column * tw, y0 = (domain.rows() - 1 - row) * th;
    const std::size_t bytes = std::size_t(tw) * sizeof(float);
    for (int c = 0; c < tiled.channels(); ++c)
        for (int y = 0; y < th; ++y) {
            float* big = tiled.plane(c) + std::size_t(y0 + y) * std::size_t(tiled.width()) + x0;
            float* small = tile.plane(c) + std::size_t(y) * std::size_t(tw);
            if (out)
                std::memcpy(small, big, bytes);
            else
                std::memcpy(big, small, bytes);
        }
}

} // namespace

bool CpuSimulator::runTilesApart(int steps) {
    const Domain& domain = m_k.domain;
    // Semi-implicit runs keep their residual for lastSolveResidual(), and
    // brush-painted maps live on the whole grid: both take the one-pass path.
    if (domain.kind() != DomainKind::TiledGrid || m_k.integrator != Integrator::ExplicitEuler ||
        !m_session.paramMaps.empty() || steps < 2)
        return false;
    const int columns = domain.columns(), rows = domain.rows();
    if (m_tileRuns.empty())
        for (int row = 0; row < rows; ++row)
            for (int column = 0; column < columns; ++column) {
                Session tile = tileSession(m_session, column, row);
                tile.dt = m_k.dt;
                m_tileRuns.push_back(std::make_unique<CpuSimulator>(tile));
            }
    const int tiles = columns * rows;
    const int tw = domain.tileWidth(), th = domain.tileHeight();
#pragma omp parallel for schedule(dynamic)
    for (int t = 0; t < tiles; ++t) {
        const int column = t % columns, row = t / columns;
        CpuSimulator& run = *m_tileRuns[std::size_t(t)];
        State& tileState = run.m_current;
        copyTile(domain, column, row, m_current, tileState, true);
        std::vector<std::uint8_t> frozen;
        if (!m_frozenMask.empty()) {
            frozen.resize(std::size_t(tw) * std::size_t(th));
            const int x0 = column * tw, y0 = (rows - 1 - row) * th;
            for (int y = 0; y < th; ++y)
                for (int x = 0; x < tw; ++x)
                    frozen[std::size_t(y) * std::size_t(tw) + std::size_t(x)] =
                        m_frozenMask[std::size_t(y0 + y) * std::size_t(domain.width()) +
                                     std::size_t(x0 + x)];
        }
        run.setFrozen(frozen);
        run.run(steps);
        copyTile(domain, column, row, m_current, run.m_current, false);
    }
    return true;
}

} // namespace morphogen
