// Witkin-Kass's threshold reaction (eq. 13, with the threshold as a
// parameter): where it fires on hand-made cells, and what the threshold does
// to a pattern grown from the jittered diamond grid.

#include <cstdio>

#include <gtest/gtest.h>

#include "core/models/witkin_kass.hpp"
#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// dC/dt of one cell (p, m) for the model's defaults with `threshold`.
std::array<float, 2> rate(float p, float m, float threshold) {
    const ReactionModel& model = *findModel("witkin_kass");
    ParamValues values;
    for (const ParamSpec& spec : model.params())
        values[spec.name] = spec.defaultValue;
    values["threshold"] = threshold;
    const std::vector<float> params = model.packParams(values);
    float c[2] = {p, m}, dcdt[2] = {};
    RowView row;
    row.n = 1;
    row.c[0] = &c[0];
    row.c[1] = &c[1];
    row.dcdt[0] = &dcdt[0];
    row.dcdt[1] = &dcdt[1];
    model.react(row, params.data());
    return {dcdt[0], dcdt[1]};
}

// Share of cells where the reaction fires (C+ - C- > threshold).
double onShare(const State& s, float threshold) {
    std::size_t on = 0;
    for (std::size_t i = 0; i < s.cellCount(); ++i)
        on += s.plane(0)[i] - s.plane(1)[i] > threshold;
    return double(on) / double(s.cellCount());
}

} // namespace

TEST(WitkinKass, TheReactionFiresStrictlyAboveTheThreshold) {
    // Defaults k = 1, b = 1: dC/dt = R - C.
    for (float threshold : {0.0f, -1.5f, 0.75f}) {
        SCOPED_TRACE(threshold);
        const float m = 0.5f;
        EXPECT_EQ(rate(m + threshold + 0.25f, m, threshold)[0], 1.0f - (m + threshold + 0.25f));
        EXPECT_EQ(rate(m + threshold + 0.25f, m, threshold)[1], 1.0f - m);
        EXPECT_EQ(rate(m + threshold, m, threshold)[0], -(m + threshold)); // a tie does not fire
        EXPECT_EQ(rate(m + threshold - 0.25f, m, threshold)[1], -m);
    }
    // The paper's eq. 13 is the default: fire where C+ > C-.
    EXPECT_EQ(findModel("witkin_kass")->param("threshold")->defaultValue, 0.0f);
}

TEST(WitkinKass, ANegativeThresholdFavoursTheFiringPhase) {
    // Seeds on a jittered diamond grid, firing, in a background that does not.
    Session s;
    s.model = "witkin_kass";
    s.params = {{"k", 1.0f}, {"b", 0.05f}, {"Dp", 0.1f}, {"Dm", 2.0f}, {"threshold", 0.0f}};
    s.width = s.height = 64;
    s.dt = 0.04f;
    s.steps = 1500;
    s.diffusion.stencil = Stencil::NinePoint;
    s.init.type = InitialCondition::Type::JitteredGrid;
    s.init.base = {{"p", 0.0f}, {"m", 6.0f}};
    s.init.inside = {{"p", 3.0f}, {"m", 0.0f}};
    s.init.spacing = 16.0f;
    s.init.spotRadius = 3.0f;
    const double symmetric = onShare(test::runCpu(s), 0.0f);
    s.params["threshold"] = -3.2f;
    const double favoured = onShare(test::runCpu(s), -3.2f);
    std::printf("firing share: threshold 0 %.3f, threshold -3.2 %.3f\n", symmetric, favoured);
    // Threshold 0: on and off are symmetric (G+ - G- integrates to zero).
    EXPECT_GT(symmetric, 0.2);
    EXPECT_LT(symmetric, 0.6);
    EXPECT_GT(favoured, symmetric + 0.15);
}
