// Semi-implicit steps on a weighted atlas (the CPU's Jacobi passes,
// relaxRowsWeighted through PaddedAtlasStep): each pass is the double
// reference's Jacobi pass, the passes converge on the implicit solve, active
// tiles solve alone, a step far past the explicit limit keeps pure diffusion
// within its start's range, frozen and unused texels keep their values, and a surface session left
// to choose its integrator runs semi-implicit exactly where it pays.

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "atlas_checks.hpp"
#include "core/base/errors.hpp"
#include "core/domain/atlas_diagonals.hpp"
#include "core/models/initial_condition.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/segments.hpp"
#include "core/surface/surface_setup.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// An open atlas with a partial last row of tiles (PaddedTilesStep... in
// atlas_weights_test) and symmetric 9-point weights whose sums vary by 9x.
std::shared_ptr<const Atlas> openAtlas() {
    auto open = std::make_shared<Atlas>(6, 5, 3);
    open->glue(0, TileEdge::PlusX, 1, TileEdge::MinusX);
    open->glue(1, TileEdge::MinusY, 3, TileEdge::PlusX, true);
    open->glue(3, TileEdge::MinusY, 4, TileEdge::PlusY);
    return open;
}

Session semiImplicit(Session s, std::shared_ptr<const AtlasWeights> weights, int passes) {
    useAtlas(s, s.atlas, std::move(weights));
    s.integrator = Integrator::SemiImplicit;
    s.relaxationPasses = passes;
    return s;
}

// `passes` Jacobi passes of (I - dt r L) x = b from x = b's start, in double:
// x' = (b + dt r sides) / (1 + dt r S) on used texels, the rest kept.
// Only the texels of `active` tiles move when it is not empty.
std::vector<double> referenceJacobi(const Atlas& atlas, const AtlasWeights& w, const State& start,
                                    double rate, double dt, int passes,
                                    const std::vector<int>& active = {}) {
    const auto& n = atlas.neighbours();
    const auto d = atlasDiagonals(atlas);
    const float* b = start.plane(0); // pure diffusion: rhs = c
    std::vector<double> x(b, b + atlas.cellCount()), next = x;
    for (int pass = 0; pass < passes; ++pass) {
        for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
            if (!atlas.used(i) || (!active.empty() && std::find(active.begin(), active.end(),
                                                                atlas.tileOf(i)) == active.end()))
                continue;
            double sides = 0, sum = 0;
            for (std::size_t k = 0; k < 4; ++k) {
                sides += double(w.coefficients[i][k]) * x[n[i][k]];
                sum += w.coefficients[i][k];
                sides += double(w.diagonal[i][k]) * x[d[i][k]];
                sum += w.diagonal[i][k];
            }
            next[i] = (b[i] + dt * rate * sides) / (1.0 + dt * rate * sum);
        }
        std::swap(x, next);
    }
    return x;
}

// max over used texels of |x - dt r L x - b|, in double (b = start).
double implicitResidual(const Atlas& atlas, const AtlasWeights& w, const State& start,
                        const State& x, double rate, double dt) {
    const auto& n = atlas.neighbours();
    const auto d = atlasDiagonals(atlas);
    const float* u = x.plane(0);
    double worst = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        double lap = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            lap += double(w.coefficients[i][k]) * (double(u[n[i][k]]) - u[i]);
            lap += double(w.diagonal[i][k]) * (double(u[d[i][k]]) - u[i]);
        }
        worst = std::max(worst, std::abs(u[i] - dt * rate * lap - start.plane(0)[i]));
    }
    return worst;
}

} // namespace

