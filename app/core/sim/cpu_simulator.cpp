#include "core/sim/cpu_simulator.hpp"

#include "core/base/errors.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include <omp.h>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_diagonals.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/flush_denormals.hpp"
#include "core/sim/spin_barrier.hpp"

namespace morphogen {

namespace {

// Below ~64k cells a step takes microseconds and the fork/join barrier
// would dominate (and spin-waits thrash when processes share the cores).
bool threaded(const State& state) {
    return state.cellCount() >= 65536;
}

// The first row of thread t's band of h rows among `threads`, as
// schedule(static) would split them (its band ends where t + 1's starts).
int bandStart(int h, int t, int threads) {
    return int(std::int64_t(h) * t / threads);
}

// Runs band(y0, y1) on one contiguous band of rows per thread, as
// schedule(static) would split them, with one kernel call per band rather
// than per row.
template <class Band> void forEachBand(const State& state, const Band& band) {
    const int h = state.height();
#pragma omp parallel if (threaded(state))
    {
        const FlushDenormals flush;
        const int t = omp_get_thread_num(), threads = omp_get_num_threads();
        band(bandStart(h, t, threads), bandStart(h, t + 1, threads));
    }
}

// --- Generic path ----------------------------------------------------------------

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

// Calls segment(base, width, edges) for the column segments of a row: the
// whole row on a grid, one periodic segment per tile on a tiled grid.
template <class Segment> void forEachRowSegment(const Domain& domain, const Segment& segment) {
    if (domain.kind() != DomainKind::TiledGrid) {
        segment(0, domain.width(), domain.edges());
        return;
    }
    for (int tx = 0; tx < domain.columns(); ++tx)
        segment(tx * domain.tileWidth(), domain.tileWidth(), EdgeMode::Periodic);
}

// Sum of a (3x3 or 5x5) kernel's taps over one row of one plane, in
// kernelTaps()' order and folding, as the fused kernels sum them (which adds
// the zero taps skipped here: only infinite neighbours could tell). R a
// constant and the bounds set inside the tap loop: GCC's code for either
// change measured ~20% slower (6 chemicals, 128^2, one thread). On a tiled
// grid every tile's columns wrap inside the tile.
template <int R>
void kernelRow(const KernelTaps& taps, const float* plane, const Domain& domain, int y,
               float* out) {
    assert(taps.radius == R);
    const int w = domain.width();
    std::fill(out, out + w, 0.0f);
    const auto rowAt = [&](int dy) { return plane + std::size_t(domain.neighbourRow(y, dy)) * w; };
    for (int i = 0; i < taps.count; ++i) {
        const KernelTap tap = taps.taps[std::size_t(i)];
        if (tap.weight == 0.0f)
            continue;
        const int dx = tap.dx;
        const float weight = tap.weight;
        const float* row = rowAt(tap.dy);
        // The tap and, folded, its point mirror: w * (c(dx, dy) + c(-dx, -dy)).
        const bool pair = taps.folded && i != 0;
        const float* mirror = pair ? rowAt(-tap.dy) : row;
        forEachRowSegment(domain, [&](int base, int sw, EdgeMode edges) {
            const float* r = row + base;
            const float* m = mirror + base;
            float* o = out + base;
            const auto column = [&](int x) { return GridDomain::wrapOrClamp(x, sw, edges); };
            // Interior columns are unit-stride; the few edge columns wrap or clamp.
            const int x0 = std::min(R, sw), x1 = std::max(x0, sw - R);
            if (!pair) {
#pragma omp simd
                for (int x = x0; x < x1; ++x)
                    o[x] += weight * r[x + dx];
                for (int x = 0; x < x0; ++x)
                    o[x] += weight * r[column(x + dx)];
                for (int x = x1; x < sw; ++x)
                    o[x] += weight * r[column(x + dx)];
                return;
            }
#pragma omp simd
            for (int x = x0; x < x1; ++x)
                o[x] += weight * (r[x + dx] + m[x - dx]);
            for (int x = 0; x < x0; ++x)
                o[x] += weight * (r[column(x + dx)] + m[column(x - dx)]);
            for (int x = x1; x < sw; ++x)
                o[x] += weight * (r[column(x + dx)] + m[column(x - dx)]);
        });
    }
}

// div(A(x) grad c) for one row with the tensor map, in the conservative form
// glsl/step.frag uses (face-averaged fluxes), so mass is conserved.
void tensorMapRow(const DiffusionOperator& op, int c, const float* plane, int w, int h, int y,
                  EdgeMode edges, float* out) {
    const std::array<float, 3>& k = op.mapCoefficients[std::size_t(c)];
    const float* ms = op.map.plane(0);
    const float* mc = op.map.plane(1);
    const float* mss = op.map.plane(2);
    auto index = [&](int x, int yy) {
        return std::size_t(GridDomain::wrapOrClamp(yy, h, edges)) * w +
               std::size_t(GridDomain::wrapOrClamp(x, w, edges));
    };
    auto axx = [&](std::size_t i) { return k[0] * ms[i] + k[1] * mc[i] - k[2] * mss[i]; };
    auto ayy = [&](std::size_t i) { return k[0] * ms[i] - k[1] * mc[i] + k[2] * mss[i]; };
    auto axy = [&](std::size_t i) { return -(k[1] * mss[i] + k[2] * mc[i]); };
    for (int x = 0; x < w; ++x) {
        const std::size_t ic = index(x, y), il = index(x - 1, y), ir = index(x + 1, y),
                          id = index(x, y - 1), iu = index(x, y + 1);
        const float cc = plane[ic], l = plane[il], r = plane[ir], d = plane[id], u = plane[iu];
        const float ru = plane[index(x + 1, y + 1)], rd = plane[index(x + 1, y - 1)];
        const float lu = plane[index(x - 1, y + 1)], ld = plane[index(x - 1, y - 1)];
        const float xx =
            0.5f * (axx(ic) + axx(ir)) * (r - cc) - 0.5f * (axx(ic) + axx(il)) * (cc - l);
        const float yy =
            0.5f * (ayy(ic) + ayy(iu)) * (u - cc) - 0.5f * (ayy(ic) + ayy(id)) * (cc - d);
        const float xy = 0.25f * (axy(ir) * (ru - rd) - axy(il) * (lu - ld)) +
                         0.25f * (axy(iu) * (ru - lu) - axy(id) * (rd - ld));
        out[x] = xx + yy + xy;
    }
}

// A weighted atlas row's interior texels (StepConstants::weightPlanes' sum and
// order): links the four link planes, diagonals the four diagonal planes or
// null; up, row, down the rows around y (start = y * w). Texels 0 and w - 1
// get 0 (border or unused: replaced or restored by the caller).
void weightedRow(const float* links, const float* diagonals, std::size_t cells, std::size_t start,
                 const float* up, const float* row, const float* down, int w, float* out) {
    const float *cpx = links + start, *cpy = links + cells + start;
    const float *cmx = links + 2 * cells + start, *cmy = links + 3 * cells + start;
    out[0] = out[w - 1] = 0.0f;
    if (diagonals) {
        const float* k = diagonals + start;
        const float *kmm = k, *kpm = k + cells, *kmp = k + 2 * cells, *kpp = k + 3 * cells;
#pragma omp simd
        for (int x = 1; x < w - 1; ++x) {
            const float a = cmx[x], b = cpx[x], d = cmy[x], e = cpy[x];
            const float sum = (((a + b) + d) + e) + ((kmm[x] + kpm[x]) + (kmp[x] + kpp[x]));
            const float sides = (((a * row[x - 1] + b * row[x + 1]) + d * up[x]) + e * down[x]) +
                                ((kmm[x] * up[x - 1] + kpm[x] * up[x + 1]) +
                                 (kmp[x] * down[x - 1] + kpp[x] * down[x + 1]));
            out[x] = sides - sum * row[x];
        }
    } else {
#pragma omp simd
        for (int x = 1; x < w - 1; ++x) {
            const float a = cmx[x], b = cpx[x], d = cmy[x], e = cpy[x];
            const float sum = ((a + b) + d) + e;
            out[x] = ((a * row[x - 1] + b * row[x + 1]) + d * up[x]) + e * down[x] - sum * row[x];
        }
    }
}

} // namespace

CpuSimulator::CpuSimulator(const Session& session)
    : m_session(session), m_model(session.reactionModel()),
      m_k(StepConstants::fromSession(session)),
      m_current(session.width, session.height, m_k.chemicals) {
    if (const Atlas* atlas = m_k.domain.atlasMap()) {
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
            if (!atlas->used(i))
                m_unusedCells.push_back(i);
        const std::vector<std::uint32_t>& border = atlas->borderCells();
        for (int y = 0; y <= atlas->height(); ++y)
            m_borderRows.push_back(
                std::size_t(std::lower_bound(border.begin(), border.end(), atlas->cellAt(0, y)) -
                            border.begin()));
        if (m_k.op.form == DiffusionOperator::Form::Laplacian9 || m_k.crossWeighted() ||
            m_k.tensorWeighted())
            m_diagonals = atlasDiagonals(*atlas);
    }
    pickKernels();
}

void CpuSimulator::setState(const State& state) {
    m_nextMatches = false;
    // (m_current is empty after takeState.)
    assert(state.width() == m_session.width && state.height() == m_session.height &&
           state.channels() == m_k.chemicals);
    m_current = state;
}

State CpuSimulator::takeState() {
    m_nextMatches = false;
    m_next = State();
    m_rhs = State();
    m_tileRuns.clear();
    return std::exchange(m_current, State());
}

std::optional<std::string> CpuSimulator::insaneValue(const ReactionModel& model) const {
    return findInsaneValue(m_current, model);
}

void CpuSimulator::run(int steps) {
    if (runTilesApart(steps))
        return;
    if (m_padded && m_weightedStep != nullptr) {
        m_nextMatches = false;
        const std::size_t n = std::size_t(m_k.domain.atlasMap()->tileSize());
        const bool many =
            m_activeTiles.empty() ? threaded(m_current) : m_activeTiles.size() * n * n >= 65536;
        m_padded->run(m_weightedStep, m_k, m_current, steps, m_activeTiles, m_frozenCells, many);
        return;
    }
    if (m_padded && m_weightedRelax && m_rhsTile != nullptr) {
        m_nextMatches = false;
        const std::size_t n = std::size_t(m_k.domain.atlasMap()->tileSize());
        const bool many =
            m_activeTiles.empty() ? threaded(m_current) : m_activeTiles.size() * n * n >= 65536;
        m_padded->runSemiImplicit(m_rhsTile, m_weightedRelax, m_k, m_current, steps,
                                  m_k.relaxationPasses, m_activeTiles, m_frozenCells, many);
        return;
    }
    // Made on the first step, not with the simulator: while a run is being
    // set up, its initial state and m_current are the two copies held.
    if (m_next.cellCount() != m_current.cellCount())
        m_next = State(m_current.width(), m_current.height(), m_current.channels());
    if (steps > 1 && fusedGridSteps()) {
        runFusedGridSteps(steps);
        return;
    }
    for (int i = 0; i < steps; ++i)
        step();
}

bool CpuSimulator::fusedGridSteps() const {
    // step()'s fused path with nothing between two steps but the swap.
    return m_activeTiles.empty() && m_k.integrator != Integrator::SemiImplicit &&
           m_explicitStep != nullptr && m_k.domain.kind() != DomainKind::Atlas &&
           m_frozenCells.empty() && m_unusedCells.empty();
}

void CpuSimulator::runFusedGridSteps(int steps) {
    // step() as one parallel region for all the steps: each thread keeps its
    // band of rows, and the threads meet at a SpinBarrier between steps
    // instead of forking and joining a team every step.
    m_nextMatches = false;
    const int h = m_current.height();
    std::optional<SpinBarrier> barrier;
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        const int t = omp_get_thread_num(), threads = omp_get_num_threads();
#pragma omp single
        barrier.emplace(threads);
        const int y0 = bandStart(h, t, threads), y1 = bandStart(h, t + 1, threads);
        State* current = &m_current;
        State* next = &m_next;
        for (int i = 0; i < steps; ++i) {
            if (i > 0)
                barrier->wait(); // every band of the last step is written
            m_explicitStep(m_k, *current, *next, y0, y1);
            std::swap(current, next);
        }
    }
    if (steps % 2 == 1)
        std::swap(m_current, m_next);
}

