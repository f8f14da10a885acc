// Drops on a tilted canvas (core/session/gravity.hpp) on the CPU backend: the
// drift's kernel, a drop's centre of mass moving along gravity at its speed and
// monotonically, a symmetric spread without gravity, conservation, the
// session's "gravity" block and its bad values.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/models/watercolour.hpp"
#include "core/numerics/kernel.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/session_run.hpp"
#include "test_support.hpp"

using namespace morphogen;
using nlohmann::json;
using M = WatercolourModel;

namespace {

constexpr double kPi = 3.14159265358979323846;

// One wet dab of pigment on a plain paper of `size` cells, one unit per cell;
// with `keepWater` nothing evaporates or soaks in (the water is all there).
json dropJson(int size, double angle, double strength, const std::string& edges, bool keepWater) {
    json j = {{"model", "watercolour"},
              {"size", size},
              {"length", size},
              {"coarse_to_fine", false},
              {"edges", edges},
              {"dt", 0.5},
              {"init", {{"type", "noise"}}},
              {"params", {{"paper_grain", 0}, {"paper_fibres", 0}}},
              {"strokes", json::array({{{"points", {{0.5, 0.5}}},
                                        {"radius", 0.1},
                                        {"water", 2.0},
                                        {"pigment", "p1"},
                                        {"amount", 0.5}}})}};
    if (strength > 0)
        j["gravity"] = {{"angle", angle}, {"strength", strength}};
    if (keepWater) {
        j["params"]["evaporation"] = 0;
        j["params"]["absorption"] = 0;
    }
    return j;
}

struct Moments {
    double mass = 0, x = 0, y = 0; // centre of mass, cells
    double xx = 0, yy = 0, xy = 0; // central second moments
};

Moments momentsOf(const State& s, int chemical) {
    Moments m;
    for (int y = 0; y < s.height(); ++y)
        for (int x = 0; x < s.width(); ++x) {
            const double v = s.at(chemical, x, y);
            m.mass += v;
            m.x += v * (x + 0.5);
            m.y += v * (y + 0.5);
        }
    m.x /= m.mass;
    m.y /= m.mass;
    for (int y = 0; y < s.height(); ++y)
        for (int x = 0; x < s.width(); ++x) {
            const double v = s.at(chemical, x, y), dx = x + 0.5 - m.x, dy = y + 0.5 - m.y;
            m.xx += v * dx * dx;
            m.yy += v * dy * dy;
            m.xy += v * dx * dy;
        }
    m.xx /= m.mass;
    m.yy /= m.mass;
    m.xy /= m.mass;
    return m;
}

} // namespace

// The drift is upwind: a texel receives from its uphill neighbour and loses as
// much as it gives downhill, so the weights off the centre are >= 0 and all of
// them sum to 0 (the total is kept, no new extrema).
TEST(Gravity, DriftKernelIsUpwindAndConservative) {
    Kernel5 k;
    addGravityDrift(k, Gravity{270.0, 0.5}, 0.25); // down the page, 2 cells per unit time
    EXPECT_DOUBLE_EQ(k.at(0, -1), 2.0);            // from the row above
    EXPECT_NEAR(k.at(0, 1), 0.0, 1e-12);
    EXPECT_NEAR(k.at(-1, 0) + k.at(1, 0), 0.0, 1e-12);
    EXPECT_NEAR(k.at(0, 0), -2.0, 1e-12);
    Kernel5 diagonal;
    addGravityDrift(diagonal, Gravity{45.0, 1.0}, 1.0); // up and right
    double sum = 0;
    for (double w : diagonal.w)
        sum += w;
    EXPECT_NEAR(sum, 0.0, 1e-12);
    EXPECT_NEAR(diagonal.at(-1, 0), std::sqrt(0.5), 1e-12); // from the left
    EXPECT_NEAR(diagonal.at(0, 1), std::sqrt(0.5), 1e-12);  // from the row below
    EXPECT_NEAR(diagonal.at(1, 0) + diagonal.at(0, -1), 0.0, 1e-12);
}

