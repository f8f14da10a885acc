// Simulations on atlas domains on the CPU: mass conservation, smooth
// spreading across an irregular (valence-3) corner, agreement with the
// periodic grid the periodic atlases stand for, untouched unused texels and
// the refusal of operators an atlas cannot run.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "atlas_checks.hpp"
#include "core/analysis/pattern_classifier.hpp"
#include "core/base/errors.hpp"
#include "core/models/initial_condition.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

State runOn(const Session& s, const State& start, int steps) {
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(steps);
    return sim.state();
}

void expectMassConserved(std::shared_ptr<const Atlas> atlas, Stencil stencil) {
    SCOPED_TRACE(stencil == Stencil::FivePoint ? "5-point" : "9-point");
    const Session s = test::pureDiffusionSession(atlas, stencil);
    const State start = test::randomUsedState(*atlas, 3);
    const State end = runOn(s, start, 200);
    const double before = test::usedSum(start, *atlas, 0), after = test::usedSum(end, *atlas, 0);
    // Float rounding of 200 steps of ~1e3 cells: far below 1e-5 relative; a
    // lost or doubled neighbour link would move mass by ~1e-2 relative or more.
    EXPECT_NEAR(after, before, 1e-5 * before);
    EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
}

} // namespace

TEST(AtlasCpu, DiffusionConservesMassOnTheCube) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint})
        expectMassConserved(std::make_shared<const Atlas>(Atlas::cube(8)), stencil);
}

TEST(AtlasCpu, DiffusionConservesMassOnRotatedTiles) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint})
        expectMassConserved(std::make_shared<const Atlas>(Atlas::rotatedTiles(8)), stencil);
}

namespace {

void expectSmoothSpreadAtACubeCorner(Stencil stencil) {
    SCOPED_TRACE(stencil == Stencil::FivePoint ? "5-point" : "9-point");
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    ASSERT_EQ(atlas->cornerValence(0, 0), 3);
    const std::vector<std::uint32_t> corner = test::cornerTexels(*atlas, 0);
    State start(atlas->width(), atlas->height(), 2);
    for (std::uint32_t c : corner)
        start.plane(0)[c] = 1.0f;
    const State end = runOn(test::pureDiffusionSession(atlas, stencil), start, 40);
    const float* u = end.plane(0);
    // The cube is symmetric under the 3-fold turn about this corner's
    // diagonal: each of the three tiles holds the same mass and the same
    // profile (only summation order differs, hence 1e-6).
    std::vector<double> tileMass;
    for (std::uint32_t c : corner) {
        const int tile = atlas->tileOf(c);
        double m = 0;
        for (int v = 0; v < atlas->tileSize(); ++v)
            for (int w = 0; w < atlas->tileSize(); ++w)
                m += u[atlas->tileCell(tile, w, v)];
        tileMass.push_back(m);
    }
    for (double m : tileMass)
        EXPECT_NEAR(m, tileMass[0], 1e-6 * tileMass[0]);
    for (std::uint32_t c : corner)
        EXPECT_NEAR(u[c], u[corner[0]], 1e-6f);
    // Smooth: no hole and no spike at the corner. Each corner texel holds the
    // maximum and values fall monotonically along its tile's edges and diagonal.
    for (std::uint32_t c : corner) {
        for (Direction d :
             {Direction::PlusX, Direction::PlusY, Direction::MinusX, Direction::MinusY})
            EXPECT_GE(u[c], u[atlas->step(c, d).cell]);
        std::uint32_t previous = c;
        for (int i = 0; i < 4; ++i) {
            const std::uint32_t next = atlas->walk(previous, {Direction::PlusX, Direction::PlusY});
            if (atlas->tileOf(next) != atlas->tileOf(c))
                break;
            EXPECT_GT(u[previous], u[next]);
            previous = next;
        }
    }
    EXPECT_NEAR(test::usedSum(end, *atlas, 0), 3.0, 3e-5);
}

} // namespace

// Valence 3 is an irregular corner: the 9-point diagonals there are the
// mean of the two orders (atlas_diagonals.hpp).
TEST(AtlasCpu, BlobAtAValence3CornerSpreadsSymmetricallyAndSmoothly) {
    expectSmoothSpreadAtACubeCorner(Stencil::FivePoint);
    expectSmoothSpreadAtACubeCorner(Stencil::NinePoint);
}

TEST(AtlasCpu, PeriodicPlaneAtlasEqualsThePeriodicGrid) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint}) {
        auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(8, 3, 2));
        const Session onAtlas = test::atlasSession(atlas, stencil);
        Session grid = onAtlas;
        grid.atlas.reset();
        ASSERT_EQ(grid.domain().kind(), DomainKind::Grid);
        const State start = makeInitialState(grid.init, grid.reactionModel(), grid.params,
                                             grid.width, grid.height, 5);
        const State a = runOn(onAtlas, start, 100), g = runOn(grid, start, 100);
        // The same sums in the same order (-x, +x, -y, +y; diagonals as the
        // grid's, 0.5 (v + v) being v exactly), so bit for bit.
        EXPECT_EQ(test::maxAbsDifference(a, g), 0.0f);
        EXPECT_GT(test::maxAbsDifference(a, start), 1e-3f);
    }
}