void CpuSimulator::setFrozen(const std::vector<std::uint8_t>& frozen) {
    assert(frozen.empty() || frozen.size() == m_current.cellCount());
    // An index list: frozen cells are few, and the fused kernels stay untouched.
    m_frozenMask = frozen;
    m_frozenCells.clear();
    for (std::size_t i = 0; i < frozen.size(); ++i)
        if (frozen[i])
            m_frozenCells.push_back(std::uint32_t(i));
}

void CpuSimulator::restoreFrozen() {
    for (int c = 0; c < m_k.chemicals; ++c) {
        const float* from = m_current.plane(c);
        float* to = m_next.plane(c);
        for (std::uint32_t i : m_frozenCells)
            to[i] = from[i];
        for (std::uint32_t i : m_unusedCells)
            to[i] = from[i];
    }
}

void CpuSimulator::atlasLaplacianRow(const float* plane, int y, Stencil stencil, int chemical,
                                     float* out) const {
    const Atlas& atlas = *m_k.domain.atlasMap();
    const int w = atlas.width(), h = atlas.height();
    // Every texel on the texture's outer ring is a border or unused texel, so
    // clamping there only keeps the reads inside; those results are replaced.
    const float* up = plane + std::size_t(GridDomain::wrapOrClamp(y - 1, h, EdgeMode::Clamped)) * w;
    const float* row = plane + std::size_t(y) * w;
    const float* down =
        plane + std::size_t(GridDomain::wrapOrClamp(y + 1, h, EdgeMode::Clamped)) * w;
    const std::size_t cells = atlas.cellCount(), start = std::size_t(y) * w;
    if (m_k.tensorWeighted()) {
        // p S + q1 L1 + q2 L2 (StepConstants::tensorPlanes), each summed as S is.
        const std::array<float, 3>& mix = m_k.tensorMixes[std::size_t(chemical)];
        std::vector<float> part(static_cast<std::size_t>(w));
        weightedRow(m_k.weightPlanes->data(),
                    m_k.crossWeighted() ? m_k.diagonalPlanes->data() : nullptr, cells, start, up,
                    row, down, w, out);
        for (int x = 0; x < w; ++x)
            out[x] *= mix[0];
        for (std::size_t q = 0; q < 2; ++q) {
            const float* t = m_k.tensorPlanes->data() + 8 * q * cells;
            weightedRow(t, t + 4 * cells, cells, start, up, row, down, w, part.data());
            const float m = mix[q + 1];
#pragma omp simd
            for (int x = 0; x < w; ++x)
                out[x] += m * part[std::size_t(x)];
        }
    } else if (m_k.weighted()) {
        // The fused kernel's weighted sum (stepRowsWeighted), for the generic path.
        weightedRow(m_k.weightPlanes->data(),
                    m_k.crossWeighted() ? m_k.diagonalPlanes->data() : nullptr, cells, start, up,
                    row, down, w, out);
    } else {
        laplacianRow(up, row, down, out, w, EdgeMode::Clamped, stencil);
    }
    const std::vector<std::uint32_t>& border = atlas.borderCells();
    for (std::size_t b = m_borderRows[std::size_t(y)]; b < m_borderRows[std::size_t(y) + 1]; ++b)
        out[border[b] - start] = atlasLaplacian(plane, border[b], stencil, chemical);
}