// Lo 5.6 on a tilted plane: the water's centre of mass moves along the
// projection of gravity, monotonically, at the drift's speed. For a linear
// operator of constant coefficients the centre moves exactly at the kernel's
// first moment (the drift velocity); diffusion and the symmetric reaction do
// not move it, so the tolerances are float rounding (measured: 5e-5 of the
// distance) as long as nothing reaches the clamped edge and runs off (on a
// 96-cell canvas the tail did: 0.6% short).
TEST(Gravity, DropsCentreOfMassMovesAlongGravity) {
    const double strength = 0.1;
    for (double angle : {270.0, 0.0, 135.0}) {
        SCOPED_TRACE(angle);
        Session s = sessionFromJson(dropJson(128, angle, strength, "clamped", true), "drop");
        // Grid direction: display y points up, rows grow down.
        const double gx = std::cos(angle * kPi / 180), gy = -std::sin(angle * kPi / 180);
        SessionRun run(
            s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
        run.advance(1); // the stroke
        const Moments start = momentsOf(run.state(), M::W);
        double last = 0;
        for (int i = 1; i <= 10; ++i) {
            run.advance(40); // 20 time units
            const Moments m = momentsOf(run.state(), M::W);
            const double along = (m.x - start.x) * gx + (m.y - start.y) * gy;
            const double across = -(m.x - start.x) * gy + (m.y - start.y) * gx;
            EXPECT_GT(along, last) << "step block " << i;
            last = along;
            EXPECT_NEAR(along, strength * 20.0 * i, 1e-3 * strength * 20.0 * i);
            EXPECT_NEAR(across, 0.0, 0.02);
        }
        std::printf("angle %.0f: moved %.3f cells along gravity in 200 time units (drift %.3f)\n",
                    angle, last, strength * 200);
    }
}

// Without gravity the drop spreads the same way in every direction: equal
// second moments along x and y, no cross moment, the centre in place.
TEST(Gravity, WithoutGravityADropSpreadsSymmetrically) {
    Session s = sessionFromJson(dropJson(64, 0.0, 0.0, "periodic", true), "still");
    SessionRun run(
        s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
    run.advance(1);
    const Moments start = momentsOf(run.state(), M::W);
    run.advance(200);
    const Moments m = momentsOf(run.state(), M::W);
    std::printf("second moments: xx %.4f yy %.4f xy %.2g (start xx %.4f)\n", m.xx, m.yy, m.xy,
                start.xx);
    EXPECT_GT(m.xx, 1.5 * start.xx) << "the drop should have spread";
    // The stroke is drawn on the grid's cells: a disc of cells, symmetric
    // under swapping x and y to float rounding.
    EXPECT_NEAR(m.xx / m.yy, 1.0, 1e-3);
    EXPECT_NEAR(m.xy / m.xx, 0.0, 1e-3);
    EXPECT_NEAR(m.x, start.x, 1e-3);
    EXPECT_NEAR(m.y, start.y, 1e-3);
}

// On a periodic canvas the drift only moves water and pigment: water on the
// paper plus water gone, and pigment moving plus deposited, stay constant
// while the drops run, evaporate and settle.
TEST(Gravity, DropsConserveWaterAndPigment) {
    Session s = sessionFromJson(dropJson(48, 250.0, 0.3, "periodic", false), "conserve");
    SessionRun run(
        s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
    run.advance(1);
    const State a = run.state();
    run.advance(400);
    const State b = run.state();
    const double water0 = test::planeSum(a, M::W) + test::planeSum(a, M::G);
    const double water1 = test::planeSum(b, M::W) + test::planeSum(b, M::G);
    const double pigment0 = test::planeSum(a, M::P1) + test::planeSum(a, M::D1);
    const double pigment1 = test::planeSum(b, M::P1) + test::planeSum(b, M::D1);
    // Float rounding over 400 steps of ~2300 cells (as the watercolour test).
    EXPECT_NEAR(water1 / water0, 1.0, 1e-5);
    EXPECT_NEAR(pigment1 / pigment0, 1.0, 1e-5);
    EXPECT_GT(test::planeSum(b, M::G), 0.1 * water0) << "nothing evaporated";
}

// The fused kernel runs a drop (3x3 kernels with the drift) as the generic
// path does.
TEST(Gravity, FusedAndGenericPathsAgree) {
    Session fused = sessionFromJson(dropJson(40, 300.0, 0.4, "clamped", false), "fused");
    fused.steps = 150;
    ASSERT_EQ(compileDiffusion(fused).form, DiffusionOperator::Form::Kernel3);
    ASSERT_NE(fusedExplicitStep(fused.reactionModel(), StepConstants::fromSession(fused)), nullptr);
    Session generic = fused;
    const float v = fused.params.at("trap");
    generic.paramMaps["trap"] = {ParamMapSpec::Field::LinearX, v, v};
    ASSERT_EQ(fusedExplicitStep(generic.reactionModel(), StepConstants::fromSession(generic)),
              nullptr);
    const auto run = [](const Session& s) {
        SessionRun r(
            s, [](const Session& l) { return std::make_unique<CpuSimulator>(l); }, 0);
        while (!r.finished())
            r.advance(s.steps);
        return r.state();
    };
    const State a = run(fused), b = run(generic);
    float worst = 0;
    for (int c = 0; c < a.channels(); ++c)
        for (std::size_t i = 0; i < a.cellCount(); ++i)
            worst = std::max(worst, std::fabs(a.plane(c)[i] - b.plane(c)[i]));
    EXPECT_LT(worst, 1e-5f);
}

TEST(Gravity, SessionsRecordGravityAndRefuseBadValues) {
    const Session s = sessionFromJson(dropJson(32, 200.0, 0.25, "clamped", false), "rec");
    EXPECT_EQ(s.gravity, (Gravity{200.0, 0.25}));
    const json saved = sessionToJson(s);
    EXPECT_EQ(sessionFromJson(saved, "again").gravity, s.gravity);
    // Off: not written, and a session without the block has none.
    Session off = s;
    off.gravity = {};
    EXPECT_FALSE(sessionToJson(off).contains("gravity"));

    const auto refused = [](json j, const std::string& expect) {
        try {
            Session bad = sessionFromJson(j, "bad.json");
            validateSession(bad, "bad.json");
            ADD_FAILURE() << "accepted: " << j["gravity"].dump();
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(expect), std::string::npos) << e.what();
        }
    };
    json j = dropJson(32, 270.0, 0.2, "clamped", false);
    j["gravity"]["strength"] = -1;
    refused(j, "gravity.strength");
    j["gravity"]["strength"] = 1e9;
    refused(j, "gravity.strength");
    j["gravity"] = {{"angle", "down"}};
    refused(j, "gravity.angle");
    j["gravity"] = {{"speed", 1}};
    refused(j, "gravity.speed");
    j["gravity"] = {{"strength", 0.2}, {"direction", {0, 0, 0}}};
    refused(j, "gravity.direction");
}
