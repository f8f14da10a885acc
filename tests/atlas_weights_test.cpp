// Per-texel weights on an atlas on the CPU (atlas_weights.hpp): unit weights
// are the unweighted atlas bit for bit, the weights reach interior and border
// texels alike, flux-symmetric weights conserve the area-weighted amount, the
// stability bound and substeps follow the weights, and weights that do not fit
// the atlas are refused.

#include <algorithm>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "atlas_checks.hpp"
#include "core/base/errors.hpp"
#include "core/domain/atlas_diagonals.hpp"
#include "core/models/initial_condition.hpp"
#include "core/operators/stability.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/segments.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

State runOn(const Session& s, const State& start, int steps) {
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(steps);
    return sim.state();
}

Session weighted(Session s, std::shared_ptr<const AtlasWeights> weights) {
    useAtlas(s, s.atlas, std::move(weights));
    return s;
}

State startOf(const Session& s, unsigned seed) {
    return makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, seed);
}

} // namespace

TEST(AtlasWeightsCpu, UnitWeightsAreTheUnweightedAtlasBitForBit) {
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(8, 3, 2));
    auto unit = std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas));
    // Two chemicals and six (every built-in model runs the fused kernels).
    for (const char* preset : {"gs_coral", "meinhardt_random_stripes"}) {
        SCOPED_TRACE(preset);
        Session plain = loadPreset(preset);
        useAtlas(plain, atlas);
        const Session withWeights = weighted(plain, unit);
        const State start = startOf(plain, 5);
        const State a = runOn(plain, start, 80), b = runOn(withWeights, start, 80);
        EXPECT_EQ(test::maxAbsDifference(a, b), 0.0f);
        EXPECT_GT(test::maxAbsDifference(a, start), 1e-4f) << "nothing happened";
    }
}

TEST(AtlasWeightsCpu, WeightsTwoAreDoubledRatesOnInteriorAndBorderTexels) {
    // rate * (2 l + 2 r + 2 d + 2 u - 8 c) and (2 rate) * (l + r + d + u - 4 c)
    // round the same: equal bits on every texel, so the weights are read on
    // interior texels (the fused rows) and border texels (the index array).
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    const Session plain = test::atlasSession(atlas);
    Session doubled = plain;
    doubled.params["Du"] *= 2.0f;
    doubled.params["Dv"] *= 2.0f;
    doubled.dt = 0.5f; // within the doubled rates' limit for both
    Session twos =
        weighted(plain, std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas, 2.0f)));
    twos.dt = 0.5f;
    const State start = startOf(plain, 3);
    const State a = runOn(doubled, start, 60), b = runOn(twos, start, 60);
    EXPECT_EQ(test::maxAbsDifference(a, b), 0.0f);
    EXPECT_GT(test::maxAbsDifference(runOn(twos, start, 60), runOn(plain, start, 60)), 1e-4f)
        << "the weights changed nothing";
}

TEST(AtlasWeightsCpu, NinePointOnAWeightedAtlasRunsTheWeighted5PointAndSaysSo) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    auto unit = std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas));
    const Session five = weighted(test::atlasSession(atlas, Stencil::FivePoint), unit);
    const Session nine = weighted(test::atlasSession(atlas, Stencil::NinePoint), unit);
    const State start = startOf(five, 2);
    EXPECT_EQ(test::maxAbsDifference(runOn(five, start, 30), runOn(nine, start, 30)), 0.0f);
    EXPECT_TRUE(StepConstants::fromSession(nine).nineToFivePoint);
    EXPECT_NE(describePlan(nine).find("the 9-point stencil runs as the weighted 5-point"),
              std::string::npos)
        << describePlan(nine);
    EXPECT_EQ(describePlan(five), "");
}