TEST(AtlasCpu, RotatedTilesEqualThePeriodicGridTheyStandFor) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint}) {
        const int n = 8;
        auto atlas = std::make_shared<const Atlas>(Atlas::rotatedTiles(n));
        const std::vector<std::uint32_t> planeCell = Atlas::rotatedTilesPlaneCells(n);
        Session grid = test::atlasSession(atlas, stencil);
        grid.atlas.reset();
        grid.width = grid.height = 3 * n;
        const State gridStart = makeInitialState(grid.init, grid.reactionModel(), grid.params,
                                                 grid.width, grid.height, 9);
        State atlasStart(atlas->width(), atlas->height(), 2);
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
            for (int c = 0; c < 2; ++c)
                atlasStart.plane(c)[i] = gridStart.plane(c)[planeCell[i]];
        const State a = runOn(test::atlasSession(atlas, stencil), atlasStart, 100);
        const State g = runOn(grid, gridStart, 100);
        // Turned tiles sum their four neighbours in another order: rounding only.
        float worst = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
            for (int c = 0; c < 2; ++c)
                worst = std::max(worst, std::fabs(a.plane(c)[i] - g.plane(c)[planeCell[i]]));
        EXPECT_LT(worst, 1e-5f * test::maxAbsValue(g));
        EXPECT_GT(test::maxAbsDifference(g, gridStart), 1e-3f);
    }
}

TEST(AtlasCpu, UnusedTexelsStayUntouched) {
    // Three tiles in a 2 x 2 layout: the fourth tile's texels are unused.
    auto open = std::make_shared<Atlas>(8, 3, 2);
    open->glue(0, TileEdge::PlusX, 1, TileEdge::MinusX);
    open->glue(0, TileEdge::PlusY, 2, TileEdge::MinusY);
    const std::shared_ptr<const Atlas> atlas = open;
    const State start = test::randomUsedState(*atlas, 4);
    const State end = runOn(test::pureDiffusionSession(atlas), start, 50);
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (!atlas->used(i)) {
            ASSERT_EQ(end.plane(0)[i], 7.0f);
            ASSERT_EQ(end.plane(1)[i], 7.0f);
        }
    // Unglued edges are zero-flux: the mass stays.
    EXPECT_NEAR(test::usedSum(end, *atlas, 0), test::usedSum(start, *atlas, 0),
                1e-5 * test::usedSum(start, *atlas, 0));
}

namespace {

std::string refusal(const Session& s) {
    try {
        CpuSimulator sim(s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST(AtlasCpu, OperatorsAnAtlasCannotRunAreRefusedByName) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    EXPECT_EQ(refusal(test::atlasSession(atlas, Stencil::NinePoint)), "no error");
    for (const char* preset : {"wk_zebra", "gs_generalized_c", "wk_spiral_stripes"}) {
        Session s = loadPreset(preset);
        useAtlas(s, atlas);
        const std::string message = refusal(s);
        // An anisotropic tensor needs the direction field a mesh gives it (AtlasWeights::tensor).
        EXPECT_NE(message.find("diffusion operator cannot run on an atlas domain (accepted "
                               "there: isotropic diffusion, 5-point or 9-point stencil; "
                               "anisotropic tensors on a mesh"),
                  std::string::npos)
            << preset << ": " << message;
    }
    Session implicit = test::atlasSession(atlas);
    implicit.integrator = Integrator::SemiImplicit;
    EXPECT_NE(refusal(implicit).find("semi_implicit integrator runs on a weighted atlas"),
              std::string::npos)
        << refusal(implicit);
}

TEST(AtlasCpu, StabilityOnAnAtlasIsTheGershgorinBoundAndSaysSo) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    const Session s = test::atlasSession(atlas);
    const ExplicitStability st = explicitStability(compileDiffusion(s), s.domain(), s.dt);
    EXPECT_FALSE(st.exact);
    EXPECT_NE(st.basis.find("Gershgorin bound on the atlas domain"), std::string::npos);
    const float maxRate = std::max(s.params.at("Du"), s.params.at("Dv"));
    ASSERT_TRUE(st.maxStableDt);
    EXPECT_NEAR(*st.maxStableDt, 2.0 / (8.0 * maxRate), 1e-6);
    // On the periodic grid of the same cells the exact analysis is used.
    Session grid = s;
    grid.atlas.reset();
    EXPECT_TRUE(explicitStability(compileDiffusion(grid), grid.domain(), grid.dt).exact);
}

TEST(AtlasCpu, GridOnlyFeaturesAreRefusedByName) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    Session s = test::atlasSession(atlas);
    const State state = test::randomUsedState(*atlas, 2);
    try {
        measurePattern(state, 0, s.domain());
        FAIL() << "FFT statistics ran on an atlas";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("pattern statistics (FFT wavelength and "
                                             "orientation) needs a grid's x and y axes and cannot "
                                             "run on an atlas domain"),
                  std::string::npos)
            << e.what();
    }
    Session mapped = s;
    mapped.paramMaps["F"] = ParamMapSpec{};
    try {
        CpuSimulator sim(mapped);
        FAIL() << "a param map in x ran on an atlas";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("param_maps (fields in grid x and y) cannot vary a "
                                             "parameter over an atlas domain"),
                  std::string::npos)
            << e.what();
    }
}

