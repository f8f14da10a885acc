#pragma once

#include <array>
#include <memory>

#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_padded_atlas.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

// The CPU reference backend: the oracle for the GPU path in tests and the
// fallback for batch work where the only GL is a software rasterizer. Rows
// are split across OpenMP threads. Built-in models on the homogeneous
// operators step through the fused kernels of cpu_kernels.hpp; other models,
// the tensor map and runs with a zero diffusion rate take a generic path
// through ReactionModel::react() and row buffers.
class CpuSimulator : public Simulator {
public:
    explicit CpuSimulator(const Session& session);

    std::string backendName() const override { return "cpu"; }
    void setState(const State& state) override;
    State state() const override { return m_current; }
    // The state without a copy (the designer's display reads it every
    // frame: 2 MB copied and page-faulted at 512 x 512 x 2); valid until the
    // simulator next runs or changes.
    const State& currentState() const { return m_current; }
    State takeState() override;
    std::optional<std::string> insaneValue(const ReactionModel& model) const override;
    void run(int steps) override;
    void setFrozen(const std::vector<std::uint8_t>& frozen) override;
    void applyBrush(const Brush& brush) override; // cpu_brush.cpp
    void setActiveTiles(const std::vector<int>& tiles) override;

    // Semi-implicit runs: max over cells of |(I - dt A) c' - (c + dt f(c))|
    // for the last step, i.e. how far the relaxation passes left the solve.
    double lastSolveResidual() const;

private:
    void step();
    void stepGeneric();
    void stepSemiImplicit();
    void rhsGeneric(); // m_rhs = c + dt f(c) through ReactionModel::react()
    // react() on view.n cells from cell `first` (a row of the texture, or a
    // tile's row of an atlas) into view.dcdt: one call, or per cell with its
    // own parameters under param maps.
    void reactCells(RowView& view, std::size_t first, std::vector<float>& params) const;
    // Localized runs: one explicit step of the active tiles' texels only,
    // through the index array, the others left as they are in both buffers.
    void stepActiveTiles();
    std::vector<int> m_activeTiles; // empty: all
    // Whether m_next holds m_current's values outside the active tiles (then
    // a localized step need not copy them); false after anything writes
    // m_current alone or a whole step swaps the buffers.
    bool m_nextMatches = false;
    // Frozen cells of m_next take their values from m_current.
    void restoreFrozen();
    // The diffusion term of chemical c on row y, rate included.
    void diffusionRow(int c, const float* plane, int y, float* out) const;

    // Picks the fused kernels for the current constants (a rate of 0 may
    // need the generic path).
    void pickKernels();
    // A tiled grid (a batched sweep) advances each tile `steps` steps on its
    // own, tiles in parallel, while it fits in cache (cpu_tile_runs.cpp);
    // false where the one-pass row kernels must run instead.
    bool runTilesApart(int steps);
    // A plain grid on a fused kernel (no frozen cells): run() takes its steps
    // in one parallel region (runFusedGridSteps), the same arithmetic as step().
    bool fusedGridSteps() const;
    void runFusedGridSteps(int steps);
    const Session& liveSession() const override { return m_session; }
    const StepConstants& stepConstants() const override { return m_k; }
    void applyLiveChange(Session next) override;

    // runTilesApart: one simulator per tile (row-major from the bottom row),
    // made on first use and dropped whenever the constants change.
    std::vector<std::unique_ptr<CpuSimulator>> m_tileRuns;
    // As built, with live params and dt applied and painted parameters' maps added.
    Session m_session;
    const ReactionModel& m_model;
    // Null where the generic path runs.
    StepRowsKernel m_explicitStep = nullptr;
    StepTileKernel m_weightedStep = nullptr; // run through m_padded
    RelaxTileKernels m_weightedRelax;        // semi-implicit, through m_padded
    StepTileKernel m_rhsTile = nullptr;      // its right-hand side there
    StepRowsKernel m_rhsPass = nullptr;
    RelaxRowsKernel m_relax = nullptr;
    StepConstants m_k;
    // Kernel3/Kernel5: each chemical's taps as the generic path sums them.
    std::array<KernelTaps, kMaxChemicals> m_kernelTaps{};
    State m_current;
    State m_next;                             // made on the first step
    State m_rhs;                              // SemiImplicit: c + dt f(c) of the step being solved
    std::vector<std::uint32_t> m_frozenCells; // indices of frozen cells (cascades)
    std::vector<std::uint8_t> m_frozenMask;   // the same cells as a mask (brush hold/release)
    // Atlas domains: texels outside every tile (kept as they are, like frozen
    // cells), and per row y the border cells borderCells()[m_borderRows[y],
    // m_borderRows[y + 1]) that go through the index array.
    std::vector<std::uint32_t> m_unusedCells;
    std::vector<std::size_t> m_borderRows;
    // 9-point on an atlas: per cell its diagonals in both orders (atlas_diagonals.hpp).
    std::vector<std::array<std::uint32_t, 8>> m_diagonals;
    // Weighted atlases on a fused kernel: every step, global or of active
    // tiles, through halo-padded tiles.
    std::unique_ptr<PaddedAtlasStep> m_padded;
    // The 5- or 9-point Laplacian of one atlas row: interior texels by +-1 /
    // +-width in one vectorised loop, then the row's border texels by the
    // index array (and the diagonals).
    // With anisotropy (StepConstants::tensorWeighted) chemical's whole term, its
    // mix's rate included; otherwise at rate 1.
    void atlasLaplacianRow(const float* plane, int y, Stencil stencil, int chemical,
                           float* out) const;
    // The same at one atlas texel through the index array.
    float atlasLaplacian(const float* plane, std::uint32_t cell, Stencil stencil,
                         int chemical) const;
    // A weighted sum (four link planes, four diagonal planes or null) at one texel.
    float weightedAt(const float* links, const float* diagonals, const float* plane,
                     std::uint32_t cell) const;
    // Chemical's diffusion term at one texel, its rate included (0 if it does
    // not diffuse), and its drift if it drifts.
    float atlasTerm(const float* plane, std::uint32_t cell, Stencil stencil, int chemical) const;
    // The drift of water drops on a model (StepConstants::driftPlanes) at one
    // texel through the index array, and added to a row of chemical's terms
    // (interior texels by +-1 / +-width, border texels by the index array).
    float driftAt(const float* plane, std::uint32_t cell) const;
    void addDriftRow(const float* plane, int y, int chemical, float* out) const;
    // After a fused step over an unweighted atlas texture (a clamped grid to
    // the kernel): the explicit step of every tile-border texel again,
    // through the map.
    void redoAtlasBorder();
};

} // namespace morphogen