namespace {

void expectAreaWeightedMassConserved(std::shared_ptr<const Atlas> atlas) {
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricWeights(*atlas, 17));
    const Session s = weighted(test::pureDiffusionSession(atlas), weights);
    const State start = test::randomUsedState(*atlas, 3);
    const State end = runOn(s, start, 200);
    const double before = test::areaWeightedSum(start, *atlas, *weights, 0);
    const double after = test::areaWeightedSum(end, *atlas, *weights, 0);
    // c_ij a_i equals c_ji a_j to float rounding (~1e-7): far below 1e-5
    // relative after 200 steps; a weight read from the wrong side or link
    // moves the amount by ~1e-3 relative or more (checked below).
    EXPECT_NEAR(after, before, 1e-5 * before);
    EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
    // The plain sum is not what the weights conserve.
    EXPECT_GT(std::fabs(test::usedSum(end, *atlas, 0) - test::usedSum(start, *atlas, 0)),
              1e-3 * test::usedSum(start, *atlas, 0));
}

} // namespace

TEST(AtlasWeightsCpu, SymmetricWeightsConserveTheAreaWeightedAmountOnTheCube) {
    expectAreaWeightedMassConserved(std::make_shared<const Atlas>(Atlas::cube(8)));
}

TEST(AtlasWeightsCpu, SymmetricWeightsConserveTheAreaWeightedAmountOnRotatedTiles) {
    expectAreaWeightedMassConserved(std::make_shared<const Atlas>(Atlas::rotatedTiles(8)));
}

TEST(AtlasWeightsCpu, WeightsThatDoNotFitTheAtlasAreRefused) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(4));
    Session s = test::atlasSession(atlas);
    AtlasWeights shorter = uniformAtlasWeights(*atlas);
    shorter.coefficients.pop_back();
    try {
        useAtlas(s, atlas, std::make_shared<const AtlasWeights>(shorter));
        FAIL() << "weights of the wrong size were accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "atlas weights: " + std::to_string(atlas->cellCount() - 1) +
                      " coefficient and " + std::to_string(atlas->cellCount()) + " area entries"),
                  std::string::npos)
            << e.what();
    }
    AtlasWeights negative = uniformAtlasWeights(*atlas);
    negative.area[5] = -1.0f;
    EXPECT_THROW(useAtlas(s, atlas, std::make_shared<const AtlasWeights>(negative)), InputError);
    // A session whose weights were swapped behind useAtlas's back is refused when it runs.
    s.atlasWeights = std::make_shared<const AtlasWeights>(shorter);
    EXPECT_THROW(CpuSimulator{s}, InputError);
}

TEST(AtlasWeightsCpu, StabilityAndSubstepsFollowTheLargestWeightSum) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    AtlasWeights w = uniformAtlasWeights(*atlas);
    w.coefficients[atlas->tileCell(2, 3, 3)] = {3.0f, 2.0f, 2.5f, 2.0f}; // sum 9.5
    const Session s = weighted(test::atlasSession(atlas), std::make_shared<const AtlasWeights>(w));
    const ExplicitStability st = explicitStability(compileDiffusion(s), s.domain(), s.dt);
    EXPECT_FALSE(st.exact);
    EXPECT_NE(st.basis.find("weighted atlas"), std::string::npos) << st.basis;
    ASSERT_TRUE(st.maxStableDt);
    EXPECT_NEAR(*st.maxStableDt, 1.0 / (9.5 * s.params.at("Du")), 1e-6);
    // ceil(9.5 / 4) = 3 steps of dt / 3 per session step, as ceil(1 / h^2) on grids.
    const std::vector<Segment> segments = segmentsOf(s);
    ASSERT_EQ(segments.size(), 1u);
    EXPECT_EQ(segments[0].substeps, 3);
    EXPECT_FLOAT_EQ(segments[0].session.dt, s.dt / 3.0f);
    EXPECT_EQ(segments[0].session.steps, 3 * s.steps);
    EXPECT_NE(describePlan(s).find("every step runs as 3 steps of dt/3"), std::string::npos)
        << describePlan(s);
    // Sums at most 4: no substeps.
    const Session unit =
        weighted(test::atlasSession(atlas),
                 std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas)));
    EXPECT_EQ(segmentsOf(unit)[0].substeps, 1);
}

