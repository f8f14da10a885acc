#include "core/sim/cpu_kernels.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "core/models/builtin_models.hpp"
#include "core/sim/vector_clones.hpp"

// The loops below must be inlined into the clones to be built for AVX2 too.
// Lambdas holding a whole row's work need it said as well: GCC otherwise
// keeps them as one baseline (SSE2) function that the AVX2 clone calls.
#if defined(__GNUC__)
#define MORPHOGEN_INLINE inline __attribute__((always_inline))
#define MORPHOGEN_INLINE_LAMBDA __attribute__((always_inline))
#else
#define MORPHOGEN_INLINE inline
#define MORPHOGEN_INLINE_LAMBDA
#endif

namespace morphogen {

namespace {

// --- Diffusion terms -------------------------------------------------------------
//
// One chemical's A c at a cell, read through at(dx, dy) (the value dx columns
// right and dy rows down, already wrapped or clamped). The kernels call at()
// with constant offsets only, so interior columns become unit-stride loads.

// rate * the 5- or 9-point Laplacian, summed in the order the generic path
// and the GLSL use; reordering the sums changes the last bits.
template <Stencil S> class LaplacianTerm {
public:
    static constexpr int kRadius = 1;

    LaplacianTerm() = default;
    LaplacianTerm(const StepConstants& k, int c) : m_rate(k.op.rates[std::size_t(c)]) {}

    bool isZero() const { return m_rate == 0.0f; }

    template <class At> float operator()(const At& at) const {
        const float sides = at(-1, 0) + at(1, 0) + at(0, -1) + at(0, 1);
        if constexpr (S == Stencil::FivePoint)
            return m_rate * (sides - 4.0f * at(0, 0));
        const float corners = at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1);
        return m_rate * ((4.0f * sides + corners - 20.0f * at(0, 0)) * (1.0f / 6.0f));
    }

private:
    float m_rate = 0.0f;
};

constexpr int absolute(int v) {
    return v < 0 ? -v : v;
}

// Taps of a (2R+1)^2 kernel in glsl/step.frag's order: the centre, then
// each ring outwards, row by row (index (dy + R) * side + dx + R).
template <int R> constexpr std::array<int, (2 * R + 1) * (2 * R + 1)> tapOrder() {
    constexpr int side = 2 * R + 1;
    std::array<int, side * side> order{};
    std::size_t i = 0;
    for (int ring = 0; ring <= R; ++ring)
        for (int dy = -ring; dy <= ring; ++dy)
            for (int dx = -ring; dx <= ring; ++dx)
                if (std::max(absolute(dx), absolute(dy)) == ring)
                    order[i++] = (dy + R) * side + dx + R;
    return order;
}

// The taps of tapOrder<R>() that come before their point mirror (tap i's
// mirror is taps - 1 - i, in the same ring), in that order: each stands for
// the pair in a folded sum.
template <int R> constexpr std::array<int, (2 * R + 1) * (2 * R + 1) / 2> pairOrder() {
    constexpr int taps = (2 * R + 1) * (2 * R + 1);
    std::array<int, taps / 2> order{};
    std::size_t n = 0;
    for (int i : tapOrder<R>())
        if (i < taps / 2)
            order[n++] = i;
    return order;
}

bool centrallySymmetric(const Kernel5& kernel) {
    const std::size_t n = kernel.w.size();
    for (std::size_t i = 0; i < n / 2; ++i)
        if (float(kernel.w[i]) != float(kernel.w[n - 1 - i]))
            return false;
    return true;
}

template <int R> KernelTaps tapsOf(const Kernel5& kernel, bool folded) {
    constexpr int side = 2 * R + 1;
    KernelTaps taps;
    taps.folded = folded;
    taps.radius = R;
    const auto add = [&](int i) {
        const int dx = i % side - R, dy = i / side - R;
        taps.taps[std::size_t(taps.count++)] = {dx, dy, float(kernel.at(dx, dy))};
    };
    add(tapOrder<R>()[0]);
    if (folded)
        for (int i : pairOrder<R>())
            add(i);
    else
        for (std::size_t i = 1; i < tapOrder<R>().size(); ++i)
            add(tapOrder<R>()[i]);
    return taps;
}

// A chemical's 3x3 (R = 1) or 5x5 (R = 2) kernel, rate included, in float,
// summed as kernelTaps() says (folded when Folded). Zero taps are summed too,
// as on the GPU: the generic path's skipping them only differs for infinite
// neighbours.
template <int R, bool Folded> class KernelTerm {
public:
    static constexpr int kRadius = R;

    KernelTerm() = default;
    KernelTerm(const StepConstants& k, int c) {
        const Kernel5& kernel = k.op.kernels[std::size_t(c)];
        for (int dy = -R; dy <= R; ++dy)
            for (int dx = -R; dx <= R; ++dx)
                m_weights[std::size_t((dy + R) * kSide + dx + R)] = float(kernel.at(dx, dy));
    }

    bool isZero() const {
        return std::all_of(m_weights.begin(), m_weights.end(), [](float v) { return v == 0.0f; });
    }

    template <class At> float operator()(const At& at) const {
        if constexpr (Folded)
            return sumPairs(at, std::make_index_sequence<kTaps / 2>());
        else
            return sum(at, std::make_index_sequence<kTaps - 1>());
    }

private:
    static constexpr int kSide = 2 * R + 1;
    static constexpr int kTaps = kSide * kSide;
    static constexpr std::array<int, kTaps> kOrder = tapOrder<R>();
    static constexpr std::array<int, kTaps / 2> kPairs = pairOrder<R>();

    template <int I, class At> float tap(const At& at) const {
        return m_weights[std::size_t(I)] * at(I % kSide - R, I / kSide - R);
    }
    template <int I, class At> float pair(const At& at) const {
        constexpr int dx = I % kSide - R, dy = I / kSide - R;
        return m_weights[std::size_t(I)] * (at(dx, dy) + at(-dx, -dy));
    }
    // Folds rather than loops, so that every tap's offsets are constants
    // before the vectoriser runs.
    template <class At, std::size_t... I> float sum(const At& at, std::index_sequence<I...>) const {
        float s = tap<kOrder[0]>(at);
        ((s += tap<kOrder[I + 1]>(at)), ...);
        return s;
    }
    template <class At, std::size_t... I>
    float sumPairs(const At& at, std::index_sequence<I...>) const {
        float s = tap<kOrder[0]>(at);
        ((s += pair<kPairs[I]>(at)), ...);
        return s;
    }

    std::array<float, kTaps> m_weights{};
};

// --- Row access ----------------------------------------------------------------

// The 2R+1 rows around y of one plane, wrapped or clamped by the domain
// (inside y's tile on a tiled grid).
template <int R>
MORPHOGEN_INLINE void rowWindow(const float* plane, int y, int w, const Domain& domain,
                                const float** rows) {
    for (int dy = -R; dy <= R; ++dy)
        rows[dy + R] = plane + std::size_t(domain.neighbourRow(y, dy)) * w;
}

// Calls cell(x, column) for every column of the segment [base, base + w) of a
// row, column(dx) being the index of the column dx away. Interior columns come
// first in one unit-stride, vectorised loop; the R columns at each end wrap or
// clamp inside the segment. A grid's row is one segment at base 0 (a constant
// once inlined); a tiled grid's row is one segment per tile, each periodic.
template <int R, class Cell>
MORPHOGEN_INLINE void forEachColumn(int base, int w, EdgeMode edges, const Cell& cell) {
    const int x0 = std::min(R, w), x1 = std::max(x0, w - R);
#pragma omp simd
    for (int x = base + x0; x < base + x1; ++x)
        cell(x, [x](int dx) { return x + dx; });
    // One loop with one call, so that GCC inlines it into the AVX2 clone too:
    // SSE code called from there pays for the switch between encodings.
    for (int i = 0; i < x0 + w - x1; ++i) {
        const int x = i < x0 ? i : x1 + i - x0;
        int columns[2 * R + 1];
        for (int dx = -R; dx <= R; ++dx)
            columns[dx + R] = base + GridDomain::wrapOrClamp(x + dx, w, edges);
        cell(base + x, [&columns](int dx) { return columns[dx + R]; });
    }
}

// Calls segment(base, width, params) for the column segments of row y: the
// whole row with the session's parameters on a grid, one per tile with that
// tile's parameters on a tiled grid.
template <bool Tiled, class Segment>
MORPHOGEN_INLINE void forEachSegment(const StepConstants& k, int y, int w, const Segment& segment) {
    if constexpr (!Tiled) {
        segment(0, w, k.params.data());
    } else {
        const int tw = k.domain.tileWidth(), ty = y / k.domain.tileHeight();
        for (int tx = 0; tx < k.domain.columns(); ++tx)
            segment(tx * tw, tw, k.tileParamsAt(tx, ty));
    }
}

// --- Kernels -------------------------------------------------------------------

// Explicit Euler on rows [y0, y1) with Cell's reaction inlined: one pass per
// row, every chemical's stencil, the reaction, the update and the clamp per
// cell, and no row buffers. Chemicals that do not diffuse get a term of
// exactly 0, as the generic path has it (fusedExplicitStep checks their
// operator is zero).
template <class Cell, class Term, bool Tiled>
MORPHOGEN_VECTOR_CLONES void stepRows(const StepConstants& k, const State& in, State& out, int y0,
                                      int y1) {
    constexpr int n = Cell::kChemicals, r = Term::kRadius;
    const int w = in.width();
    const EdgeMode edges = k.domain.edges();
    const float dt = k.dt;
    Term terms[n];
    float lo[n], hi[n];
    for (int c = 0; c < n; ++c) {
        terms[c] = Term(k, c);
        lo[c] = k.clampMin[c];
        hi[c] = k.clampMax[c];
    }
    for (int y = y0; y < y1; ++y) {
        const float* rows[n][2 * r + 1];
        float* next[n];
        for (int c = 0; c < n; ++c) {
            rowWindow<r>(in.plane(c), y, w, k.domain, rows[c]);
            next[c] = out.plane(c) + std::size_t(y) * w;
        }
        const auto segment = [&](int base, int width, const float* params) MORPHOGEN_INLINE_LAMBDA {
            const Cell cell(params);
            forEachColumn<r>(base, width, edges, [&](int x, const auto& column) {
                float conc[n], dcdt[n];
                for (int c = 0; c < n; ++c)
                    conc[c] = rows[c][r][x];
                cell.react(conc, dcdt);
                // Unrolled (up to kMaxChemicals) before the vectoriser runs, which a 5x5
                // body would not be by default.
#pragma GCC unroll 12
                for (int c = 0; c < n; ++c) {
                    const float* const* window = rows[c];
                    const float diffusion =
                        Cell::diffuses(c)
                            ? terms[c]([&](int dx, int dy) { return window[dy + r][column(dx)]; })
                            : 0.0f;
                    next[c][x] =
                        std::min(std::max(conc[c] + dt * (dcdt[c] + diffusion), lo[c]), hi[c]);
                }
            });
        };
        forEachSegment<Tiled>(k, y, w, segment);
    }
}

// One row of a weighted atlas padded by halos (PaddedAtlasStep): its weight
// planes' pointers, and per texel the weights' sum S and a chemical's
// weighted neighbours ("sides"), summed in the order both backends use
// (StepConstants::weightPlanes). Cross: the diagonals too
// (StepConstants::diagonalPlanes), a texel's diagonals being the padded
// grid's; every read is inside the texture (the outer rows and columns 0 and
// w-1 are halo, never stepped).
template <bool Cross> struct WeightRow {
    const float* px;
    const float* py;
    const float* mx;
    const float* my;
    // Diagonal planes (-x,-y), (+x,-y), (-x,+y), (+x,+y); unread without Cross.
    const float* mm = nullptr;
    const float* pm = nullptr;
    const float* mp = nullptr;
    const float* pp = nullptr;

    WeightRow(const StepConstants& k, std::size_t cells, std::size_t row) {
        const float* planes = k.weightPlanes->data();
        px = planes + row;
        py = planes + cells + row;
        mx = planes + 2 * cells + row;
        my = planes + 3 * cells + row;
        if constexpr (Cross) {
            const float* diagonals = k.diagonalPlanes->data();
            mm = diagonals + row;
            pm = diagonals + cells + row;
            mp = diagonals + 2 * cells + row;
            pp = diagonals + 3 * cells + row;
        }
    }
};

// Texel x's weights, read once for all its chemicals.
struct TexelWeights {
    float l, r, d, u;                     // links -x, +x, -y, +y
    float k0 = 0, k1 = 0, k2 = 0, k3 = 0; // diagonals
    float sum;
};

template <bool Cross> MORPHOGEN_INLINE TexelWeights texelWeights(const WeightRow<Cross>& w, int x) {
    TexelWeights t;
    t.l = w.mx[x];
    t.r = w.px[x];
    t.d = w.my[x];
    t.u = w.py[x];
    t.sum = ((t.l + t.r) + t.d) + t.u;
    if constexpr (Cross) {
        t.k0 = w.mm[x];
        t.k1 = w.pm[x];
        t.k2 = w.mp[x];
        t.k3 = w.pp[x];
        t.sum += (t.k0 + t.k1) + (t.k2 + t.k3);
    }
    return t;
}

// Sum over texel x's neighbours of weight times value, for one chemical's rows.
template <bool Cross>
MORPHOGEN_INLINE float weightedSides(const TexelWeights& t, const float* mid, const float* down,
                                     const float* up, int x) {
    float sides = ((t.l * mid[x - 1] + t.r * mid[x + 1]) + t.d * down[x]) + t.u * up[x];
    if constexpr (Cross)
        sides += (t.k0 * down[x - 1] + t.k1 * down[x + 1]) + (t.k2 * up[x - 1] + t.k3 * up[x + 1]);
    return sides;
}

// Chemical c's rows y - 1, y and y + 1 (clamped) of `state`.
struct RowTriple {
    const float* down;
    const float* mid;
    const float* up;
};
MORPHOGEN_INLINE RowTriple rowTriple(const State& state, int c, int y) {
    const std::size_t w = std::size_t(state.width());
    const float* plane = state.plane(c);
    return {plane + std::size_t(y > 0 ? y - 1 : y) * w, plane + std::size_t(y) * w,
            plane + std::size_t(y < state.height() - 1 ? y + 1 : y) * w};
}

// Explicit Euler on rows [y0, y1), columns [x0, x1), of a weighted atlas
// padded by halos: stepRows with the weighted term (WeightRow), the
// coefficients streamed unit-stride from their planes.
template <class Cell, bool Cross>
MORPHOGEN_VECTOR_CLONES void stepRowsWeighted(const StepConstants& k, const State& in, State& out,
                                              int y0, int y1, int x0, int x1) {
    constexpr int n = Cell::kChemicals;
    const int w = in.width();
    const float dt = k.dt;
    float rate[n], lo[n], hi[n];
    for (int c = 0; c < n; ++c) {
        rate[c] = k.op.rates[std::size_t(c)];
        lo[c] = k.clampMin[c];
        hi[c] = k.clampMax[c];
    }
    const Cell cell(k.params.data());
    for (int y = y0; y < y1; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(w);
        const WeightRow<Cross> weights(k, in.cellCount(), row);
        RowTriple rows[n];
        float* next[n];
        for (int c = 0; c < n; ++c) {
            rows[c] = rowTriple(in, c, y);
            next[c] = out.plane(c) + row;
        }
        // A lambda, so that conc and dcdt are not omp simd's per-lane arrays.
        const auto texel = [&](int x) MORPHOGEN_INLINE_LAMBDA {
            float conc[n], dcdt[n];
            for (int c = 0; c < n; ++c)
                conc[c] = rows[c].mid[x];
            cell.react(conc, dcdt);
            const TexelWeights t = texelWeights(weights, x);
#pragma GCC unroll 12
            for (int c = 0; c < n; ++c) {
                const float sides =
                    weightedSides<Cross>(t, rows[c].mid, rows[c].down, rows[c].up, x);
                const float diffusion =
                    Cell::diffuses(c) ? rate[c] * (sides - t.sum * conc[c]) : 0.0f;
                next[c][x] = std::min(std::max(conc[c] + dt * (dcdt[c] + diffusion), lo[c]), hi[c]);
            }
        };
#pragma omp simd
        for (int x = x0; x < x1; ++x)
            texel(x);
    }
}

// One Jacobi pass on rows [y0, y1), columns [x0, x1), of a weighted atlas
// padded by halos: x' = clamp((rhs + dt r sides) / (1 + dt r S)) for the N
// chemicals listed. A chemical that does not diffuse (r = 0) gets rhs.
// Texel-major over the N chemicals, as the explicit kernel: the weights are
// read once per texel.
template <int N, bool Cross>
MORPHOGEN_VECTOR_CLONES void
relaxRowsWeighted(const StepConstants& k, const std::uint8_t* chemicals, const State& in,
                  const State& rhs, State& out, int y0, int y1, int x0, int x1) {
    const int w = in.width();
    float a[N], lo[N], hi[N];
    for (int i = 0; i < N; ++i) {
        const int c = chemicals[i];
        a[i] = k.dt * k.op.rates[std::size_t(c)];
        lo[i] = k.clampMin[c];
        hi[i] = k.clampMax[c];
    }
    for (int y = y0; y < y1; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(w);
        const WeightRow<Cross> weights(k, in.cellCount(), row);
        RowTriple rows[N];
        const float* b[N];
        float* next[N];
        for (int i = 0; i < N; ++i) {
            const int c = chemicals[i];
            rows[i] = rowTriple(in, c, y);
            b[i] = rhs.plane(c) + row;
            next[i] = out.plane(c) + row;
        }
#pragma omp simd
        for (int x = x0; x < x1; ++x) {
            const TexelWeights t = texelWeights(weights, x);
#pragma GCC unroll 12
            for (int i = 0; i < N; ++i) {
                const float sides =
                    weightedSides<Cross>(t, rows[i].mid, rows[i].down, rows[i].up, x);
                next[i][x] = std::min(
                    std::max((b[i][x] + a[i] * sides) / (1.0f + a[i] * t.sum), lo[i]), hi[i]);
            }
        }
    }
}

template <bool Cross, std::size_t... I> RelaxTileKernels relaxForCounts(std::index_sequence<I...>) {
    return {{nullptr, &relaxRowsWeighted<int(I) + 1, Cross>...}};
}

// rhs = c + dt react(c) on columns [x0, x1) of one row (`row`, `rhs`: each
// chemical's row of the state and of the right-hand side).
template <class Cell, int N>
MORPHOGEN_INLINE void rhsSpan(const Cell& cell, float dt, const float* const (&row)[N],
                              float* const (&rhs)[N], int x0, int x1) {
    // A lambda, so that conc and dcdt are not omp simd's per-lane arrays,
    // which GCC fails to vectorise.
    const auto rhsCell = [&](int x) {
        float conc[N], dcdt[N];
        for (int c = 0; c < N; ++c)
            conc[c] = row[c][x];
        cell.react(conc, dcdt);
        for (int c = 0; c < N; ++c)
            rhs[c][x] = conc[c] + dt * dcdt[c];
    };
#pragma omp simd
    for (int x = x0; x < x1; ++x)
        rhsCell(x);
}

// rhs = c + dt react(c) on rows [y0, y1), columns [x0, x1), with the
// session's parameters (a weighted atlas's padded tiles).
template <class Cell>
MORPHOGEN_VECTOR_CLONES void rhsBlock(const StepConstants& k, const State& in, State& out, int y0,
                                      int y1, int x0, int x1) {
    constexpr int n = Cell::kChemicals;
    const int w = in.width();
    const Cell cell(k.params.data());
    for (int y = y0; y < y1; ++y) {
        const float* row[n];
        float* rhs[n];
        for (int c = 0; c < n; ++c) {
            row[c] = in.plane(c) + std::size_t(y) * w;
            rhs[c] = out.plane(c) + std::size_t(y) * w;
        }
        rhsSpan<Cell, n>(cell, k.dt, row, rhs, x0, x1);
    }
}

// rhs = c + dt react(c) on rows [y0, y1).
template <class Cell, bool Tiled>
MORPHOGEN_VECTOR_CLONES void rhsRows(const StepConstants& k, const State& in, State& out, int y0,
                                     int y1) {
    constexpr int n = Cell::kChemicals;
    const int w = in.width();
    for (int y = y0; y < y1; ++y) {
        const float* row[n];
        float* rhs[n];
        for (int c = 0; c < n; ++c) {
            row[c] = in.plane(c) + std::size_t(y) * w;
            rhs[c] = out.plane(c) + std::size_t(y) * w;
        }
        const auto segment = [&](int base, int width, const float* params) MORPHOGEN_INLINE_LAMBDA {
            rhsSpan<Cell, n>(Cell(params), k.dt, row, rhs, base, base + width);
        };
        forEachSegment<Tiled>(k, y, w, segment);
    }
}

// One relaxation pass on rows [y0, y1). Chemicals are independent here, so
// each runs on its own; one with a zero operator skips the stencil (its term
// is exactly 0, as the generic path's).
template <class Term, bool Tiled>
MORPHOGEN_VECTOR_CLONES void relaxRows(const StepConstants& k, const State& x, const State& rhs,
                                       State& out, int y0, int y1) {
    constexpr int r = Term::kRadius;
    const int w = x.width();
    const EdgeMode edges = k.domain.edges();
    const float dt = k.dt;
    for (int c = 0; c < k.chemicals; ++c) {
        const Term term(k, c);
        const bool diffuses = !term.isZero();
        const float omega = k.omega[std::size_t(c)];
        const float lo = k.clampMin[c], hi = k.clampMax[c];
        for (int y = y0; y < y1; ++y) {
            const float* window[2 * r + 1];
            rowWindow<r>(x.plane(c), y, w, k.domain, window);
            const float* x0 = window[r];
            const float* b = rhs.plane(c) + std::size_t(y) * w;
            float* next = out.plane(c) + std::size_t(y) * w;
            const auto update = [&](int i, float diffusion) {
                next[i] =
                    std::min(std::max(x0[i] + omega * (b[i] - x0[i] + dt * diffusion), lo), hi);
            };
            if (!diffuses) {
#pragma omp simd
                for (int i = 0; i < w; ++i)
                    update(i, 0.0f);
                continue;
            }
            const auto segment = [&](int base, int width, const float*) MORPHOGEN_INLINE_LAMBDA {
                forEachColumn<r>(base, width, edges, [&](int i, const auto& column) {
                    update(i, term([&](int dx, int dy) { return window[dy + r][column(dx)]; }));
                });
            };
            forEachSegment<Tiled>(k, y, w, segment);
        }
    }
}

// --- Selection -------------------------------------------------------------------

template <class T> struct Tag { using Type = T; };

// Calls pick(Tag<Model::Cell>) for the built-in model `model` is; null for others.
template <class Kernel = StepRowsKernel, class Pick>
Kernel withCell(const ReactionModel& model, const Pick& pick) {
    Kernel kernel = nullptr;
    visitBuiltinModel(model, [&](const auto& builtin) {
        using Model = std::decay_t<decltype(builtin)>;
        kernel = pick(Tag<typename Model::Cell>());
    });
    return kernel;
}

// Every built-in model has fused kernels, up to kMaxChemicals chemicals. They
// used to stop at four: beyond that the kernel did not vectorise and the
// generic path's row passes won, but the cause was GCC declining to inline the
// larger Cells' react() (MORPHOGEN_CELL_REACT, reaction_model.hpp). Inlined,
// the fused step of a 6- to 10-chemical model runs 1.4x-2.8x the generic one's
// steps per second (bench, 256 and 512 cells).
template <class Cell, class Term> StepRowsKernel explicitIf(const StepConstants& k) {
    assert(Cell::kChemicals == k.chemicals);
    for (int c = 0; c < Cell::kChemicals; ++c)
        if (Term(k, c).isZero() == Cell::diffuses(c))
            return nullptr;
    return k.tiled() ? &stepRows<Cell, Term, true> : &stepRows<Cell, Term, false>;
}

template <class Term> RelaxRowsKernel relaxFor(const StepConstants& k) {
    return k.tiled() ? &relaxRows<Term, true> : &relaxRows<Term, false>;
}

// Per-cell parameters stop the fused kernels, except a tiled grid's
// per-tile ones (one Cell per tile segment) that are not diffusion rates.
bool fusedParamsOk(const StepConstants& k) {
    return !k.hasParamMaps() || k.paramsPerTileOnly();
}

} // namespace