float CpuSimulator::weightedAt(const float* links, const float* diagonals, const float* plane,
                               std::uint32_t cell) const {
    // StepConstants::weightPlanes' order; the interior loop's.
    const std::array<std::uint32_t, 4>& n = m_k.domain.atlasMap()->neighbours()[cell];
    const std::size_t cells = m_current.cellCount();
    const float b = links[cell], e = links[cells + cell];
    const float a = links[2 * cells + cell], d = links[3 * cells + cell];
    float sum = ((a + b) + d) + e;
    float sides = ((a * plane[n[2]] + b * plane[n[0]]) + d * plane[n[3]]) + e * plane[n[1]];
    if (diagonals) {
        // Non-zero only where both orders reach one texel: order 0 serves.
        const float* k = diagonals + cell;
        const std::array<std::uint32_t, 8>& g = m_diagonals[cell];
        const float k0 = k[0], k1 = k[cells], k2 = k[2 * cells], k3 = k[3 * cells];
        sum += (k0 + k1) + (k2 + k3);
        sides += (k0 * plane[g[0]] + k1 * plane[g[1]]) + (k2 * plane[g[2]] + k3 * plane[g[3]]);
    }
    return sides - sum * plane[cell];
}

float CpuSimulator::atlasLaplacian(const float* plane, std::uint32_t cell, Stencil stencil,
                                   int chemical) const {
    if (m_k.tensorWeighted()) {
        const std::array<float, 3>& mix = m_k.tensorMixes[std::size_t(chemical)];
        const std::size_t cells = m_current.cellCount();
        const float* t = m_k.tensorPlanes->data();
        return mix[0] * weightedAt(m_k.weightPlanes->data(),
                                   m_k.crossWeighted() ? m_k.diagonalPlanes->data() : nullptr,
                                   plane, cell) +
               mix[1] * weightedAt(t, t + 4 * cells, plane, cell) +
               mix[2] * weightedAt(t + 8 * cells, t + 12 * cells, plane, cell);
    }
    if (m_k.weighted())
        return weightedAt(m_k.weightPlanes->data(),
                          m_k.crossWeighted() ? m_k.diagonalPlanes->data() : nullptr, plane, cell);
    const std::array<std::uint32_t, 4>& n = m_k.domain.atlasMap()->neighbours()[cell];
    // The interior loop's order: -x, +x, then the two vertical neighbours.
    const float sides = plane[n[2]] + plane[n[0]] + plane[n[3]] + plane[n[1]];
    if (stencil == Stencil::FivePoint)
        return sides - 4.0f * plane[cell];
    // Each diagonal the mean of its two orders (equal away from irregular
    // corners, where 0.5 (v + v) == v exactly); the grid's order of corners.
    const std::array<std::uint32_t, 8>& d = m_diagonals[cell];
    const float corners = 0.5f * (plane[d[0]] + plane[d[4]]) + 0.5f * (plane[d[1]] + plane[d[5]]) +
                          0.5f * (plane[d[2]] + plane[d[6]]) + 0.5f * (plane[d[3]] + plane[d[7]]);
    return (4.0f * sides + corners - 20.0f * plane[cell]) * (1.0f / 6.0f);
}