TEST(AtlasWeightsCpu, CappedSumsKeepEveryFluxAndTheAmount) {
    // A texel of a third of the area with three times the coefficients (its
    // neighbours' links to it unchanged: the pair's flux is the same both
    // ways), as a squeezed texel is: sum 12 needs 3 substeps.
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    AtlasWeights w = uniformAtlasWeights(*atlas);
    const std::uint32_t squeezed = atlas->tileCell(2, 3, 3);
    w.coefficients[squeezed] = {3.0f, 3.0f, 3.0f, 3.0f};
    w.area[squeezed] = 1.0f / 3.0f;
    ASSERT_EQ(weightedSubsteps(w), 3);
    int capped = 0;
    float smallest = 0;
    const AtlasWeights c = capCoefficientSums(w, 4.0f, &capped, &smallest);
    EXPECT_EQ(capped, 1);
    EXPECT_NEAR(smallest, 1.0f / 3.0f, 1e-6f);
    EXPECT_LE(maxCoefficientSum(c), 4.0f);
    EXPECT_EQ(weightedSubsteps(c), 1);
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        for (std::size_t d = 0; d < 4; ++d)
            EXPECT_NEAR(c.coefficients[i][d] * c.area[i], w.coefficients[i][d] * w.area[i], 1e-6f);
    // The capped weights are still valid, and diffusion on them keeps the amount.
    auto shared = std::make_shared<const AtlasWeights>(c);
    checkAtlasWeights(*atlas, *shared);
    const Session s = weighted(test::pureDiffusionSession(atlas), shared);
    const State start = test::randomUsedState(*atlas, 3);
    const State end = runOn(s, start, 100);
    EXPECT_NEAR(test::areaWeightedSum(end, *atlas, c, 0),
                test::areaWeightedSum(start, *atlas, c, 0),
                1e-5 * test::areaWeightedSum(start, *atlas, c, 0));
    // Under the limit nothing changes.
    const AtlasWeights same = capCoefficientSums(w, 20.0f, &capped, &smallest);
    EXPECT_EQ(capped, 0);
    EXPECT_EQ(smallest, 1.0f);
    EXPECT_EQ(same.coefficients, w.coefficients);
    EXPECT_EQ(same.area, w.area);
}

TEST(AtlasWeightsCpu, OperatorsAnAtlasCannotRunAreStillRefusedWithWeights) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    auto unit = std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas));
    for (const char* preset : {"wk_zebra", "gs_generalized_c"}) {
        Session s = loadPreset(preset);
        useAtlas(s, atlas, unit);
        EXPECT_THROW(CpuSimulator{s}, InputError) << preset;
    }
    // The semi-implicit step runs on weights: atlas_semi_implicit_test.
}

// Weights with diagonals (the 9-point stencil of sheared surface texels).

namespace {

// One explicit step of pure diffusion of u (gs_coral with F = k = 0 and v = 0:
// no reaction on u), in double, with the weights' 9 points.
std::vector<double> referenceStep(const Atlas& atlas, const AtlasWeights& w, const State& start,
                                  double rate, double dt) {
    const auto& n = atlas.neighbours();
    const auto d = atlasDiagonals(atlas);
    const float* u = start.plane(0);
    std::vector<double> out(atlas.cellCount());
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        double lap = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            lap += double(w.coefficients[i][k]) * (double(u[n[i][k]]) - u[i]);
            lap += double(w.diagonal[i][k]) * (double(u[d[i][k]]) - u[i]);
        }
        out[i] = atlas.used(i) ? u[i] + dt * rate * lap : u[i];
    }
    return out;
}

} // namespace

