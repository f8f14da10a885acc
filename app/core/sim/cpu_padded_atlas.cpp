#include "core/sim/cpu_padded_atlas.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "core/domain/atlas.hpp"
#include "core/sim/flush_denormals.hpp"

namespace morphogen {

PaddedAtlasStep::PaddedAtlasStep(const Atlas& atlas,
                                 const std::vector<std::array<std::uint32_t, 8>>& diagonals,
                                 const StepConstants& k)
    : m_atlas(atlas), m_n(atlas.tileSize()),
      m_tileRows((atlas.tileCount() + atlas.tilesPerRow() - 1) / atlas.tilesPerRow()),
      m_padded(atlas.tileSize() + 2), m_width(atlas.tilesPerRow() * (atlas.tileSize() + 2)) {
    assert(k.weighted());
    assert(!k.crossWeighted() || diagonals.size() == atlas.cellCount());
    const int n = m_n;
    const auto& next = atlas.neighbours();
    const auto across = [&](int t, int u, int v, Direction d) {
        return next[atlas.tileCell(t, u, v)][std::size_t(d)];
    };
    const std::size_t halo = 4 * std::size_t(n + 1);
    m_haloTo.reserve(halo * std::size_t(atlas.tileCount()));
    m_haloFrom.reserve(m_haloTo.capacity());
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const auto add = [&](int u, int v, std::uint32_t from) {
            m_haloTo.push_back(paddedCell(t, u, v));
            m_haloFrom.push_back(paddedOf(from));
        };
        // The four edges: the neighbour across of each edge texel (on an open
        // edge whatever the map holds there: its weight is 0).
        for (int i = 0; i < n; ++i) {
            add(-1, i, across(t, 0, i, Direction::MinusX));
            add(n, i, across(t, n - 1, i, Direction::PlusX));
            add(i, -1, across(t, i, 0, Direction::MinusY));
            add(i, n, across(t, i, n - 1, Direction::PlusY));
        }
        // The corners, read only by the corner texel's diagonal: its first
        // order's texel (the one a non-zero weight has; atlasDiagonals), or
        // the texel itself where nothing reads it.
        const std::array<std::array<int, 2>, 4> corners = {
            {{0, 0}, {n - 1, 0}, {0, n - 1}, {n - 1, n - 1}}};
        for (std::size_t s = 0; s < 4; ++s) {
            const int u = corners[s][0], v = corners[s][1];
            const std::uint32_t cell = atlas.tileCell(t, u, v);
            add(u == 0 ? -1 : n, v == 0 ? -1 : n, diagonals.empty() ? cell : diagonals[cell][s]);
        }
    }
    const int height = m_tileRows * m_padded;
    m_in = State(m_width, height, k.chemicals);
    m_out = State(m_width, height, k.chemicals);
}

std::uint32_t PaddedAtlasStep::paddedCell(int tile, int u, int v) const {
    const int tpr = m_atlas.tilesPerRow();
    const int x = (tile % tpr) * m_padded + 1 + u;
    const int y = (tile / tpr) * m_padded + 1 + v;
    return std::uint32_t(y) * std::uint32_t(m_width) + std::uint32_t(x);
}

std::uint32_t PaddedAtlasStep::paddedOf(std::uint32_t cell) const {
    const int tile = m_atlas.tileOf(cell);
    assert(tile >= 0);
    const auto w = std::uint32_t(m_atlas.width());
    const std::uint32_t origin = m_atlas.tileCell(tile, 0, 0);
    return paddedCell(tile, int(cell % w - origin % w), int(cell / w - origin / w));
}

std::vector<float> PaddedAtlasStep::padPlanes(const std::vector<float>& planes) const {
    const std::size_t cells = m_atlas.cellCount(), padded = m_in.cellCount();
    const std::size_t count = planes.size() / cells;
    assert(count * cells == planes.size());
    std::vector<float> out(count * padded, 0.0f);
    for (std::size_t p = 0; p < count; ++p)
        for (int t = 0; t < m_atlas.tileCount(); ++t)
            for (int v = 0; v < m_n; ++v)
                std::copy_n(planes.data() + p * cells + m_atlas.tileCell(t, 0, v), m_n,
                            out.data() + p * padded + paddedCell(t, 0, v));
    return out;
}

