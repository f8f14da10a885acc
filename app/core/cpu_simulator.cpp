#include "core/cpu_simulator.hpp"

#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include <omp.h>

#include "core/models/gray_scott.hpp"
#include "core/models/turing_mcgraw.hpp"
#include "core/models/turing_turk.hpp"

// GCC builds an AVX2 copy of each fused kernel beside the baseline x86-64
// (SSE2) one and picks per machine when the program loads, so one binary
// runs anywhere and uses 8-wide vectors where it can. Not "fma", nor
// "arch=x86-64-v3", which implies it: GCC would then contract a * b + c into
// fused multiply-adds, and the CPU results would stop matching the generic
// path, older runs and llvmpipe bit for bit.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define MORPHOGEN_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MORPHOGEN_VECTOR_CLONES
#endif

namespace morphogen {

namespace {

using FusedKernel = void (*)(const StepConstants& k, const State& in, State& out, int y0, int y1);

// Below ~64k cells a step takes microseconds and the fork/join barrier
// would dominate (and spin-waits thrash when processes share the cores).
bool threaded(const State& state) {
    return state.cellCount() >= 65536;
}

// --- Fused path ----------------------------------------------------------------

// lap at column x of one chemical, xl and xr being its (wrapped or clamped)
// neighbour columns. The sums run in the order the generic path and the GLSL
// use; reordering them changes the last bits.
template <Stencil S>
inline float laplacian(const float* up, const float* row, const float* down, int xl, int x,
                       int xr) {
    if constexpr (S == Stencil::FivePoint) {
        return row[xl] + row[xr] + up[x] + down[x] - 4.0f * row[x];
    } else {
        const float sides = row[xl] + row[xr] + up[x] + down[x];
        const float corners = up[xl] + up[xr] + down[xl] + down[xr];
        return (4.0f * sides + corners - 20.0f * row[x]) * (1.0f / 6.0f);
    }
}

// Steps rows [y0, y1) with Cell's reaction inlined: one pass per row, every
// chemical's stencil, the reaction, the Euler update and the clamp per cell,
// and no row buffers. Requires (diffusion != 0) == Cell::diffuses() per
// chemical (fusedKernelIf checks), so no lap is spent on Turk's beta.
template <class Cell, Stencil S>
MORPHOGEN_VECTOR_CLONES void stepRowsFused(const StepConstants& k, const State& in, State& out,
                                           int y0, int y1) {
    constexpr int n = Cell::kChemicals;
    const Cell cell(k.params.data());
    const int w = in.width(), h = in.height();
    const EdgeMode edges = k.domain.edges();
    const float dt = k.dt;
    float d[n], lo[n], hi[n], dTimesZero[n];
    for (int c = 0; c < n; ++c) {
        d[c] = k.diffusion[c];
        lo[c] = k.clampMin[c];
        hi[c] = k.clampMax[c];
        // The generic path adds D * lap with lap filled with 0 for these.
        dTimesZero[c] = d[c] * 0.0f;
    }
    const int xFirstLeft = GridDomain::wrapOrClamp(-1, w, edges);
    const int xFirstRight = GridDomain::wrapOrClamp(1, w, edges);
    const int xLastRight = GridDomain::wrapOrClamp(w, w, edges);
    for (int y = y0; y < y1; ++y) {
        const std::size_t yUp = std::size_t(GridDomain::wrapOrClamp(y - 1, h, edges)) * w;
        const std::size_t yMid = std::size_t(y) * w;
        const std::size_t yDown = std::size_t(GridDomain::wrapOrClamp(y + 1, h, edges)) * w;
        const float *up[n], *row[n], *down[n];
        float* next[n];
        for (int c = 0; c < n; ++c) {
            const float* plane = in.plane(c);
            up[c] = plane + yUp;
            row[c] = plane + yMid;
            down[c] = plane + yDown;
            next[c] = out.plane(c) + yMid;
        }
        const auto stepCell = [&](int xl, int x, int xr) {
            float conc[n], dcdt[n];
            for (int c = 0; c < n; ++c)
                conc[c] = row[c][x];
            cell.react(conc, dcdt);
            for (int c = 0; c < n; ++c) {
                const float diffusion = Cell::diffuses(c)
                                            ? d[c] * laplacian<S>(up[c], row[c], down[c], xl, x, xr)
                                            : dTimesZero[c];
                next[c][x] = std::min(std::max(conc[c] + dt * (dcdt[c] + diffusion), lo[c]), hi[c]);
            }
        };
        stepCell(xFirstLeft, 0, xFirstRight);
        if (w > 1)
            stepCell(w - 2, w - 1, xLastRight);
#pragma omp simd
        for (int x = 1; x < w - 1; ++x)
            stepCell(x - 1, x, x + 1);
    }
}

// The fused kernel for a model, or null where the generic path must run:
// a model without a Cell here, or a zero diffusion rate on a chemical that
// normally diffuses (its lap must count as exactly 0, as the generic path has it).
template <class Model>
FusedKernel fusedKernelIf(const ReactionModel& model, const StepConstants& k) {
    using Cell = typename Model::Cell;
    if (dynamic_cast<const Model*>(&model) == nullptr)
        return nullptr;
    // The fused kernels know only the isotropic 5- and 9-point Laplacians.
    if (k.op.form != DiffusionOperator::Form::Laplacian5 &&
        k.op.form != DiffusionOperator::Form::Laplacian9)
        return nullptr;
    assert(Cell::kChemicals == k.chemicals);
    for (int c = 0; c < Cell::kChemicals; ++c)
        if ((k.diffusion[c] != 0.0f) != Cell::diffuses(c))
            return nullptr;
    if (k.stencil == Stencil::FivePoint)
        return &stepRowsFused<Cell, Stencil::FivePoint>;
    return &stepRowsFused<Cell, Stencil::NinePoint>;
}

FusedKernel fusedKernelFor(const ReactionModel& model, const StepConstants& k) {
    for (FusedKernel kernel :
         {fusedKernelIf<GrayScottModel>(model, k), fusedKernelIf<TuringTurkModel>(model, k),
          fusedKernelIf<TuringMcGrawModel>(model, k)})
        if (kernel != nullptr)
            return kernel;
    return nullptr;
}

// Denormals: Gray-Scott's background v decays through the denormal range,
// where every arithmetic op is ~100x slower on x86 (a quarter of the cells at
// 1024^2; flushing measured 1300 -> 2000 it/s there). Flushing them to zero
// changes values below 1e-38 only. MXCSR is per thread, so each parallel
// region sets it for its own threads.
class FlushDenormals {
public:
#if defined(__SSE2__)
    FlushDenormals() : m_saved(_mm_getcsr()) {
        _mm_setcsr(m_saved | 0x8040u);
    }
    ~FlushDenormals() {
        _mm_setcsr(m_saved);
    }

private:
    unsigned m_saved;
#endif
};

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

// Sum of a (3x3 or 5x5) kernel's taps over one row of one plane.
void kernelRow(const Kernel5& kernel, int radius, const float* plane, int w, int h, int y,
               EdgeMode edges, float* out) {
    std::fill(out, out + w, 0.0f);
    for (int dy = -radius; dy <= radius; ++dy) {
        const float* row = plane + std::size_t(GridDomain::wrapOrClamp(y + dy, h, edges)) * w;
        for (int dx = -radius; dx <= radius; ++dx) {
            const float weight = float(kernel.at(dx, dy));
            if (weight == 0.0f)
                continue;
            // Interior columns are unit-stride; the few edge columns wrap or clamp.
            const int x0 = std::min(radius, w), x1 = std::max(x0, w - radius);
#pragma omp simd
            for (int x = x0; x < x1; ++x)
                out[x] += weight * row[x + dx];
            for (int x = 0; x < x0; ++x)
                out[x] += weight * row[GridDomain::wrapOrClamp(x + dx, w, edges)];
            for (int x = x1; x < w; ++x)
                out[x] += weight * row[GridDomain::wrapOrClamp(x + dx, w, edges)];
        }
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

} // namespace

CpuSimulator::CpuSimulator(const Session& session)
    : m_model(session.reactionModel()), m_k(StepConstants::fromSession(session)),
      m_current(session.width, session.height, m_k.chemicals),
      m_next(session.width, session.height, m_k.chemicals) {
    m_fused = fusedKernelFor(m_model, m_k);
}

void CpuSimulator::setState(const State& state) {
    assert(state.width() == m_current.width() && state.height() == m_current.height() &&
           state.channels() == m_current.channels());
    m_current = state;
}

void CpuSimulator::run(int steps) {
    for (int i = 0; i < steps; ++i)
        step();
}

void CpuSimulator::step() {
    if (m_k.integrator == Integrator::SemiImplicit) {
        stepSemiImplicit();
        return;
    }
    if (m_fused == nullptr) {
        stepGeneric();
        return;
    }
    const int h = m_current.height();
    // One contiguous band of rows per thread, as schedule(static) would give,
    // with one kernel call per band rather than per row.
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        const int t = omp_get_thread_num(), threads = omp_get_num_threads();
        m_fused(m_k, m_current, m_next, int(std::int64_t(h) * t / threads),
                int(std::int64_t(h) * (t + 1) / threads));
    }
    std::swap(m_current, m_next);
}

void CpuSimulator::diffusionRow(int c, const float* plane, int y, float* out) const {
    const int w = m_current.width(), h = m_current.height();
    const EdgeMode edges = m_k.domain.edges();
    const DiffusionOperator& op = m_k.op;
    switch (op.form) {
    case DiffusionOperator::Form::Laplacian5:
    case DiffusionOperator::Form::Laplacian9: {
        const float d = op.rates[std::size_t(c)];
        if (d == 0.0f) {
            std::fill(out, out + w, 0.0f);
            return;
        }
        laplacianRow(plane + std::size_t(GridDomain::wrapOrClamp(y - 1, h, edges)) * w,
                     plane + std::size_t(y) * w,
                     plane + std::size_t(GridDomain::wrapOrClamp(y + 1, h, edges)) * w, out, w,
                     edges, m_k.stencil);
#pragma omp simd
        for (int x = 0; x < w; ++x)
            out[x] = d * out[x];
        return;
    }
    case DiffusionOperator::Form::Kernel3:
    case DiffusionOperator::Form::Kernel5:
        kernelRow(op.kernels[std::size_t(c)], op.form == DiffusionOperator::Form::Kernel3 ? 1 : 2,
                  plane, w, h, y, edges, out);
        return;
    case DiffusionOperator::Form::TensorMap:
        tensorMapRow(op, c, plane, w, h, y, edges, out);
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
        std::vector<float> scratch(std::size_t(w) * 2 * 4);
        float* term[4];
        RowView view;
        view.n = w;
        for (int c = 0; c < 4; ++c) {
            term[c] = scratch.data() + std::size_t(c) * w;
            view.dcdt[c] = scratch.data() + std::size_t(4 + c) * w;
        }
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            for (int c = 0; c < nc; ++c) {
                const float* plane = m_current.plane(c);
                view.c[c] = plane + std::size_t(y) * w;
                diffusionRow(c, plane, y, term[c]);
            }
            m_model.react(view, m_k.params.data());
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
    std::swap(m_current, m_next);
}

void CpuSimulator::stepSemiImplicit() {
    const int w = m_current.width(), h = m_current.height(), nc = m_k.chemicals;
    if (m_rhs.cellCount() == 0)
        m_rhs = State(w, h, nc);
    const float dt = m_k.dt;
#pragma omp parallel if (threaded(m_current))
    {
        const FlushDenormals flush;
        std::vector<float> scratch(std::size_t(w) * 4);
        RowView view;
        view.n = w;
        for (int c = 0; c < 4; ++c)
            view.dcdt[c] = scratch.data() + std::size_t(c) * w;
#pragma omp for schedule(static)
        for (int y = 0; y < h; ++y) {
            for (int c = 0; c < nc; ++c)
                view.c[c] = m_current.plane(c) + std::size_t(y) * w;
            m_model.react(view, m_k.params.data());
            for (int c = 0; c < nc; ++c) {
                float* rhs = m_rhs.plane(c) + std::size_t(y) * w;
#pragma omp simd
                for (int x = 0; x < w; ++x)
                    rhs[x] = view.c[c][x] + dt * view.dcdt[c][x];
            }
        }
    }
    // Relaxation sweeps from x0 = c: each reads m_current, writes m_next.
    for (int sweep = 0; sweep < m_k.jacobiSweeps; ++sweep) {
#pragma omp parallel if (threaded(m_current))
        {
            const FlushDenormals flush;
            std::vector<float> term(static_cast<std::size_t>(w));
#pragma omp for schedule(static)
            for (int y = 0; y < h; ++y)
                for (int c = 0; c < nc; ++c) {
                    const float* x0 = m_current.plane(c) + std::size_t(y) * w;
                    diffusionRow(c, m_current.plane(c), y, term.data());
                    const float* rhs = m_rhs.plane(c) + std::size_t(y) * w;
                    float* out = m_next.plane(c) + std::size_t(y) * w;
                    const float omega = m_k.omega[std::size_t(c)];
                    const float lo = m_k.clampMin[c], hi = m_k.clampMax[c];
#pragma omp simd
                    for (int x = 0; x < w; ++x)
                        out[x] = std::min(
                            std::max(x0[x] + omega * (rhs[x] - x0[x] + dt * term[std::size_t(x)]),
                                     lo),
                            hi);
                }
        }
        std::swap(m_current, m_next);
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

} // namespace morphogen
