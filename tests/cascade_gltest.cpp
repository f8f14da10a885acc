// cascade_test's checks on the GPU backend.

#include <gtest/gtest.h>

#include "cascade_checks.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"

using namespace morphogen;

namespace {
SimulatorFactory gpu() {
    test::glContext();
    return [](const Session& s) { return std::make_unique<gl::GpuSimulator>(s); };
}
} // namespace

TEST(GpuCascade, FrozenCellsKeepTheirValuesBitForBit) {
    test::checkFrozenCellsExact(gpu());
}

TEST(GpuCascade, LeopardResetsFrozenCells) {
    test::checkLeopardReset(gpu());
}

TEST(GpuParamMaps, TheParameterAtACellIsTheMapsValue) {
    test::checkParamMapReadBack(gpu());
}

// Three chemicals on one texture, then six on two (MRT) after the model change.
TEST(GpuCascade, ModelChangeFreezesByTheOldModelAndResetsTheNew) {
    test::checkModelChangeFreezesAndResets(gpu());
}