bool foldsKernels(const DiffusionOperator& op) {
    if (op.form != DiffusionOperator::Form::Kernel3 && op.form != DiffusionOperator::Form::Kernel5)
        return false;
    for (int c = 0; c < op.chemicals; ++c)
        if (!centrallySymmetric(op.kernels[std::size_t(c)]))
            return false;
    return true;
}

KernelTaps kernelTaps(const DiffusionOperator& op, int chemical) {
    assert(op.form == DiffusionOperator::Form::Kernel3 ||
           op.form == DiffusionOperator::Form::Kernel5);
    const Kernel5& kernel = op.kernels[std::size_t(chemical)];
    return op.form == DiffusionOperator::Form::Kernel3 ? tapsOf<1>(kernel, foldsKernels(op))
                                                       : tapsOf<2>(kernel, foldsKernels(op));
}

StepRowsKernel fusedExplicitStep(const ReactionModel& model, const StepConstants& k) {
    // On an unweighted atlas the kernel steps the texture as a clamped grid,
    // right for every interior texel; the caller redoes the border texels
    // (CpuSimulator::redoAtlasBorder). A weighted one's runs on halo-padded
    // tiles (PaddedAtlasStep).
    if (!fusedParamsOk(k))
        return nullptr;
    if (k.weighted())
        return nullptr; // fusedWeightedStep
    const bool folded = foldsKernels(k.op);
    return withCell(model, [&](auto tag) -> StepRowsKernel {
        using Cell = typename decltype(tag)::Type;
        switch (k.op.form) {
        case DiffusionOperator::Form::Laplacian5:
            return explicitIf<Cell, LaplacianTerm<Stencil::FivePoint>>(k);
        case DiffusionOperator::Form::Laplacian9:
            return explicitIf<Cell, LaplacianTerm<Stencil::NinePoint>>(k);
        case DiffusionOperator::Form::Kernel3:
            return folded ? explicitIf<Cell, KernelTerm<1, true>>(k)
                          : explicitIf<Cell, KernelTerm<1, false>>(k);
        case DiffusionOperator::Form::Kernel5:
            return folded ? explicitIf<Cell, KernelTerm<2, true>>(k)
                          : explicitIf<Cell, KernelTerm<2, false>>(k);
        case DiffusionOperator::Form::TensorMap:
            break;
        }
        return nullptr;
    });
}

