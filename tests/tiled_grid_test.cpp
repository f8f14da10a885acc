// The tiled grid domain on the CPU: a batched sweep runs every tile in one
// pass, and each tile must be exactly the simulation of its own session.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/sweep.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

SweepSpec smallSweep(const std::string& preset, SweepAxis x, SweepAxis y, int steps) {
    SweepSpec spec;
    spec.base = loadPreset(preset);
    spec.base.steps = steps;
    spec.x = std::move(x);
    spec.y = std::move(y);
    spec.columns = 3;
    spec.rows = 2;
    spec.tile = 16;
    spec.base.width = spec.base.height = spec.tile;
    return spec;
}

// The one-pass row kernels over all tiles, one step per call (runs of
// several steps advance each tile on its own instead: cpu_tile_runs.cpp).
State runOnePass(const Session& batched) {
    CpuSimulator simulator(batched);
    simulator.setState(initialState(batched));
    for (int i = 0; i < batched.steps; ++i)
        simulator.run(1);
    return simulator.state();
}

// Bit for bit, both ways of running a tiled grid: the one-pass kernels do each
// tile's arithmetic in the same order as a standalone run (same stencil sums,
// same reaction, the same parameter values), only the neighbour indices
// differ; the tile-blocked run is a standalone run per tile.
void expectTilesMatchOneByOne(const Session& batched) {
    const State blocked = runBatched(batched, cpu());
    const State onePass = runOnePass(batched);
    const int tile = batched.width / batched.tiles.columns;
    for (int row = 0; row < batched.tiles.rows; ++row)
        for (int column = 0; column < batched.tiles.columns; ++column) {
            const State alone = runTile(tileSession(batched, column, row), cpu());
            EXPECT_EQ(test::maxAbsDifference(extractTile(blocked, column, row, tile), alone), 0.0f)
                << "tile-blocked, tile (" << column << ", " << row << ")";
            EXPECT_EQ(test::maxAbsDifference(extractTile(onePass, column, row, tile), alone), 0.0f)
                << "one pass, tile (" << column << ", " << row << ")";
        }
}

} // namespace

TEST(TiledGrid, FusedFivePointBatchedEqualsTileByTile) {
    expectTilesMatchOneByOne(
        batchedSession(smallSweep("gs_coral", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 60)));
}

TEST(TiledGrid, FusedNinePointBatchedEqualsTileByTile) {
    SweepSpec spec = smallSweep("gs_coral", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 60);
    spec.base.diffusion.stencil = Stencil::NinePoint;
    expectTilesMatchOneByOne(batchedSession(spec));
}

TEST(TiledGrid, FusedFiveByFiveKernelBatchedEqualsTileByTile) {
    expectTilesMatchOneByOne(batchedSession(
        smallSweep("gs_generalized_c", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 40)));
}

TEST(TiledGrid, SweptDiffusionRateBatchedEqualsTileByTile) {
    // A swept rate takes the generic path (per-cell rate) in the batched run.
    expectTilesMatchOneByOne(
        batchedSession(smallSweep("gs_coral", {"Du", 0.15f, 0.25f}, {"F", 0.02f, 0.05f}, 60)));
}

TEST(TiledGrid, GenericPathBatchedEqualsTileByTile) {
    // Six chemicals: the generic row-pass path.
    const Session base = loadPreset("meinhardt_random_stripes");
    const ReactionModel& model = base.reactionModel();
    const std::string a = model.params()[0].name, b = model.params()[1].name;
    const float a0 = base.params.at(a), b0 = base.params.at(b);
    expectTilesMatchOneByOne(batchedSession(smallSweep(
        "meinhardt_random_stripes", {a, a0 * 0.9f, a0 * 1.1f}, {b, b0 * 0.9f, b0 * 1.1f}, 30)));
}

TEST(TiledGrid, SemiImplicitBatchedEqualsTileByTile) {
    SweepSpec spec = smallSweep("gs_coral", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 20);
    spec.base.integrator = Integrator::SemiImplicit;
    spec.base.dt = 2.0f;
    expectTilesMatchOneByOne(batchedSession(spec));
}

TEST(TiledGrid, TilesRoundTripThroughJson) {
    const Session batched =
        batchedSession(smallSweep("gs_coral", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 20));
    const Session again = sessionFromJson(sessionToJson(batched), "round trip");
    ASSERT_EQ(again.tiles.params, batched.tiles.params);
    EXPECT_EQ(again.domain().kind(), DomainKind::TiledGrid);
    EXPECT_EQ(runBatched(again, cpu()), runBatched(batched, cpu()));
}

TEST(TiledGrid, BadTilesAreRefusedByName) {
    nlohmann::json j = sessionToJson(
        batchedSession(smallSweep("gs_coral", {"k", 0.05f, 0.065f}, {"F", 0.02f, 0.05f}, 20)));
    auto message = [](const nlohmann::json& bad) {
        try {
            sessionFromJson(bad, "t.json");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    nlohmann::json uneven = j;
    uneven["tiles"] = {{"grid", {5, 2}}};
    EXPECT_NE(message(uneven).find("must split the 48 x 32 grid evenly"), std::string::npos)
        << message(uneven);
    nlohmann::json shortValues = j;
    shortValues["tiles"]["params"]["k"] = {0.05};
    EXPECT_NE(message(shortValues).find("tiles.params.k"), std::string::npos)
        << message(shortValues);
    nlohmann::json clamped = j;
    clamped["edges"] = "clamped";
    EXPECT_NE(message(clamped).find("periodic"), std::string::npos) << message(clamped);
}

TEST(TiledGrid, TensorMapIsRefusedOnATiledGrid) {
    Session s = batchedSession(
        smallSweep("wk_spiral_stripes", {"k", 0.05f, 0.065f}, {"b", 0.01f, 0.02f}, 1));
    try {
        CpuSimulator simulator(s);
        FAIL() << "a tensor map ran on a tiled grid";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("tiled grid"), std::string::npos) << e.what();
    }
}