float CpuSimulator::atlasTerm(const float* plane, std::uint32_t cell, Stencil stencil,
                              int chemical) const {
    const float d = m_k.op.rates[std::size_t(chemical)];
    float term = 0.0f;
    if (d != 0.0f) {
        const float lap = atlasLaplacian(plane, cell, stencil, chemical);
        term = m_k.tensorWeighted() ? lap : d * lap;
    }
    const float drifts = m_k.drifts[std::size_t(chemical)];
    if (m_k.drifting() && drifts != 0.0f)
        term = term + drifts * driftAt(plane, cell);
    return term;
}

namespace {

// StepConstants::driftCarrier: the carrier's mobility at a texel, as step.frag's.
inline float mobility(float carrier, float cling) {
    const float w = std::max(carrier, 0.0f);
    return w / (w + cling);
}

} // namespace

float CpuSimulator::driftAt(const float* plane, std::uint32_t cell) const {
    // addDriftRow's order: -x, +x, -y, +y, then the outflow.
    const std::array<std::uint32_t, 4>& n = m_k.domain.atlasMap()->neighbours()[cell];
    const std::size_t cells = m_current.cellCount();
    const float* p = m_k.driftPlanes->data() + cell;
    const float px = p[0], py = p[cells], mx = p[2 * cells], my = p[3 * cells], out = p[4 * cells];
    if (m_k.driftCarrier < 0)
        return (((mx * plane[n[2]] + px * plane[n[0]]) + my * plane[n[3]]) + py * plane[n[1]]) -
               out * plane[cell];
    // What a texel passes on is its amount times its carrier's mobility.
    const float* w = m_current.plane(m_k.driftCarrier);
    const float cl = m_k.driftCling;
    const auto at = [&](std::uint32_t i) { return mobility(w[i], cl) * plane[i]; };
    return (((mx * at(n[2]) + px * at(n[0])) + my * at(n[3])) + py * at(n[1])) - out * at(cell);
}