StepTileKernel fusedWeightedStep(const ReactionModel& model, const StepConstants& k) {
    // fromSession leaves only the 5-point form on a weighted atlas.
    // Anisotropy's three operators per chemical, and the drift, go the generic path.
    if (!k.weighted() || k.tensorWeighted() || k.drifting() || !fusedParamsOk(k) ||
        k.op.form != DiffusionOperator::Form::Laplacian5)
        return nullptr;
    return withCell<StepTileKernel>(model, [&](auto tag) -> StepTileKernel {
        using Cell = typename decltype(tag)::Type;
        for (int c = 0; c < Cell::kChemicals; ++c)
            if ((k.op.rates[std::size_t(c)] == 0.0f) == Cell::diffuses(c))
                return nullptr;
        return k.crossWeighted() ? &stepRowsWeighted<Cell, true> : &stepRowsWeighted<Cell, false>;
    });
}

StepTileKernel fusedRhsTilePass(const ReactionModel& model, const StepConstants& k) {
    if (!k.weighted() || k.hasParamMaps())
        return nullptr;
    return withCell<StepTileKernel>(model, [&](auto tag) -> StepTileKernel {
        using Cell = typename decltype(tag)::Type;
        return &rhsBlock<Cell>;
    });
}

StepRowsKernel fusedRhsPass(const ReactionModel& model, const StepConstants& k) {
    if (!fusedParamsOk(k) || k.domain.kind() == DomainKind::Atlas)
        return nullptr;
    return withCell(model, [&](auto tag) -> StepRowsKernel {
        using Cell = typename decltype(tag)::Type;
        return k.tiled() ? &rhsRows<Cell, true> : &rhsRows<Cell, false>;
    });
}

