// Why `morphogen map` runs with clamped (zero-flux) edges: on a parameter map, a periodic grid
// joins the two ends of each swept range, so the pattern of one end leaks into the other and
// draws a strip along the border that belongs to neither parameter value.

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/session/session.hpp"
#include "test_support.hpp"

using namespace morphogen;
using morphogen::test::runCpu;

namespace {

constexpr int kWidth = 48, kHeight = 24;

// Gray-Scott swept in k across x as `map --x k:0.058:0.09` would: coral grows where k is low
// (left), and v dies out where k is high (right).
Session sweptSession(EdgeMode edges) {
    Session s = loadPreset("gs_coral");
    s.width = kWidth;
    s.height = kHeight;
    s.steps = 3000;
    s.edges = edges;
    s.init.spotCount = 40;
    s.init.spotRadius = 3;
    s.paramMaps["k"] = {ParamMapSpec::Field::LinearX, 0.058f, 0.09f};
    validateSession(s, "test");
    return s;
}

// Largest |v - v'| between two cells of column x: 0 when the column is uniform.
float columnRange(const State& state, int chemical, int x) {
    float lo = state.at(chemical, x, 0), hi = lo;
    for (int y = 1; y < state.height(); ++y) {
        lo = std::min(lo, state.at(chemical, x, y));
        hi = std::max(hi, state.at(chemical, x, y));
    }
    return hi - lo;
}

float columnMax(const State& state, int chemical, int x) {
    float hi = state.at(chemical, x, 0);
    for (int y = 1; y < state.height(); ++y)
        hi = std::max(hi, state.at(chemical, x, y));
    return hi;
}

} // namespace

TEST(MapEdges, ClampedEdgesKeepTheEndsOfTheSweptAxisApart) {
    constexpr int v = 1;
    const State periodic = runCpu(sweptSession(EdgeMode::Periodic));
    const State clamped = runCpu(sweptSession(EdgeMode::Clamped));
    // Precondition: v persists at the low-k edge in both runs (a solid or patterned region).
    ASSERT_GT(columnMax(periodic, v, 0), 0.1f);
    ASSERT_GT(columnMax(clamped, v, 0), 0.1f);
    // Periodic: the left edge's v reaches the high-k right edge through the wrap (measured 0.12).
    EXPECT_GT(columnMax(periodic, v, kWidth - 1), 1e-2f);
    // Clamped: the right edge sees only its own inert neighbours and settles uniform (v ~ 1e-19).
    EXPECT_LT(columnMax(clamped, v, kWidth - 1), 1e-6f);
    EXPECT_LT(columnRange(clamped, v, kWidth - 1), 1e-6f);
}