void PaddedAtlasStep::prepare(const StepConstants& k) {
    if (k.weightPlanes != m_sourceWeights || k.diagonalPlanes != m_sourceDiagonals) {
        m_k = k;
        m_sourceWeights = k.weightPlanes;
        m_sourceDiagonals = k.diagonalPlanes;
        m_k.weightPlanes = std::make_shared<const std::vector<float>>(padPlanes(*k.weightPlanes));
        if (k.diagonalPlanes)
            m_k.diagonalPlanes =
                std::make_shared<const std::vector<float>>(padPlanes(*k.diagonalPlanes));
    }
    // What the kernels and the passes read besides the planes; live changes
    // set them.
    m_k.dt = k.dt;
    m_k.relaxationPasses = k.relaxationPasses;
    m_k.contraction = k.contraction;
    m_k.chemicalContraction = k.chemicalContraction;
    m_k.op.rates = k.op.rates;
    m_k.params = k.params;
    m_k.clampMin = k.clampMin;
    m_k.clampMax = k.clampMax;
    // Only the chemicals that diffuse read their halo (the fused kernels run
    // with a rate of 0 exactly where the model does not diffuse).
    m_diffusing.clear();
    for (int c = 0; c < k.chemicals; ++c)
        if (k.op.rates[std::size_t(c)] != 0.0f)
            m_diffusing.push_back(c);
}

void PaddedAtlasStep::load(const State& state, State& to) const {
    for (int c = 0; c < state.channels(); ++c)
        for (int t = 0; t < m_atlas.tileCount(); ++t)
            for (int v = 0; v < m_n; ++v)
                std::copy_n(state.plane(c) + m_atlas.tileCell(t, 0, v), m_n,
                            to.plane(c) + paddedCell(t, 0, v));
}

void PaddedAtlasStep::store(int tile, State& state) const {
    for (int c = 0; c < state.channels(); ++c)
        for (int v = 0; v < m_n; ++v)
            std::copy_n(m_in.plane(c) + paddedCell(tile, 0, v), m_n,
                        state.plane(c) + m_atlas.tileCell(tile, 0, v));
}

void PaddedAtlasStep::fillHalos(int first, int end, const std::array<float*, kMaxChemicals>& planes,
                                const std::vector<int>* chemicals) const {
    const std::size_t halo = 4 * std::size_t(m_n + 1);
    const std::uint32_t* to = m_haloTo.data() + halo * std::size_t(first);
    const std::uint32_t* from = m_haloFrom.data() + halo * std::size_t(first);
    const std::size_t count = halo * std::size_t(end - first);
    for (int c : chemicals ? *chemicals : m_diffusing) {
        float* plane = planes[std::size_t(c)];
        // Halo cells and their sources (tile texels) are disjoint sets.
#pragma omp simd
        for (std::size_t i = 0; i < count; ++i)
            plane[to[i]] = plane[from[i]];
    }
}

template <class Block>
void PaddedAtlasStep::forEachBlock(bool all, bool threaded, const Block& block) const {
    const int tiles = m_atlas.tileCount(), tpr = m_atlas.tilesPerRow(), last = m_width - 1;
    if (all) {
#pragma omp parallel for schedule(static) if (threaded)
        for (int r = 0; r < m_tileRows; ++r) {
            const FlushDenormals flush;
            // Whole rows (the halo columns between tiles too, unread): one
            // long vector loop per row rather than one per tile.
            block(r * tpr, std::min((r + 1) * tpr, tiles), r * m_padded + 1, r * m_padded + 1 + m_n,
                  1, last);
        }
    } else {
        const int count = int(m_runs.size());
#pragma omp parallel for schedule(static) if (threaded)
        for (int i = 0; i < count; ++i) {
            const FlushDenormals flush;
            const TileRun& run = m_runs[std::size_t(i)];
            const int x0 = (run.first % tpr) * m_padded + 1, y0 = (run.first / tpr) * m_padded + 1;
            const int x1 = ((run.end - 1) % tpr) * m_padded + 1 + m_n;
            block(run.first, run.end, y0, y0 + m_n, x0, x1);
        }
    }
}