RelaxRowsKernel fusedRelaxation(const StepConstants& k) {
    // The sweep reads no reaction parameter, and fromSession refuses mapped
    // diffusion rates with the semi-implicit integrator: param maps are fine.
    if (k.domain.kind() == DomainKind::Atlas)
        return nullptr;
    switch (k.op.form) {
    case DiffusionOperator::Form::Laplacian5:
        return relaxFor<LaplacianTerm<Stencil::FivePoint>>(k);
    case DiffusionOperator::Form::Laplacian9:
        return relaxFor<LaplacianTerm<Stencil::NinePoint>>(k);
    case DiffusionOperator::Form::Kernel3:
        return foldsKernels(k.op) ? relaxFor<KernelTerm<1, true>>(k)
                                  : relaxFor<KernelTerm<1, false>>(k);
    case DiffusionOperator::Form::Kernel5:
        return foldsKernels(k.op) ? relaxFor<KernelTerm<2, true>>(k)
                                  : relaxFor<KernelTerm<2, false>>(k);
    case DiffusionOperator::Form::TensorMap:
        break;
    }
    return nullptr;
}

RelaxTileKernels weightedRelaxation(const StepConstants& k) {
    if (!k.weighted() || k.tensorWeighted() || k.drifting() ||
        k.op.form != DiffusionOperator::Form::Laplacian5)
        return {};
    for (int m : k.mappedRate)
        if (m >= 0)
            return {};
    assert(k.chemicals >= 1 && k.chemicals <= kMaxChemicals);
    using Counts = std::make_index_sequence<kMaxChemicals>;
    return k.crossWeighted() ? relaxForCounts<true>(Counts{}) : relaxForCounts<false>(Counts{});
}

} // namespace morphogen