TEST(AtlasSemiImplicitCpu, EachPassIsJacobisAndThePassesSolveTheImplicitStep) {
    const auto atlas = openAtlas();
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    const State start = test::randomUsedState(*atlas, 4);
    Session s = semiImplicit(test::pureDiffusionSession(atlas), weights, 3);
    const double rate = s.params.at("Du");
    // Far past the explicit limit: the largest sum's Gershgorin bound times 20.
    s.dt = float(20.0 / (rate * maxCoefficientSum(*weights)));
    for (int passes : {1, 3}) {
        s.relaxationPasses = passes;
        CpuSimulator sim(s);
        sim.setState(start);
        sim.run(1);
        const State x = sim.state();
        const std::vector<double> ref =
            referenceJacobi(*atlas, *weights, start, rate, s.dt, passes);
        double worst = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
            if (atlas->used(i))
                worst = std::max(worst, std::abs(double(x.plane(0)[i]) - ref[i]));
            else
                EXPECT_EQ(x.plane(0)[i], start.plane(0)[i]) << "unused cell " << i;
        EXPECT_LT(worst, 1e-5) << passes << " passes";
    }
    // Enough passes solve (I - dt A) x = c: the residual falls from the
    // start's (x = c) to round-off.
    State before = start;
    const double initial = implicitResidual(*atlas, *weights, start, before, rate, s.dt);
    s.relaxationPasses = 400;
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(1);
    EXPECT_GT(initial, 0.1);
    EXPECT_LT(implicitResidual(*atlas, *weights, start, sim.state(), rate, s.dt), 1e-4);
}

// Each chemical relaxes only as long as it needs (chemicalRelaxationPasses):
// Gray-Scott's v diffuses at half u's rate, so fewer passes leave it the
// residual u has after all of them. With u = 0 (and F = k = 0) the reaction
// is 0, so v's step is pure diffusion: it must equal the double reference's
// Jacobi passes at v's own count, and its implicit residual must be no larger
// than u's own Jacobi residual bound after the full count.
TEST(AtlasSemiImplicitCpu, ASlowerChemicalStopsAfterItsOwnPasses) {
    const auto atlas = openAtlas();
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    Session s = semiImplicit(test::pureDiffusionSession(atlas), weights, 8);
    const double du = s.params.at("Du"), dv = s.params.at("Dv");
    ASSERT_LT(dv, du);
    s.dt = float(2.0 / (du * maxCoefficientSum(*weights)));
    const StepConstants k = StepConstants::fromSession(s);
    const double sigmaU = s.dt * du * maxCoefficientSum(*weights);
    const double sigmaV = s.dt * dv * maxCoefficientSum(*weights);
    const double rhoU = sigmaU / (1 + sigmaU), rhoV = sigmaV / (1 + sigmaV);
    EXPECT_NEAR(k.contraction, rhoU, 1e-12);
    EXPECT_EQ(chemicalRelaxationPasses(k, 0), 8);
    const int own = chemicalRelaxationPasses(k, 1);
    // The fewest passes that reach u's residual factor after eight.
    EXPECT_LE(std::pow(rhoV, own), std::pow(rhoU, 8) * (1 + 1e-9));
    EXPECT_GT(std::pow(rhoV, own - 1), std::pow(rhoU, 8));
    ASSERT_LT(own, 8);
    ASSERT_GE(own, 1);

    // v random, u = 0: the kernel relaxes both for `own` passes, then u alone
    // (v carried through the remaining swaps).
    State start = test::randomUsedState(*atlas, 5);
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (atlas->used(i)) {
            start.plane(1)[i] = start.plane(0)[i];
            start.plane(0)[i] = 0.0f;
        }
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(1);
    const State x = sim.state();
    State vStart = start; // v's plane as chemical 0, for the one-chemical reference
    std::copy_n(start.plane(1), atlas->cellCount(), vStart.plane(0));
    const std::vector<double> ref = referenceJacobi(*atlas, *weights, vStart, dv, s.dt, own);
    double worst = 0;
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (atlas->used(i)) {
            worst = std::max(worst, std::abs(double(x.plane(1)[i]) - ref[i]));
            EXPECT_EQ(x.plane(0)[i], 0.0f);
        }
    EXPECT_LT(worst, 1e-5);
    // And not what more passes give: the count is really v's own.
    const std::vector<double> more = referenceJacobi(*atlas, *weights, vStart, dv, s.dt, 8);
    double apart = 0;
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (atlas->used(i))
            apart = std::max(apart, std::abs(ref[i] - more[i]));
    EXPECT_GT(apart, 1e-4);
    // Several steps in one run equal one run per step (the carried chemical
    // comes back to the state each step).
    CpuSimulator many(s), single(s);
    many.setState(start);
    single.setState(start);
    many.run(3);
    for (int i = 0; i < 3; ++i)
        single.run(1);
    EXPECT_EQ(test::maxAbsDifference(many.state(), single.state()), 0.0f);
}

