// Localized reaction-diffusion on the CPU (core/sim/localized_rd.hpp, Lo et
// al. section 4): tile neighbourhoods from the gluing, the active set's
// growth schedule, and steps that leave inactive tiles bit for bit as they
// were while active tiles read them as neighbours.

#include <algorithm>

#include <gtest/gtest.h>

#include "atlas_checks.hpp"
#include "core/base/errors.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/models/initial_condition.hpp"
#include "core/sim/brush.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/localized_rd.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

std::vector<int> allTiles(int count) {
    std::vector<int> t(std::size_t(count), 0);
    for (int i = 0; i < count; ++i)
        t[std::size_t(i)] = i;
    return t;
}

} // namespace

TEST(TileNeighbourhoods, CubeFacesShareCornersWithAllButTheOppositeFace) {
    const Atlas cube = Atlas::cube(4);
    const TileNeighbourhoods n(cube);
    EXPECT_EQ(n.vertexCount(), 8);
    // Every corner's class has as many corners as cornerValence says (3).
    for (int t = 0; t < 6; ++t)
        for (int c = 0; c < 4; ++c) {
            int corners = 0;
            for (int s = 0; s < 6; ++s)
                for (int d = 0; d < 4; ++d)
                    corners += n.vertex(s, d) == n.vertex(t, c) ? 1 : 0;
            EXPECT_EQ(corners, cube.cornerValence(t, c)) << "tile " << t << " corner " << c;
        }
    // Face 0 (+x) meets +y, -y, +z, -z at its corners; -x (tile 1) is opposite.
    EXPECT_EQ(n.grow({0}), (std::vector<int>{0, 2, 3, 4, 5}));
    EXPECT_EQ(n.grow({1}), (std::vector<int>{1, 2, 3, 4, 5}));
    EXPECT_EQ(n.grow(n.grow({0})), allTiles(6));
}

TEST(TileNeighbourhoods, PlaneGrowsBySquaresAndAValence5FanIsOneNeighbourhood) {
    const TileNeighbourhoods plane(Atlas::periodicPlane(4, 10, 10));
    EXPECT_EQ(plane.vertexCount(), 100);
    std::vector<int> a = plane.grow({55});
    EXPECT_EQ(a.size(), 9u); // 3 x 3 around tile (5, 5)
    EXPECT_EQ(a, (std::vector<int>{44, 45, 46, 54, 55, 56, 64, 65, 66}));
    EXPECT_EQ(plane.grow(a).size(), 25u);
    EXPECT_EQ(plane.grow(plane.grow(a)).size(), 49u);
    // Across the periodic wrap: tile 0's neighbours include 9, 90 and 99.
    const std::vector<int> corner = plane.grow({0});
    for (int t : {0, 1, 9, 10, 11, 19, 90, 91, 99})
        EXPECT_TRUE(std::binary_search(corner.begin(), corner.end(), t)) << t;
    // Rotated and mirrored gluings: a 3 x 3 torus, every tile next to every other.
    EXPECT_EQ(TileNeighbourhoods(Atlas::rotatedTiles(4)).grow({4}), allTiles(9));
    // Five tiles round one vertex (open outer edges).
    std::vector<std::array<int, 4>> quads;
    for (int i = 0; i < 5; ++i)
        quads.push_back({0, 1 + i, 6 + i, 1 + (i + 1) % 5});
    const TileNeighbourhoods fan(Atlas::fromQuads(4, quads));
    EXPECT_EQ(fan.of(2), allTiles(5));
    EXPECT_EQ(fan.vertex(0, 0), fan.vertex(3, 0));
}

TEST(ActiveTileSchedule, GrowsEveryMIterationsAndGoesGlobalPastTheThreshold) {
    const Atlas atlas = Atlas::periodicPlane(4, 10, 10);
    const TileNeighbourhoods n(atlas);
    ActiveTileSchedule schedule(n, {55}, 50, 0.4);
    EXPECT_FALSE(schedule.global());
    EXPECT_EQ(schedule.phase(), 1);
    EXPECT_EQ(schedule.tiles().size(), 9u); // A1 = N(A0)
    EXPECT_EQ(schedule.iterationsLeft(), 50);
    EXPECT_FALSE(schedule.advance(30));
    EXPECT_EQ(schedule.iterationsLeft(), 20);
    EXPECT_TRUE(schedule.advance(20));
    EXPECT_EQ(schedule.phase(), 2);
    EXPECT_EQ(schedule.tiles().size(), 25u);
    EXPECT_TRUE(schedule.advance(50));
    EXPECT_EQ(schedule.tiles().size(), 0u); // A3 has 49 > 40 tiles: global
    EXPECT_TRUE(schedule.global());
    EXPECT_FALSE(schedule.advance(100));
    // Nothing touched: nothing to localize.
    EXPECT_TRUE(ActiveTileSchedule(n, {}, 50).global());
}