void CpuSimulator::addDriftRow(const float* plane, int y, int chemical, float* out) const {
    const float drifts = m_k.drifts[std::size_t(chemical)];
    if (!m_k.drifting() || drifts == 0.0f)
        return;
    const Atlas& atlas = *m_k.domain.atlasMap();
    const int w = atlas.width(), h = atlas.height();
    const std::size_t cells = atlas.cellCount(), start = std::size_t(y) * w;
    const std::vector<std::uint32_t>& border = atlas.borderCells();
    const std::size_t first = m_borderRows[std::size_t(y)], end = m_borderRows[std::size_t(y) + 1];
    // The border texels' terms before the interior loop's (wrong) drift.
    float kept[64];
    std::vector<float> more;
    float* before = end - first <= 64 ? kept : (more.resize(end - first), more.data());
    for (std::size_t b = first; b < end; ++b)
        before[b - first] = out[border[b] - start];
    const float* up = plane + std::size_t(GridDomain::wrapOrClamp(y - 1, h, EdgeMode::Clamped)) * w;
    const float* row = plane + start;
    const float* down =
        plane + std::size_t(GridDomain::wrapOrClamp(y + 1, h, EdgeMode::Clamped)) * w;
    const float* p = m_k.driftPlanes->data() + start;
    const float *px = p, *py = p + cells, *mx = p + 2 * cells, *my = p + 3 * cells;
    const float* o = p + 4 * cells;
    // Texels 0 and w - 1 are border or unused texels (unused ones are restored).
    if (m_k.driftCarrier < 0) {
#pragma omp simd
        for (int x = 1; x < w - 1; ++x)
            out[x] =
                out[x] + drifts * ((((mx[x] * row[x - 1] + px[x] * row[x + 1]) + my[x] * up[x]) +
                                    py[x] * down[x]) -
                                   o[x] * row[x]);
    } else {
        const float* carrier = m_current.plane(m_k.driftCarrier);
        const float *cu = carrier + (up - plane), *cr = carrier + (row - plane),
                    *cd = carrier + (down - plane);
        const float cl = m_k.driftCling;
#pragma omp simd
        for (int x = 1; x < w - 1; ++x) {
            const float l = mobility(cr[x - 1], cl) * row[x - 1];
            const float r = mobility(cr[x + 1], cl) * row[x + 1];
            const float u = mobility(cu[x], cl) * up[x], d = mobility(cd[x], cl) * down[x];
            const float c = mobility(cr[x], cl) * row[x];
            out[x] =
                out[x] + drifts * ((((mx[x] * l + px[x] * r) + my[x] * u) + py[x] * d) - o[x] * c);
        }
    }
    for (std::size_t b = first; b < end; ++b)
        out[border[b] - start] = before[b - first] + drifts * driftAt(plane, border[b]);
}

