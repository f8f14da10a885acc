// Brush writes on the CPU backend: a loop over the region's cells.

#include <algorithm>

#include "core/sim/cpu_simulator.hpp"

namespace morphogen {

void CpuSimulator::applyBrush(const Brush& brush) {
    checkBrush(brush, m_model, m_k.domain);
    if (brush.region.empty())
        return;
    m_nextMatches = false; // m_current changes alone
    const std::vector<BrushRegion::Cell>& cells = brush.region.cells();
    switch (brush.mode) {
    case BrushMode::Hold:
    case BrushMode::Release: {
        const bool hold = brush.mode == BrushMode::Hold;
        if (m_frozenMask.empty() && !hold)
            return;
        std::vector<std::uint8_t> mask = m_frozenMask;
        mask.resize(m_current.cellCount(), 0);
        for (const BrushRegion::Cell& cell : cells)
            mask[cell.index] = hold ? 1 : 0;
        if (std::none_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; }))
            mask.clear();
        setFrozen(mask);
        return;
    }
    case BrushMode::Paint: {
        int m = mappedIndex(m_k, m_model, brush.param);
        if (m < 0) {
            // The kernels were chosen for the maps there were; choose again.
            Session session = m_session;
            StepConstants k = withParamMap(session, m_k, brush.param);
            m_k = std::move(k);
            m_session = std::move(session);
            pickKernels();
            m = mappedIndex(m_k, m_model, brush.param);
        }
        float* plane = m_k.paramMaps.plane(m);
        for (const BrushRegion::Cell& cell : cells)
            plane[cell.index] = blend(plane[cell.index], brush.value, cell.weight);
        return;
    }
    default: {
        const int c = brush.chemical;
        const float lo = m_k.clampMin[std::size_t(c)], hi = m_k.clampMax[std::size_t(c)];
        float* plane = m_current.plane(c);
        const bool noisy = brush.mode == BrushMode::Randomise;
        for (const BrushRegion::Cell& cell : cells)
            plane[cell.index] =
                brushChemical(brush.mode, plane[cell.index], cell.weight, brush.value,
                              noisy ? brushNoise(brush.seed, cell.index) : 0.0f, lo, hi);
        return;
    }
    }
}

} // namespace morphogen
