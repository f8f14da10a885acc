#include "core/cpu_simulator.hpp"

#include <algorithm>
#include <cassert>

namespace morphogen {

CpuSimulator::CpuSimulator(const Session& session)
    : m_model(session.reactionModel()), m_k(StepConstants::fromSession(session)),
      m_current(session.width, session.height, m_k.chemicals),
      m_next(session.width, session.height, m_k.chemicals) {}

void CpuSimulator::setState(const State& state) {
    assert(state.width() == m_current.width() && state.height() == m_current.height() &&
           state.channels() == m_current.channels());
    m_current = state;
}

void CpuSimulator::run(int steps) {
    for (int i = 0; i < steps; ++i)
        step();
}

namespace {

// lap of one row. up/down are the neighbouring rows (already wrapped or
// clamped); columns 0 and w-1 wrap or clamp by the edge mode.
void laplacianRow(const float* up, const float* row, const float* down, float* out, int w,
                  EdgeMode edges, Stencil stencil) {
    auto at = [&](const float* r, int x) { return r[GridDomain::wrapOrClamp(x, w, edges)]; };
    auto edgeCell = [&](int x) {
        if (stencil == Stencil::FivePoint)
            return at(row, x - 1) + at(row, x + 1) + up[x] + down[x] - 4.0f * row[x];
        const float sides = at(row, x - 1) + at(row, x + 1) + up[x] + down[x];
        const float corners = at(up, x - 1) + at(up, x + 1) + at(down, x - 1) + at(down, x + 1);
        return (4.0f * sides + corners - 20.0f * row[x]) * (1.0f / 6.0f);
    };
    out[0] = edgeCell(0);
    if (w > 1)
        out[w - 1] = edgeCell(w - 1);
    if (stencil == Stencil::FivePoint) {
#pragma omp simd
        for (int x = 1; x < w - 1; ++x)
            out[x] = row[x - 1] + row[x + 1] + up[x] + down[x] - 4.0f * row[x];
    } else {
#pragma omp simd
        for (int x = 1; x < w - 1; ++x) {
            const float sides = row[x - 1] + row[x + 1] + up[x] + down[x];
            const float corners = up[x - 1] + up[x + 1] + down[x - 1] + down[x + 1];
            out[x] = (4.0f * sides + corners - 20.0f * row[x]) * (1.0f / 6.0f);
        }
    }
}

} // namespace

void CpuSimulator::step() {
    const int w = m_current.width(), h = m_current.height(), nc = m_k.chemicals;
    const EdgeMode edges = m_k.domain.edges();
    // Below ~64k cells a step takes microseconds and the fork/join barrier
    // would dominate (and spin-waits thrash when processes share the cores).
    const bool threaded = m_current.cellCount() >= 65536;
#pragma omp parallel if (threaded)
    {
        std::vector<float> scratch(std::size_t(w) * 2 * 4);
        float* lap[4];
        RowView view;
        view.n = w;
        for (int c = 0; c < 4; ++c) {
            lap[c] = scratch.data() + std::size_t(c) * w;
            view.dcdt[c] = scratch.data() + std::size_t(4 + c) * w;
        }
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            const int yUp = GridDomain::wrapOrClamp(y - 1, h, edges);
            const int yDown = GridDomain::wrapOrClamp(y + 1, h, edges);
            for (int c = 0; c < nc; ++c) {
                const float* plane = m_current.plane(c);
                view.c[c] = plane + std::size_t(y) * w;
                if (m_k.diffusion[c] != 0.0f)
                    laplacianRow(plane + std::size_t(yUp) * w, view.c[c],
                                 plane + std::size_t(yDown) * w, lap[c], w, edges, m_k.stencil);
                else
                    std::fill(lap[c], lap[c] + w, 0.0f);
            }
            m_model.react(view, m_k.params.data());
            for (int c = 0; c < nc; ++c) {
                const float* cur = view.c[c];
                const float* r = view.dcdt[c];
                const float* l = lap[c];
                float* out = m_next.plane(c) + std::size_t(y) * w;
                const float dt = m_k.dt, d = m_k.diffusion[c];
                const float lo = m_k.clampMin[c], hi = m_k.clampMax[c];
#pragma omp simd
                for (int x = 0; x < w; ++x)
                    out[x] = std::min(std::max(cur[x] + dt * (r[x] + d * l[x]), lo), hi);
            }
        }
    }
    std::swap(m_current, m_next);
}

} // namespace morphogen