void CpuSimulator::redoAtlasBorder() {
    // A weighted atlas's fused steps run through PaddedAtlasStep.
    assert(!m_k.weighted());
    const Stencil stencil = m_k.op.form == DiffusionOperator::Form::Laplacian5 ? Stencil::FivePoint
                                                                               : Stencil::NinePoint;
    const int nc = m_k.chemicals;
    const float dt = m_k.dt;
    const std::vector<std::uint32_t>& border = m_k.domain.atlasMap()->borderCells();
    // As the generic path: the reaction of a block of border texels gathered
    // into rows (one react() call per block), the term, the update and clamp.
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        constexpr std::size_t kBlock = 256;
        std::vector<float> scratch(kBlock * 2 * std::size_t(nc));
        RowView view;
        for (int c = 0; c < nc; ++c) {
            view.c[c] = scratch.data() + std::size_t(c) * kBlock;
            view.dcdt[c] = scratch.data() + std::size_t(nc + c) * kBlock;
        }
#pragma omp for schedule(static)
        for (std::size_t b0 = 0; b0 < border.size(); b0 += kBlock) {
            const std::size_t count = std::min(kBlock, border.size() - b0);
            view.n = int(count);
            for (int c = 0; c < nc; ++c) {
                float* conc = scratch.data() + std::size_t(c) * kBlock;
                for (std::size_t i = 0; i < count; ++i)
                    conc[i] = m_current.plane(c)[border[b0 + i]];
            }
            m_model.react(view, m_k.params.data());
            for (int c = 0; c < nc; ++c) {
                const float* plane = m_current.plane(c);
                for (std::size_t i = 0; i < count; ++i) {
                    const std::uint32_t cell = border[b0 + i];
                    const float term = atlasTerm(plane, cell, stencil, c);
                    m_next.plane(c)[cell] = std::min(
                        std::max(view.c[c][i] + dt * (view.dcdt[c][i] + term), m_k.clampMin[c]),
                        m_k.clampMax[c]);
                }
            }
        }
    }
}

void CpuSimulator::reactCells(RowView& view, std::size_t first, std::vector<float>& params) const {
    if (!m_k.hasParamMaps()) {
        m_model.react(view, m_k.params.data());
        return;
    }
    // One cell at a time with that cell's parameters: slower, but param maps
    // are for maps and sweeps, not for speed.
    const std::size_t row = first;
    RowView cell;
    cell.n = 1;
    for (int x = 0; x < view.n; ++x) {
        for (std::size_t m = 0; m < m_k.mappedParams.size(); ++m)
            params[std::size_t(m_k.mappedParams[m])] = m_k.paramMaps.plane(int(m))[row + x];
        for (int c = 0; c < m_k.chemicals; ++c) {
            cell.c[c] = view.c[c] + x;
            cell.dcdt[c] = view.dcdt[c] + x;
        }
        m_model.react(cell, params.data());
    }
}

void CpuSimulator::setActiveTiles(const std::vector<int>& tiles) {
    m_activeTiles = checkActiveTiles(m_k.domain, tiles);
    m_nextMatches = false;
}

void CpuSimulator::stepActiveTiles() {
    const Atlas& atlas = *m_k.domain.atlasMap();
    const int nc = m_k.chemicals, n = atlas.tileSize();
    const float dt = m_k.dt;
    if (!m_nextMatches) {
        for (int c = 0; c < nc; ++c)
            std::copy_n(m_current.plane(c), m_current.cellCount(), m_next.plane(c));
        m_nextMatches = true;
    }
    const Stencil stencil = m_k.op.form == DiffusionOperator::Form::Laplacian5 ? Stencil::FivePoint
                                                                               : Stencil::NinePoint;
    const int tiles = int(m_activeTiles.size());
    // A tile's rows, each one react() call and the index array's Laplacian
    // (the texels of a few tiles: no fused pass over the whole texture).
#pragma omp parallel if (std::size_t(tiles) * std::size_t(n) * std::size_t(n) >= 65536)
    {
        const FlushDenormals flush;
        std::vector<float> scratch(std::size_t(n) * std::size_t(nc));
        std::vector<float> params = m_k.params;
        RowView view;
        view.n = n;
        for (int c = 0; c < nc; ++c)
            view.dcdt[c] = scratch.data() + std::size_t(c) * std::size_t(n);
#pragma omp for schedule(static)
        for (int i = 0; i < tiles; ++i) {
            const int tile = m_activeTiles[std::size_t(i)];
            for (int v = 0; v < n; ++v) {
                const std::uint32_t start = atlas.tileCell(tile, 0, v);
                for (int c = 0; c < nc; ++c)
                    view.c[c] = m_current.plane(c) + start;
                reactCells(view, start, params);
                for (int c = 0; c < nc; ++c) {
                    const float* plane = m_current.plane(c);
                    float* out = m_next.plane(c);
                    const float lo = m_k.clampMin[c], hi = m_k.clampMax[c];
                    const int mapped = m_k.mappedRate[std::size_t(c)];
                    for (int u = 0; u < n; ++u) {
                        const std::uint32_t cell = start + std::uint32_t(u);
                        // A mapped rate: the operator was compiled at rate 1.
                        const float term = atlasTerm(plane, cell, stencil, c) *
                                           (mapped >= 0 ? m_k.paramMaps.plane(mapped)[cell] : 1.0f);
                        out[cell] =
                            std::min(std::max(plane[cell] + dt * (view.dcdt[c][u] + term), lo), hi);
                    }
                }
                if (!m_frozenMask.empty())
                    for (int u = 0; u < n; ++u)
                        if (m_frozenMask[start + std::uint32_t(u)])
                            for (int c = 0; c < nc; ++c)
                                m_next.plane(c)[start + std::uint32_t(u)] =
                                    m_current.plane(c)[start + std::uint32_t(u)];
            }
        }
    }
    std::swap(m_current, m_next);
}