namespace {

// Five tiles around one vertex (valence 5), every quad's corner 0 at it:
// vertices 0 (centre), 1..5 (spokes), 6..10 (outer). Outer edges are open.
std::shared_ptr<const Atlas> fiveTileFan(int n) {
    std::vector<std::array<int, 4>> quads;
    for (int i = 0; i < 5; ++i)
        quads.push_back({0, 1 + i, 6 + i, 1 + (i + 1) % 5});
    return std::make_shared<const Atlas>(Atlas::fromQuads(n, quads));
}

} // namespace

TEST(AtlasCpu, BlobAtAValence5CornerSpreadsSymmetricallyAndSmoothly) {
    auto atlas = fiveTileFan(8);
    ASSERT_EQ(atlas->cornerValence(0, 0), 5);
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint}) {
        SCOPED_TRACE(stencil == Stencil::FivePoint ? "5-point" : "9-point");
        State start(atlas->width(), atlas->height(), 2);
        for (int t = 0; t < 5; ++t)
            start.plane(0)[atlas->cornerCell(t, 0)] = 1.0f;
        const State end = runOn(test::pureDiffusionSession(atlas, stencil), start, 40);
        const float* u = end.plane(0);
        EXPECT_NEAR(test::usedSum(end, *atlas, 0), 5.0, 5e-5);
        // Five-fold symmetric: the same value at the same texel of every tile.
        for (int t = 1; t < 5; ++t)
            for (int v = 0; v < atlas->tileSize(); ++v)
                for (int w = 0; w < atlas->tileSize(); ++w)
                    ASSERT_NEAR(u[atlas->tileCell(t, w, v)], u[atlas->tileCell(0, w, v)], 1e-6f)
                        << "tile " << t << " texel (" << w << ", " << v << ")";
        // No spike or hole: the corner holds the maximum, values fall along the diagonal.
        for (int i = 0; i + 1 < atlas->tileSize(); ++i)
            EXPECT_GT(u[atlas->tileCell(0, i, i)], u[atlas->tileCell(0, i + 1, i + 1)]);
        EXPECT_GE(u[atlas->tileCell(0, 0, 0)], u[atlas->tileCell(0, 1, 0)]);
    }
}

TEST(AtlasCpu, GenericPathOnRotatedTilesEqualsThePeriodicGrid) {
    // A diffusing chemical at rate 0 sends the run down the generic row-pass
    // path (the fused kernels refuse it), which walks atlas rows with
    // atlasLaplacianRow; s1 and s2 still diffuse across the tile edges.
    const int n = 8;
    auto atlas = std::make_shared<const Atlas>(Atlas::rotatedTiles(n));
    const std::vector<std::uint32_t> planeCell = Atlas::rotatedTilesPlaneCells(n);
    Session onAtlas = loadPreset("meinhardt_random_stripes");
    onAtlas.params["Dg"] = 0.0f;
    useAtlas(onAtlas, atlas);
    ASSERT_EQ(fusedExplicitStep(onAtlas.reactionModel(), StepConstants::fromSession(onAtlas)),
              nullptr);
    Session grid = onAtlas;
    grid.atlas.reset();
    grid.width = grid.height = 3 * n;
    const State gridStart =
        makeInitialState(grid.init, grid.reactionModel(), grid.params, grid.width, grid.height, 9);
    const int chemicals = gridStart.channels();
    State atlasStart(atlas->width(), atlas->height(), chemicals);
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        for (int c = 0; c < chemicals; ++c)
            atlasStart.plane(c)[i] = gridStart.plane(c)[planeCell[i]];
    const State a = runOn(onAtlas, atlasStart, 60), g = runOn(grid, gridStart, 60);
    float worst = 0;
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        for (int c = 0; c < chemicals; ++c)
            worst = std::max(worst, std::fabs(a.plane(c)[i] - g.plane(c)[planeCell[i]]));
    EXPECT_LT(worst, 1e-5f * test::maxAbsValue(g));
    EXPECT_GT(test::maxAbsDifference(g, gridStart), 1e-4f);
}
