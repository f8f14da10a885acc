// A batched sweep on the GPU: the tiles of one texture must behave as
// separate simulations, each periodic on its own.

#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/sim/cpu_simulator.hpp"
#include "core/sim/sweep.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory gpu() {
    test::glContext();
    return [](const Session& s) { return std::make_unique<gl::GpuSimulator>(s); };
}

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

SweepSpec smallSweep(Stencil stencil) {
    SweepSpec spec;
    spec.base = loadPreset("gs_coral");
    spec.base.diffusion.stencil = stencil;
    spec.base.steps = 200;
    spec.x = {"k", 0.05f, 0.065f};
    spec.y = {"F", 0.02f, 0.05f};
    spec.columns = 3;
    spec.rows = 2;
    spec.tile = 24;
    spec.base.width = spec.base.height = spec.tile;
    return spec;
}

bool sameTile(const State& a, const State& b, int column, int row, int tile) {
    return extractTile(a, column, row, tile) == extractTile(b, column, row, tile);
}

void checkTilesIndependent(Stencil stencil) {
    const SweepSpec spec = smallSweep(stencil);
    const Session batched = batchedSession(spec);
    const State first = runBatched(batched, gpu());

    // Change one tile's parameter pair: only that tile may change.
    const int changedColumn = 1, changedRow = 1;
    Session edited = batched;
    const std::size_t index = std::size_t(changedRow * spec.columns + changedColumn);
    edited.tiles.params["k"][index] = 0.06f;
    edited.tiles.params["F"][index] = 0.03f;
    const State second = runBatched(edited, gpu());
    for (int row = 0; row < spec.rows; ++row)
        for (int column = 0; column < spec.columns; ++column) {
            const bool same = sameTile(first, second, column, row, spec.tile);
            if (column == changedColumn && row == changedRow)
                EXPECT_FALSE(same) << "the edited tile did not change";
            else
                EXPECT_TRUE(same) << "tile (" << column << ", " << row << ") changed";
        }

    // Each tile is the simulation of its own session, as the CPU runs it.
    for (int row = 0; row < spec.rows; ++row)
        for (int column = 0; column < spec.columns; ++column) {
            const State expected = runTile(tileSession(edited, column, row), cpu());
            const State got = extractTile(second, column, row, spec.tile);
            float worst = 0;
            for (int c = 0; c < got.channels(); ++c)
                for (std::size_t i = 0; i < got.cellCount(); ++i)
                    worst = std::max(worst, std::fabs(got.plane(c)[i] - expected.plane(c)[i]));
            EXPECT_LT(worst, 1e-4f) << "tile (" << column << ", " << row << ")";
        }
}

} // namespace

TEST(GpuSweep, TilesAreIndependentAndMatchTheCpuFivePoint) {
    checkTilesIndependent(Stencil::FivePoint);
}

TEST(GpuSweep, TilesAreIndependentAndMatchTheCpuNinePoint) {
    checkTilesIndependent(Stencil::NinePoint);
}

TEST(GpuSweep, TilesSurviveASessionRoundTrip) {
    const Session batched = batchedSession(smallSweep(Stencil::FivePoint));
    const Session again = sessionFromJson(sessionToJson(batched), "round trip");
    ASSERT_EQ(again.tiles.params, batched.tiles.params);
    EXPECT_EQ(runBatched(again, gpu()), runBatched(batched, gpu()));
}