void CpuSimulator::step() {
    // Without run()'s padded semi-implicit path (per-cell reaction
    // parameters) a semi-implicit step solves over the whole atlas: the
    // active tiles' explicit step would be unstable at its dt.
    if (!m_activeTiles.empty() && m_k.integrator != Integrator::SemiImplicit) {
        stepActiveTiles();
        return;
    }
    m_nextMatches = false;
    if (m_k.integrator == Integrator::SemiImplicit) {
        stepSemiImplicit();
        return;
    }
    if (m_explicitStep == nullptr) {
        stepGeneric();
        return;
    }
    forEachBand(m_current, [&](int y0, int y1) { m_explicitStep(m_k, m_current, m_next, y0, y1); });
    if (m_k.domain.kind() == DomainKind::Atlas)
        redoAtlasBorder();
    restoreFrozen();
    std::swap(m_current, m_next);
}

void CpuSimulator::diffusionRow(int c, const float* plane, int y, float* out) const {
    const int w = m_current.width(), h = m_current.height();
    const Domain& domain = m_k.domain;
    const DiffusionOperator& op = m_k.op;
    switch (op.form) {
    case DiffusionOperator::Form::Laplacian5:
    case DiffusionOperator::Form::Laplacian9: {
        const float d = op.rates[std::size_t(c)];
        if (domain.kind() == DomainKind::Atlas) {
            if (d == 0.0f) {
                std::fill(out, out + w, 0.0f);
            } else {
                atlasLaplacianRow(plane, y,
                                  op.form == DiffusionOperator::Form::Laplacian5
                                      ? Stencil::FivePoint
                                      : Stencil::NinePoint,
                                  c, out);
                // With anisotropy the chemical's mix holds its rate.
                if (!m_k.tensorWeighted()) {
#pragma omp simd
                    for (int x = 0; x < w; ++x)
                        out[x] = d * out[x];
                }
            }
            addDriftRow(plane, y, c, out);
            return;
        }
        if (d == 0.0f) {
            std::fill(out, out + w, 0.0f);
            return;
        }
        const float* up = plane + std::size_t(domain.neighbourRow(y, -1)) * w;
        const float* row = plane + std::size_t(y) * w;
        const float* down = plane + std::size_t(domain.neighbourRow(y, 1)) * w;
        const Stencil stencil = op.form == DiffusionOperator::Form::Laplacian5 ? Stencil::FivePoint
                                                                               : Stencil::NinePoint;
        forEachRowSegment(domain, [&](int base, int sw, EdgeMode edges) {
            laplacianRow(up + base, row + base, down + base, out + base, sw, edges, stencil);
        });
#pragma omp simd
        for (int x = 0; x < w; ++x)
            out[x] = d * out[x];
        return;
    }
    case DiffusionOperator::Form::Kernel3:
    case DiffusionOperator::Form::Kernel5:
        if (op.form == DiffusionOperator::Form::Kernel3)
            kernelRow<1>(m_kernelTaps[std::size_t(c)], plane, domain, y, out);
        else
            kernelRow<2>(m_kernelTaps[std::size_t(c)], plane, domain, y, out);
        return;
    case DiffusionOperator::Form::TensorMap:
        // fromSession refuses the tensor map on tiled grids and atlases.
        tensorMapRow(op, c, plane, w, h, y, domain.edges(), out);
        return;
    }
}

// Three passes per row through row buffers: the diffusion term of every
// chemical, the model's virtual react(), then the update and clamp.
void CpuSimulator::stepGeneric() {
    const int w = m_current.width(), h = m_current.height(), nc = m_k.chemicals;
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        std::vector<float> scratch(std::size_t(w) * 2 * std::size_t(nc));
        std::vector<float> params = m_k.params;
        float* term[kMaxChemicals];
        RowView view;
        view.n = w;
        for (int c = 0; c < nc; ++c) {
            term[c] = scratch.data() + std::size_t(c) * w;
            view.dcdt[c] = scratch.data() + std::size_t(nc + c) * w;
        }
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            for (int c = 0; c < nc; ++c) {
                const float* plane = m_current.plane(c);
                view.c[c] = plane + std::size_t(y) * w;
                diffusionRow(c, plane, y, term[c]);
                // A mapped rate: the operator was compiled at rate 1.
                if (const int m = m_k.mappedRate[std::size_t(c)]; m >= 0) {
                    const float* rate = m_k.paramMaps.plane(m) + std::size_t(y) * w;
                    for (int x = 0; x < w; ++x)
                        term[c][x] = rate[x] * term[c][x];
                }
            }
            reactCells(view, std::size_t(y) * std::size_t(w), params);
            for (int c = 0; c < nc; ++c) {
                const float* cur = view.c[c];
                const float* r = view.dcdt[c];
                const float* t = term[c];
                float* out = m_next.plane(c) + std::size_t(y) * w;
                const float dt = m_k.dt;
                const float lo = m_k.clampMin[c], hi = m_k.clampMax[c];
#pragma omp simd
                for (int x = 0; x < w; ++x)
                    out[x] = std::min(std::max(cur[x] + dt * (r[x] + t[x]), lo), hi);
            }
        }
    }
    restoreFrozen();
    std::swap(m_current, m_next);
}