// Lo's localized reaction-diffusion: only the active tiles solve, their
// neighbours held, the rest kept bit for bit.
TEST(AtlasSemiImplicitCpu, ActiveTilesSolveAloneWithTheirNeighboursHeld) {
    const auto atlas = openAtlas();
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    const State start = test::randomUsedState(*atlas, 5);
    Session s = semiImplicit(test::pureDiffusionSession(atlas), weights, 3);
    const double rate = s.params.at("Du");
    s.dt = float(20.0 / (rate * maxCoefficientSum(*weights)));
    for (const std::vector<int>& active : std::vector<std::vector<int>>{{0, 1, 3}, {4, 2}}) {
        CpuSimulator sim(s);
        sim.setActiveTiles(active);
        sim.setState(start);
        sim.run(1);
        const State x = sim.state();
        const std::vector<double> ref =
            referenceJacobi(*atlas, *weights, start, rate, s.dt, 3, active);
        double worst = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i) {
            const bool steps = atlas->used(i) && std::find(active.begin(), active.end(),
                                                           atlas->tileOf(i)) != active.end();
            if (steps)
                worst = std::max(worst, std::abs(double(x.plane(0)[i]) - ref[i]));
            else
                EXPECT_EQ(x.plane(0)[i], start.plane(0)[i]) << "cell " << i;
        }
        EXPECT_LT(worst, 1e-5);
        EXPECT_GT(test::maxAbsDifference(x, start), 1e-3f) << "nothing happened";
    }
}

TEST(AtlasSemiImplicitCpu, StepsFarPastTheExplicitLimitStayWithinTheStartsRange) {
    const auto atlas = openAtlas();
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    const State start = test::randomUsedState(*atlas, 7);
    Session s = semiImplicit(test::pureDiffusionSession(atlas), weights, 2);
    s.dt = float(50.0 / (s.params.at("Du") * maxCoefficientSum(*weights)));
    float lo = 1e9f, hi = -1e9f;
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (atlas->used(i)) {
            lo = std::min(lo, start.plane(0)[i]);
            hi = std::max(hi, start.plane(0)[i]);
        }
    CpuSimulator sim(s);
    sim.setState(start);
    sim.run(200);
    const State end = sim.state();
    float endLo = 1e9f, endHi = -1e9f;
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (atlas->used(i)) {
            ASSERT_TRUE(std::isfinite(end.plane(0)[i])) << "cell " << i;
            endLo = std::min(endLo, end.plane(0)[i]);
            endHi = std::max(endHi, end.plane(0)[i]);
        }
    // A convex combination per pass: no new extrema; and it diffused.
    EXPECT_GE(endLo, lo);
    EXPECT_LE(endHi, hi);
    EXPECT_LT(endHi - endLo, 0.5f * (hi - lo));
    // The same session explicit at this dt blows up (clamped to Gray-Scott's range).
    Session explicitRun = s;
    explicitRun.integrator = Integrator::ExplicitEuler;
    CpuSimulator blown(explicitRun);
    blown.setState(start);
    blown.run(20);
    EXPECT_GT(test::maxAbsDifference(blown.state(), end), 0.1f);
}