std::array<float*, kMaxChemicals> PaddedAtlasStep::inPlanes() {
    std::array<float*, kMaxChemicals> planes{};
    for (int c = 0; c < m_in.channels(); ++c)
        planes[std::size_t(c)] = m_in.plane(c);
    return planes;
}

void PaddedAtlasStep::step(StepTileKernel kernel, bool all,
                           const std::vector<std::uint32_t>& frozen, bool threaded) {
    const std::array<float*, kMaxChemicals> planes = inPlanes();
    // A halo is filled just before its tile steps: it reads m_in's tile
    // texels, which no thread writes during the step, and only its own tile
    // reads it, so no barrier; and the rows are in cache.
    forEachBlock(all, threaded, [&](int first, int end, int y0, int y1, int x0, int x1) {
        fillHalos(first, end, planes);
        kernel(m_k, m_in, m_out, y0, y1, x0, x1);
    });
    keepFrozen(frozen);
    std::swap(m_in, m_out);
}

void PaddedAtlasStep::setRuns(const std::vector<int>& active) {
    // Active tiles side by side on a row of tiles step as one span (its
    // halo columns in between are written, and refilled before being read).
    std::vector<int> sorted = active;
    std::sort(sorted.begin(), sorted.end());
    m_runs.clear();
    const int tpr = m_atlas.tilesPerRow();
    for (int t : sorted)
        if (!m_runs.empty() && m_runs.back().end == t && t % tpr != 0)
            ++m_runs.back().end;
        else
            m_runs.push_back({t, t + 1});
}

void PaddedAtlasStep::keepFrozen(const std::vector<std::uint32_t>& frozen) {
    for (int c = 0; c < m_in.channels(); ++c) {
        const float* from = m_in.plane(c);
        float* to = m_out.plane(c);
        for (std::uint32_t cell : frozen)
            to[cell] = from[cell];
    }
}

std::vector<std::uint32_t>
PaddedAtlasStep::paddedFrozen(const std::vector<std::uint32_t>& frozen) const {
    std::vector<std::uint32_t> padded;
    padded.reserve(frozen.size());
    for (std::uint32_t cell : frozen)
        if (m_atlas.used(cell)) // unused texels are never written
            padded.push_back(paddedOf(cell));
    return padded;
}

void PaddedAtlasStep::planPasses(int passes) {
    m_plan.own.fill(0);
    m_plan.relaxed.clear();
    m_plan.halos.clear();
    for (int c = 0; c < m_k.chemicals; ++c)
        m_plan.own[std::size_t(c)] = chemicalRelaxationPasses(m_k, c, passes);
    for (int pass = 0; pass < passes; ++pass) {
        // The chemicals still relaxing, and those of them whose halos this
        // pass reads (those that diffuse); none left ends the passes.
        std::vector<std::uint8_t> relaxed;
        std::vector<int> halos;
        for (int c = 0; c < m_k.chemicals; ++c)
            if (pass < m_plan.own[std::size_t(c)]) {
                relaxed.push_back(std::uint8_t(c));
                if (m_k.op.rates[std::size_t(c)] != 0.0f)
                    halos.push_back(c);
            }
        if (relaxed.empty())
            break;
        m_plan.relaxed.push_back(std::move(relaxed));
        m_plan.halos.push_back(std::move(halos));
    }
}