// Every texel, interior (the fused rows) and border (the index arrays), steps
// by the 9-point weighted Laplacian: float rounding off a double reference.
// The index path of active tiles (every tile active) agrees with the
// whole-texture run: the fused kernel on padded tiles for a two- and a
// six-chemical model, and the generic row path.
TEST(AtlasWeightsCpu, NinePointWeightsReachEveryTexelOnEveryPath) {
    for (auto atlas : {std::make_shared<const Atlas>(Atlas::cube(6)),
                       std::make_shared<const Atlas>(Atlas::rotatedTiles(6))}) {
        auto weights =
            std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 4));
        const Session s = weighted(test::pureDiffusionSession(atlas), weights);
        const State start = test::randomUsedState(*atlas, 8);
        const State one = runOn(s, start, 1);
        const std::vector<double> ref =
            referenceStep(*atlas, *weights, start, s.params.at("Du"), s.dt);
        double worst = 0, moved = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i) {
            worst = std::max(worst, std::abs(double(one.plane(0)[i]) - ref[i]));
            moved = std::max(moved, std::abs(ref[i] - double(start.plane(0)[i])));
        }
        EXPECT_LT(worst, 1e-6);
        EXPECT_GT(moved, 0.05);
        // Without the diagonals the step differs by far more than rounding.
        AtlasWeights noDiagonals = *weights;
        noDiagonals.diagonal.clear();
        const State five =
            runOn(weighted(s, std::make_shared<const AtlasWeights>(noDiagonals)), start, 1);
        EXPECT_GT(test::maxAbsDifference(five, one), 1e-2f);

        // The third: a diffusing chemical at rate 0 takes the generic path.
        for (const auto& [preset, zeroRate] :
             {std::pair{"gs_coral", ""}, std::pair{"meinhardt_random_stripes", ""},
              std::pair{"meinhardt_random_stripes", "Dg"}}) {
            SCOPED_TRACE(std::string(preset) + " " + zeroRate);
            Session p = loadPreset(preset);
            if (*zeroRate)
                p.params[zeroRate] = 0.0f;
            useAtlas(p, atlas, weights);
            ASSERT_EQ(fusedWeightedStep(p.reactionModel(), StepConstants::fromSession(p)) ==
                          nullptr,
                      bool(*zeroRate));
            const State from = startOf(p, 5);
            const State whole = runOn(p, from, 40);
            CpuSimulator tiles(p);
            std::vector<int> all(std::size_t(atlas->tileCount()));
            for (int t = 0; t < atlas->tileCount(); ++t)
                all[std::size_t(t)] = t;
            tiles.setActiveTiles(all);
            tiles.setState(from);
            tiles.run(40);
            EXPECT_LT(test::maxAbsDifference(whole, tiles.state()), 1e-5f);
            EXPECT_GT(test::maxAbsDifference(whole, from), 1e-4f) << "nothing happened";
        }
    }
}

TEST(AtlasWeightsCpu, NinePointWeightsConserveTheAreaWeightedAmount) {
    for (auto atlas : {std::make_shared<const Atlas>(Atlas::cube(8)),
                       std::make_shared<const Atlas>(Atlas::rotatedTiles(8))}) {
        auto weights =
            std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 17));
        const Session s = weighted(test::pureDiffusionSession(atlas), weights);
        const State start = test::randomUsedState(*atlas, 3);
        const State end = runOn(s, start, 200);
        const double before = test::areaWeightedSum(start, *atlas, *weights, 0);
        EXPECT_NEAR(test::areaWeightedSum(end, *atlas, *weights, 0), before, 1e-5 * before);
        EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
    }
}

TEST(AtlasWeightsCpu, NinePointWeightsRunWhateverTheStencilAndCountInTheBound) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    AtlasWeights w = uniformAtlasWeights(*atlas, 0.5f);
    w.diagonal.assign(atlas->cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    const std::uint32_t c = atlas->tileCell(2, 3, 3); // interior: every diagonal is one texel
    w.diagonal[c] = {1.0f, 2.0f, 0.5f, 1.5f};         // sum 2 + 5 = 7
    EXPECT_FLOAT_EQ(maxCoefficientSum(w), 7.0f);
    EXPECT_EQ(weightedSubsteps(w), 2);
    auto shared = std::make_shared<const AtlasWeights>(w);
    const Session five = weighted(test::atlasSession(atlas, Stencil::FivePoint), shared);
    const Session nine = weighted(test::atlasSession(atlas, Stencil::NinePoint), shared);
    EXPECT_FALSE(StepConstants::fromSession(nine).nineToFivePoint);
    EXPECT_TRUE(StepConstants::fromSession(nine).crossWeighted());
    EXPECT_NE(describePlan(nine).find("the weights' 9-point stencil runs"), std::string::npos)
        << describePlan(nine);
    const State start = startOf(five, 2);
    EXPECT_EQ(test::maxAbsDifference(runOn(five, start, 10), runOn(nine, start, 10)), 0.0f);
}