TEST(AtlasSemiImplicitCpu, FrozenTexelsKeepTheirValuesAndRunsSplitAlike) {
    const auto atlas = openAtlas();
    auto weights = std::make_shared<const AtlasWeights>(test::symmetricNinePointWeights(*atlas, 9));
    Session s = loadPreset("gs_coral");
    useAtlas(s, atlas, weights);
    s.integrator = Integrator::SemiImplicit;
    const State from = makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 3);
    std::vector<std::uint8_t> frozen(atlas->cellCount(), 0);
    for (int t = 0; t < atlas->tileCount(); ++t)
        frozen[atlas->tileCell(t, 1, 2)] = 1;
    frozen[atlas->tileCell(0, 5, 5)] = 1;
    CpuSimulator whole(s), single(s);
    for (CpuSimulator* sim : {&whole, &single}) {
        sim->setFrozen(frozen);
        sim->setState(from);
    }
    whole.run(30);
    for (int i = 0; i < 30; ++i)
        single.run(1);
    EXPECT_EQ(test::maxAbsDifference(whole.state(), single.state()), 0.0f);
    EXPECT_GT(test::maxAbsDifference(whole.state(), from), 1e-3f) << "nothing happened";
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (frozen[i] || !atlas->used(i))
            for (int c = 0; c < 2; ++c)
                EXPECT_EQ(whole.state().plane(c)[i], from.plane(c)[i]) << "cell " << i;
}

TEST(AtlasSemiImplicitCpu, OnlyIsotropicDropFreeWeightsRunIt) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    Session unweighted = test::atlasSession(atlas);
    unweighted.integrator = Integrator::SemiImplicit;
    try {
        CpuSimulator sim(unweighted);
        ADD_FAILURE() << "semi-implicit on an unweighted atlas was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("runs on a weighted atlas (a model's surface) only"),
                  std::string::npos)
            << e.what();
    }
    auto unit = std::make_shared<const AtlasWeights>(uniformAtlasWeights(*atlas));
    Session ok = test::atlasSession(atlas);
    useAtlas(ok, atlas, unit);
    ok.integrator = Integrator::SemiImplicit;
    EXPECT_NO_THROW(CpuSimulator{ok});
}

TEST(AtlasSemiImplicitCpu, ASurfaceLeftToChooseRunsSemiImplicitWhereSubstepsWouldCostMore) {
    const auto atlas = openAtlas();
    // Scaled so that the explicit step needs several substeps.
    AtlasWeights weights = test::symmetricNinePointWeights(*atlas, 9);
    for (auto* links : {&weights.coefficients, &weights.diagonal})
        for (auto& texel : *links)
            for (float& w : texel)
                w *= 6.0f;
    Session s = test::pureDiffusionSession(atlas);
    const double ratio = maxCoefficientSum(weights) / 4.0;
    const int substeps = int(std::ceil(ratio - 1e-9));
    ASSERT_GE(substeps, 3);
    bool switched = true;
    s.relaxationPasses = substeps - 1;
    EXPECT_EQ(chooseSurfaceIntegrator(s, weights, &switched), substeps);
    EXPECT_FALSE(switched);
    EXPECT_EQ(s.integrator, Integrator::ExplicitEuler);
    s.relaxationPasses = substeps - 2;
    EXPECT_EQ(chooseSurfaceIntegrator(s, weights, &switched), substeps);
    EXPECT_TRUE(switched);
    EXPECT_EQ(s.integrator, Integrator::SemiImplicit);
    // A session that named its integrator keeps it.
    Session given = test::pureDiffusionSession(atlas);
    given.relaxationPasses = 1;
    given.integratorGiven = true;
    chooseSurfaceIntegrator(given, weights, &switched);
    EXPECT_FALSE(switched);
    EXPECT_EQ(given.integrator, Integrator::ExplicitEuler);
    // Drops (drift) have no semi-implicit step.
    AtlasWeights drops = weights;
    drops.drift = std::make_shared<const AtlasDrift>();
    Session dropping = test::pureDiffusionSession(atlas);
    dropping.relaxationPasses = 1;
    chooseSurfaceIntegrator(dropping, drops, &switched);
    EXPECT_FALSE(switched);
    // Nor a diffusion rate from a param map.
    Session mapped = test::pureDiffusionSession(atlas);
    mapped.relaxationPasses = 1;
    mapped.paramMaps["Du"] = ParamMapSpec{};
    chooseSurfaceIntegrator(mapped, weights, &switched);
    EXPECT_FALSE(switched);
    // Read from JSON: a session that names it is given; one that does not is not.
    EXPECT_FALSE(loadPreset("turk_large_spots").integratorGiven);
    EXPECT_TRUE(
        sessionFromJson(sessionToJson(loadPreset("turk_large_spots")), "test").integratorGiven);
}