void PaddedAtlasStep::relaxPasses(const RelaxTileKernels& kernels, bool all,
                                  const std::vector<std::uint32_t>& frozen, bool threaded) {
    const int passes = int(m_plan.relaxed.size());
    for (int pass = 0; pass < passes; ++pass) {
        const std::vector<std::uint8_t>& relaxed = m_plan.relaxed[std::size_t(pass)];
        const std::vector<int>& halos = m_plan.halos[std::size_t(pass)];
        const RelaxTileKernel kernel = kernels.byCount[relaxed.size()];
        const std::array<float*, kMaxChemicals> planes = inPlanes();
        // As step: a block of tiles fills its own halos, then reads only them.
        forEachBlock(all, threaded, [&](int first, int end, int y0, int y1, int x0, int x1) {
            fillHalos(first, end, planes, &halos);
            kernel(m_k, relaxed.data(), m_in, m_rhs, m_out, y0, y1, x0, x1);
        });
        keepFrozen(frozen);
        std::swap(m_in, m_out);
    }
    // A chemical whose passes are done is not written again: each swap moves
    // it to the other buffer. Those left in m_out after an odd number of
    // such swaps come back once.
    for (int c = 0; c < m_k.chemicals; ++c)
        if ((passes - std::min(m_plan.own[std::size_t(c)], passes)) % 2 == 1)
            std::copy_n(m_out.plane(c), m_out.cellCount(), m_in.plane(c));
}

void PaddedAtlasStep::relax(const RelaxTileKernels& kernels, const StepConstants& k, State& state,
                            const State& rhs, int passes, const std::vector<std::uint32_t>& frozen,
                            bool threaded) {
    prepare(k);
    if (m_rhs.cellCount() == 0)
        m_rhs = State(m_in.width(), m_in.height(), m_in.channels());
    load(state, m_in);
    load(rhs, m_rhs);
    planPasses(passes);
    relaxPasses(kernels, true, paddedFrozen(frozen), threaded);
    for (int t = 0; t < m_atlas.tileCount(); ++t)
        store(t, state);
}

void PaddedAtlasStep::runSemiImplicit(StepTileKernel rhsKernel, const RelaxTileKernels& kernels,
                                      const StepConstants& k, State& state, int steps, int passes,
                                      const std::vector<int>& active,
                                      const std::vector<std::uint32_t>& frozen, bool threaded) {
    prepare(k);
    if (m_rhs.cellCount() == 0)
        m_rhs = State(m_in.width(), m_in.height(), m_in.channels());
    const std::vector<std::uint32_t> frozenPadded = paddedFrozen(frozen);
    planPasses(passes);
    load(state, m_in);
    const bool all = active.empty();
    if (!all)
        load(state, m_out); // the tiles that do not step hold their values in both
    setRuns(active);
    for (int i = 0; i < steps; ++i) {
        // The reaction reads no neighbour (the halos' rhs is never read).
        forEachBlock(all, threaded, [&](int, int, int y0, int y1, int x0, int x1) {
            rhsKernel(m_k, m_in, m_rhs, y0, y1, x0, x1);
        });
        relaxPasses(kernels, all, frozenPadded, threaded);
    }
    if (all)
        for (int t = 0; t < m_atlas.tileCount(); ++t)
            store(t, state);
    else
        for (int t : active)
            store(t, state);
}

void PaddedAtlasStep::run(StepTileKernel kernel, const StepConstants& k, State& state, int steps,
                          const std::vector<int>& active, const std::vector<std::uint32_t>& frozen,
                          bool threaded) {
    prepare(k);
    const std::vector<std::uint32_t> frozenPadded = paddedFrozen(frozen);
    load(state, m_in);
    // The tiles that do not step must hold their values in both buffers.
    if (!active.empty())
        load(state, m_out);
    setRuns(active);
    for (int i = 0; i < steps; ++i)
        step(kernel, active.empty(), frozenPadded, threaded);
    if (active.empty())
        for (int t = 0; t < m_atlas.tileCount(); ++t)
            store(t, state);
    else
        for (int t : active)
            store(t, state);
}

} // namespace morphogen
