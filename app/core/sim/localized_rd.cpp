#include "core/sim/localized_rd.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/sim/brush.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

std::vector<int> touchedTiles(const Atlas& atlas, const BrushRegion& region) {
    std::vector<int> tiles;
    for (const BrushRegion::Cell& cell : region.cells()) {
        const int t = atlas.tileOf(cell.index);
        if (t >= 0)
            tiles.push_back(t);
    }
    std::sort(tiles.begin(), tiles.end());
    tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    return tiles;
}

int iterationsToCrossTile(int tileSize, double maxDiffusion, double dt) {
    if (maxDiffusion <= 0 || dt <= 0)
        return 1;
    const double m = double(tileSize) * tileSize / (4.0 * maxDiffusion * dt);
    return std::max(1, int(std::ceil(std::min(m, 1e9))));
}

int iterationsToCrossTile(const StepConstants& k) {
    const Atlas* atlas = k.domain.atlasMap();
    assert(atlas);
    double rate = 0;
    for (int c = 0; c < k.chemicals; ++c)
        rate = std::max(rate, double(k.op.rates[std::size_t(c)]));
    double coefficient = 1;
    if (const AtlasWeights* w = k.domain.atlasWeights()) {
        coefficient = 0;
        for (const auto& c : w->coefficients)
            coefficient =
                std::max({coefficient, double(c[0]), double(c[1]), double(c[2]), double(c[3])});
    }
    return iterationsToCrossTile(atlas->tileSize(), rate * coefficient, k.dt);
}

ActiveTileSchedule::ActiveTileSchedule(const TileNeighbourhoods& neighbourhoods,
                                       const std::vector<int>& touched, int growEvery,
                                       double globalFraction)
    : m_neighbourhoods(&neighbourhoods), m_tiles(neighbourhoods.grow(touched)),
      m_growEvery(std::max(1, growEvery)), m_globalFraction(globalFraction) {
    checkThreshold();
}

void ActiveTileSchedule::checkThreshold() {
    // Nothing touched leaves nothing to localize: the set is every tile.
    if (m_tiles.empty() ||
        double(m_tiles.size()) > m_globalFraction * m_neighbourhoods->tileCount()) {
        m_global = true;
        m_tiles.clear();
    }
}

void ActiveTileSchedule::add(const std::vector<int>& touched) {
    if (m_global)
        return;
    const std::vector<int> grown = m_neighbourhoods->grow(touched);
    std::vector<int> merged;
    merged.reserve(m_tiles.size() + grown.size());
    std::set_union(m_tiles.begin(), m_tiles.end(), grown.begin(), grown.end(),
                   std::back_inserter(merged));
    m_tiles = std::move(merged);
    m_done = 0;
    checkThreshold();
}

bool ActiveTileSchedule::advance(int iterations) {
    if (m_global)
        return false;
    m_done += iterations;
    if (m_done < m_growEvery)
        return false;
    // A batch longer than a phase grows once per phase it covered.
    while (!m_global && m_done >= m_growEvery) {
        m_done -= m_growEvery;
        m_tiles = m_neighbourhoods->grow(m_tiles);
        ++m_phase;
        checkThreshold();
    }
    return true;
}

} // namespace morphogen
