#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/sim/cpu_kernels.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

class Atlas;

// Explicit steps of a weighted atlas on the CPU with every texel in the fused
// row kernel. For a run the tiles are copied into a texture of tiles padded
// by a one-texel halo; before each step every halo is filled from the texels
// across its tile's edges (and, with the weights' cross term, its four
// corners from the corner texels' diagonals), so the kernel's +-1 / +-width
// reads are the atlas's neighbours for every texel: no texel goes through
// the index array, and a texel on a tile border costs what an interior one
// does. The result is copied back once, at the end of the run.
//
// Why: with the border texels redone one by one through the index array
// (gathers), a weighted atlas ran at 0.08 (4x4 tiles, three quarters of the
// texels on a border) to 0.10 (16x16) of a grid's texels per second. The halo
// costs 4 (n + 1) copied texels per tile and step, and the kernel's wasted
// halo columns.
//
// The sums are the border path's in the same order (StepConstants::
// weightPlanes); a diagonal whose weight is 0 (an irregular corner) may read
// another texel than the index path's there, which the 0 cancels.
class PaddedAtlasStep {
public:
    // `k` is a weighted atlas's constants; `diagonals` the atlas's
    // (atlasDiagonals) when the weights have a cross term, else empty.
    PaddedAtlasStep(const Atlas& atlas, const std::vector<std::array<std::uint32_t, 8>>& diagonals,
                    const StepConstants& k);

    // Runs `steps` explicit steps of `state` (atlas layout) with `kernel`
    // (fusedWeightedStep's for `k`, whose dt, rates, parameters and clamps
    // are read now). Only the `active` tiles step (empty: all; Lo's
    // localized reaction-diffusion), the others serving as neighbours. Texels
    // outside every tile keep their values, as do the `frozen` cells (atlas
    // cells, in any order).
    void run(StepTileKernel kernel, const StepConstants& k, State& state, int steps,
             const std::vector<int>& active, const std::vector<std::uint32_t>& frozen,
             bool threaded);

    // Runs `passes` Jacobi passes of a semi-implicit step (weightedRelaxation's
    // `kernels` for `k`) on (I - dt A) x = rhs, from x = `state`, which gets
    // the result; `rhs` is in the atlas layout. Each chemical stops after its
    // own passes (chemicalRelaxationPasses), carried unchanged through the
    // rest. The `frozen` cells keep their values.
    void relax(const RelaxTileKernels& kernels, const StepConstants& k, State& state,
               const State& rhs, int passes, const std::vector<std::uint32_t>& frozen,
               bool threaded);
    // `steps` whole semi-implicit steps in the padded layout: the right-hand
    // side by `rhsKernel` (fusedRhsTilePass's), then relax's passes. The
    // state is copied in and out once, not once per step. With `active`
    // tiles (as run) only they step, a local solve whose neighbours hold.
    void runSemiImplicit(StepTileKernel rhsKernel, const RelaxTileKernels& kernels,
                         const StepConstants& k, State& state, int steps, int passes,
                         const std::vector<int>& active, const std::vector<std::uint32_t>& frozen,
                         bool threaded);

private:
    std::uint32_t paddedCell(int tile, int u, int v) const;
    std::vector<std::uint32_t> paddedFrozen(const std::vector<std::uint32_t>& frozen) const;
    void keepFrozen(const std::vector<std::uint32_t>& frozen);
    // The passes of a semi-implicit step for the constants prepare() set:
    // each chemical's count (chemicalRelaxationPasses of `passes`) and, per
    // pass, the chemicals relaxing and the halos they read. Made once per
    // run, not per step.
    void planPasses(int passes);
    void relaxPasses(const RelaxTileKernels& kernels, bool all,
                     const std::vector<std::uint32_t>& frozen, bool threaded);
    // Calls block(firstTile, endTile, y0, y1, x0, x1) for every row of tiles
    // (all) or every run of active tiles (m_runs), in parallel.
    template <class Block> void forEachBlock(bool all, bool threaded, const Block& block) const;
    void setRuns(const std::vector<int>& active);
    std::array<float*, kMaxChemicals> inPlanes();
    std::uint32_t paddedOf(std::uint32_t cell) const; // a used atlas cell's
    std::vector<float> padPlanes(const std::vector<float>& planes) const;
    void prepare(const StepConstants& k);
    // Copies tiles' texels from the atlas into `to`, or from m_in to the atlas.
    void load(const State& state, State& to) const;
    void store(int tile, State& state) const;
    // Fills the halos of tiles [first, end) for the `chemicals` (all that
    // diffuse when null).
    void fillHalos(int first, int end, const std::array<float*, kMaxChemicals>& planes,
                   const std::vector<int>* chemicals = nullptr) const;
    // One step of every tile (all) or of m_runs.
    void step(StepTileKernel kernel, bool all, const std::vector<std::uint32_t>& frozen,
              bool threaded);

    const Atlas& m_atlas;
    int m_n = 0; // tile size
    int m_tileRows = 0;
    int m_padded = 0; // n + 2
    int m_width = 0;  // of the padded texture
    // Per tile, its halo's 4 (n + 1) cells and their sources, both in the
    // padded texture, tile t's from 4 (n + 1) t on.
    std::vector<std::uint32_t> m_haloTo, m_haloFrom;
    // The constants with the weight planes laid out padded (zeros in the
    // halo), padded again when the atlas constants' planes change.
    StepConstants m_k;
    std::shared_ptr<const std::vector<float>> m_sourceWeights, m_sourceDiagonals;
    // The active tiles of a run as runs of consecutive tiles on one row of tiles.
    struct TileRun {
        int first = 0, end = 0;
    };
    std::vector<TileRun> m_runs;
    struct PassPlan {
        std::array<int, kMaxChemicals> own{};           // passes per chemical
        std::vector<std::vector<std::uint8_t>> relaxed; // per pass
        std::vector<std::vector<int>> halos;            // per pass
    };
    PassPlan m_plan;
    State m_rhs;                  // relax's right-hand side, padded (made on its first call)
    std::vector<int> m_diffusing; // chemicals with a rate other than 0
    State m_in, m_out;
};

} // namespace morphogen
