// Localized reaction-diffusion on the GPU: only the active tiles' quads are
// drawn, inactive tiles keep their values bit for bit in both targets, and
// the result agrees with the CPU's localized run.

#include <algorithm>
#include <array>

#include <gtest/gtest.h>

#include "atlas_checks.hpp"
#include "core/models/initial_condition.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// 5 global steps, then `steps` with tiles 5, 6 and 9 active (5 and 6 one
// rectangle), then 3 with tile 5 only: the state before the local steps,
// after them, and at the end.
template <class Sim>
std::array<State, 3> localRun(const Session& s, const State& start, int steps) {
    Sim sim(s);
    sim.setState(start);
    sim.run(5);
    const State before = sim.state();
    sim.setActiveTiles({5, 6, 9});
    sim.run(steps);
    const State after = sim.state();
    sim.setActiveTiles({5});
    sim.run(3);
    return {before, after, sim.state()};
}

} // namespace

TEST(LocalizedGpu, InactiveTilesStayBitIdenticalAndTheCpuAgrees) {
    test::glContext();
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(8, 4, 4));
    for (auto weights : {std::shared_ptr<const AtlasWeights>(),
                         std::make_shared<const AtlasWeights>(test::symmetricWeights(*atlas, 4))}) {
        SCOPED_TRACE(weights ? "weighted" : "unweighted");
        Session s = test::atlasSession(atlas);
        useAtlas(s, atlas, weights);
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 7);
        const auto [before, gpu, shrunk] = localRun<gl::GpuSimulator>(s, start, 31);
        const std::vector<int> active = {5, 6, 9};
        for (int t = 0; t < atlas->tileCount(); ++t) {
            const bool isActive = std::count(active.begin(), active.end(), t) > 0;
            EXPECT_EQ(test::tileEqual(before, gpu, *atlas, t), !isActive) << "tile " << t;
        }
        // Tiles 6 and 9 left the set with the values they had reached.
        EXPECT_TRUE(test::tileEqual(gpu, shrunk, *atlas, 6));
        EXPECT_TRUE(test::tileEqual(gpu, shrunk, *atlas, 9));
        EXPECT_FALSE(test::tileEqual(gpu, shrunk, *atlas, 5));
        const std::array<State, 3> cpu = localRun<CpuSimulator>(s, start, 31);
        EXPECT_LT(test::maxAbsDifference(cpu[1], gpu), 1e-5f * test::maxAbsValue(cpu[1]));
        EXPECT_LT(test::maxAbsDifference(cpu[2], shrunk), 1e-5f * test::maxAbsValue(cpu[2]));
    }
}