TEST(AtlasWeightsCpu, DiagonalWeightsThatDoNotFitAreRefused) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(4));
    const auto refused = [&](const AtlasWeights& w, const std::string& message) {
        try {
            checkAtlasWeights(*atlas, w);
            ADD_FAILURE() << "accepted; expected: " << message;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    };
    AtlasWeights w = uniformAtlasWeights(*atlas);
    w.diagonal.assign(atlas->cellCount() - 1, {0.0f, 0.0f, 0.0f, 0.0f});
    refused(w, "diagonal entries for an atlas of");
    w.diagonal.assign(atlas->cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    checkAtlasWeights(*atlas, w);
    w.diagonal[atlas->tileCell(1, 1, 1)][2] = -0.5f;
    refused(w, "negative or non-finite diagonal coefficient");
    // A cube corner (valence 3): the corner texel's diagonal towards it is two texels.
    w.diagonal.assign(atlas->cellCount(), {0.0f, 0.0f, 0.0f, 0.0f});
    const std::uint32_t corner = atlas->cornerCell(0, 0);
    const auto d = atlasDiagonals(*atlas);
    ASSERT_NE(d[corner][0], d[corner][4]);
    w.diagonal[corner][0] = 1.0f;
    refused(w, "towards an irregular tile corner");
}

// A weighted atlas steps on tiles padded with halos (PaddedAtlasStep), all of
// them or the active ones. Against the double reference: open edges (the halo
// holds the texel itself), a partial last row of tiles, active tiles side by
// side and apart, frozen texels kept exactly and unused ones untouched; and a
// run of 30 steps equals 30 runs of one (the padded layout lives for a run).
TEST(AtlasWeightsCpu, PaddedTilesStepOpenEdgesActiveTilesAndFrozenTexels) {
    auto open = std::make_shared<Atlas>(6, 5, 3); // tiles 0, 1, 2 on a row, 3, 4 below
    open->glue(0, TileEdge::PlusX, 1, TileEdge::MinusX);
    open->glue(1, TileEdge::MinusY, 3, TileEdge::PlusX, true);
    open->glue(3, TileEdge::MinusY, 4, TileEdge::PlusY);
    const std::shared_ptr<const Atlas> atlas = open;
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    const Session s = weighted(test::pureDiffusionSession(atlas), weights);
    const State start = test::randomUsedState(*atlas, 4);
    const std::vector<double> ref = referenceStep(*atlas, *weights, start, s.params.at("Du"), s.dt);
    std::vector<std::uint8_t> frozen(atlas->cellCount(), 0);
    for (int t = 0; t < atlas->tileCount(); ++t)
        frozen[atlas->tileCell(t, 1, 2)] = 1;
    frozen[atlas->tileCell(0, 5, 5)] = 1; // a corner texel

    for (const std::vector<int>& active : std::vector<std::vector<int>>{{}, {0, 1, 3}, {4, 2}}) {
        CpuSimulator sim(s);
        sim.setFrozen(frozen);
        sim.setActiveTiles(active);
        sim.setState(start);
        sim.run(1);
        const State one = sim.state();
        double worst = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i) {
            const int tile = atlas->tileOf(i);
            const bool steps =
                tile >= 0 && !frozen[i] &&
                (active.empty() || std::find(active.begin(), active.end(), tile) != active.end());
            if (steps)
                worst = std::max(worst, std::abs(double(one.plane(0)[i]) - ref[i]));
            else
                EXPECT_EQ(one.plane(0)[i], start.plane(0)[i]) << "cell " << i;
        }
        EXPECT_LT(worst, 1e-6);
    }

    Session reacting = loadPreset("gs_coral");
    useAtlas(reacting, atlas, weights);
    const State from = startOf(reacting, 3);
    CpuSimulator whole(reacting), single(reacting);
    for (CpuSimulator* sim : {&whole, &single}) {
        sim->setFrozen(frozen);
        sim->setState(from);
    }
    whole.run(30);
    for (int i = 0; i < 30; ++i)
        single.run(1);
    EXPECT_EQ(test::maxAbsDifference(whole.state(), single.state()), 0.0f);
    EXPECT_GT(test::maxAbsDifference(whole.state(), from), 1e-3f) << "nothing happened";
}