TEST(ActiveTileSchedule, IterationsToCrossATileFollowTheSpreadingRadius) {
    // sqrt(4 D t) = n: t = n^2 / (4 D); 16^2 / (4 * 0.25 * 1) = 256 steps of dt 1.
    EXPECT_EQ(iterationsToCrossTile(16, 0.25, 1.0), 256);
    EXPECT_EQ(iterationsToCrossTile(16, 0.25, 0.5), 512);
    EXPECT_EQ(iterationsToCrossTile(8, 0.2097, 0.9), 85); // gs_coral on 8-texel tiles
    // From a run's constants: the largest rate, times the largest coefficient.
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    Session s = test::atlasSession(atlas);
    EXPECT_EQ(iterationsToCrossTile(StepConstants::fromSession(s)),
              iterationsToCrossTile(8, s.params.at("Du"), s.dt));
    useAtlas(s, atlas, std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas, 2.0f)));
    EXPECT_EQ(iterationsToCrossTile(StepConstants::fromSession(s)),
              iterationsToCrossTile(8, 2.0 * s.params.at("Du"), s.dt));
}

TEST(ActiveTileSchedule, BrushTouchesTheTilesItsCellsLieIn) {
    const Atlas atlas = Atlas::periodicPlane(8, 4, 4);
    const Domain domain = Domain::atlas(std::make_shared<const Atlas>(atlas));
    // A disc round the shared corner of tiles 5, 6, 9, 10 (texel (16, 16)).
    const BrushRegion region = BrushRegion::disc(domain, 15.5f, 15.5f, 3.0f);
    EXPECT_EQ(touchedTiles(atlas, region), (std::vector<int>{5, 6, 9, 10}));
}

TEST(LocalizedCpu, InactiveTilesStayBitIdenticalAndActiveOnesEvolve) {
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(8, 4, 4));
    for (auto weights : {std::shared_ptr<const AtlasWeights>(),
                         std::make_shared<const AtlasWeights>(test::symmetricWeights(*atlas, 4))}) {
        SCOPED_TRACE(weights ? "weighted" : "unweighted");
        Session s = test::atlasSession(atlas);
        useAtlas(s, atlas, weights);
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 7);
        CpuSimulator sim(s);
        sim.setState(start);
        sim.run(5); // a global step first: the buffers differ outside any set
        const State before = sim.state();
        const std::vector<int> active = {5, 6};
        sim.setActiveTiles(active);
        sim.run(31); // odd: the buffers swap an odd number of times
        const State after = sim.state();
        for (int t = 0; t < atlas->tileCount(); ++t) {
            const bool isActive = std::count(active.begin(), active.end(), t) > 0;
            EXPECT_EQ(test::tileEqual(before, after, *atlas, t), !isActive) << "tile " << t;
        }
        // A tile leaving the set keeps the value it reached, whatever the
        // buffers held before (3 steps: the swap parity changes).
        sim.setActiveTiles({5});
        sim.run(3);
        const State shrunk = sim.state();
        EXPECT_TRUE(test::tileEqual(after, shrunk, *atlas, 6));
        EXPECT_FALSE(test::tileEqual(after, shrunk, *atlas, 5));
        // Back to global: everything steps again.
        sim.setActiveTiles({});
        sim.run(2);
        const State global = sim.state();
        for (int t = 0; t < atlas->tileCount(); ++t)
            EXPECT_FALSE(test::tileEqual(shrunk, global, *atlas, t)) << "tile " << t;
    }
}

TEST(LocalizedCpu, EveryTileActiveIsTheGlobalStep) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    for (auto weights : {std::shared_ptr<const AtlasWeights>(),
                         std::make_shared<const AtlasWeights>(test::symmetricWeights(*atlas, 2))}) {
        SCOPED_TRACE(weights ? "weighted" : "unweighted");
        Session s = test::atlasSession(atlas);
        useAtlas(s, atlas, weights);
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 3);
        CpuSimulator global(s), local(s);
        global.setState(start);
        local.setState(start);
        local.setActiveTiles(allTiles(6));
        global.run(40);
        local.run(40);
        // The same sums per texel (the fused rows and the index array add in
        // one order); the reaction through react() or a fused Cell may round
        // differently, hence a bound rather than bits.
        EXPECT_LT(test::maxAbsDifference(global.state(), local.state()),
                  1e-6f * test::maxAbsValue(global.state()));
        EXPECT_GT(test::maxAbsDifference(global.state(), start), 1e-3f);
    }
}

TEST(LocalizedCpu, ActiveTilesOutOfRangeOrOffAnAtlasAreRefused) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(4));
    CpuSimulator sim(test::atlasSession(atlas));
    try {
        sim.setActiveTiles({2, 6});
        FAIL() << "tile 6 of 6 accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "active tile 6 is out of range (accepted: 0..5)");
    }
    Session grid = loadPreset("gs_coral");
    grid.width = grid.height = 16;
    CpuSimulator onGrid(grid);
    EXPECT_THROW(onGrid.setActiveTiles({0}), InputError);
    onGrid.setActiveTiles({}); // all: fine anywhere
}