void CpuSimulator::stepSemiImplicit() {
    const int w = m_current.width(), h = m_current.height();
    if (m_rhs.cellCount() == 0)
        m_rhs = State(w, h, m_k.chemicals);
    if (m_rhsPass != nullptr)
        forEachBand(m_current, [&](int y0, int y1) { m_rhsPass(m_k, m_current, m_rhs, y0, y1); });
    else
        rhsGeneric();
    if (m_weightedRelax) {
        m_padded->relax(m_weightedRelax, m_k, m_current, m_rhs, m_k.relaxationPasses, m_frozenCells,
                        threaded(m_current));
        return;
    }
    // fromSession refuses the tensor map here, so every operator has a sweep.
    assert(m_relax != nullptr);
    // Relaxation passes from x0 = c: each reads m_current, writes m_next.
    for (int sweep = 0; sweep < m_k.relaxationPasses; ++sweep) {
        forEachBand(m_current,
                    [&](int y0, int y1) { m_relax(m_k, m_current, m_rhs, m_next, y0, y1); });
        restoreFrozen(); // the iterate starts at c, so frozen cells keep c exactly
        std::swap(m_current, m_next);
    }
}

void CpuSimulator::rhsGeneric() {
    const int w = m_current.width(), h = m_current.height(), nc = m_k.chemicals;
    const float dt = m_k.dt;
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        std::vector<float> scratch(std::size_t(w) * std::size_t(nc));
        std::vector<float> params = m_k.params;
        RowView view;
        view.n = w;
        for (int c = 0; c < nc; ++c)
            view.dcdt[c] = scratch.data() + std::size_t(c) * w;
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            for (int c = 0; c < nc; ++c)
                view.c[c] = m_current.plane(c) + std::size_t(y) * w;
            reactCells(view, std::size_t(y) * std::size_t(w), params);
            for (int c = 0; c < nc; ++c) {
                float* rhs = m_rhs.plane(c) + std::size_t(y) * w;
#pragma omp simd
                for (int x = 0; x < w; ++x)
                    rhs[x] = view.c[c][x] + dt * view.dcdt[c][x];
            }
        }
    }
}

double CpuSimulator::lastSolveResidual() const {
    if (m_k.integrator != Integrator::SemiImplicit || m_rhs.cellCount() == 0)
        return 0.0;
    const int w = m_current.width(), h = m_current.height();
    std::vector<float> term(static_cast<std::size_t>(w));
    double worst = 0;
    for (int c = 0; c < m_k.chemicals; ++c)
        for (int y = 0; y < h; ++y) {
            diffusionRow(c, m_current.plane(c), y, term.data());
            const float* x = m_current.plane(c) + std::size_t(y) * w;
            const float* rhs = m_rhs.plane(c) + std::size_t(y) * w;
            for (int i = 0; i < w; ++i)
                worst =
                    std::max(worst, std::fabs(double(x[i]) - m_k.dt * double(term[std::size_t(i)]) -
                                              double(rhs[i])));
        }
    return worst;
}

void CpuSimulator::pickKernels() {
    m_tileRuns.clear(); // built from the old constants
    m_explicitStep = fusedExplicitStep(m_model, m_k);
    m_rhsPass = fusedRhsPass(m_model, m_k);
    m_relax = fusedRelaxation(m_k);
    const bool semiImplicit = m_k.integrator == Integrator::SemiImplicit;
    m_weightedStep = semiImplicit ? nullptr : fusedWeightedStep(m_model, m_k);
    m_weightedRelax = semiImplicit ? weightedRelaxation(m_k) : RelaxTileKernels{};
    m_rhsTile = m_weightedRelax ? fusedRhsTilePass(m_model, m_k) : nullptr;
    if (m_weightedStep != nullptr || m_weightedRelax) {
        if (!m_padded)
            m_padded = std::make_unique<PaddedAtlasStep>(*m_k.domain.atlasMap(), m_diagonals, m_k);
    } else {
        m_padded.reset();
    }
    // The generic path's taps follow the kernels, which live rate changes rescale.
    if (m_k.op.form == DiffusionOperator::Form::Kernel3 ||
        m_k.op.form == DiffusionOperator::Form::Kernel5)
        for (int c = 0; c < m_k.chemicals; ++c)
            m_kernelTaps[std::size_t(c)] = kernelTaps(m_k.op, c);
}

void CpuSimulator::applyLiveChange(Session next) {
    // Derived before anything changes: a refused change (InputError) leaves the run as it was.
    updateLiveConstants(m_k, next);
    m_session = std::move(next);
    pickKernels();
}

} // namespace morphogen
