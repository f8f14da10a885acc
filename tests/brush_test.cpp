// Brush regions, and brush writes on the CPU backend (brush_gltest runs the
// same checks on the GPU and compares the two).

#include <set>

#include <gtest/gtest.h>

#include "brush_checks.hpp"
#include "core/base/errors.hpp"
#include "core/sim/brush.hpp"
#include "core/sim/cpu_simulator.hpp"

using namespace morphogen;

namespace {

SimulatorFactory cpu() {
    return [](const Session& s) { return std::make_unique<CpuSimulator>(s); };
}

// Every cell lies in exactly one rectangle, and every rectangle in the grid.
void expectRectsPartitionCells(const BrushRegion& region) {
    const int w = region.gridWidth(), h = region.gridHeight();
    for (const CellRect& r : region.rects()) {
        EXPECT_GE(r.x, 0);
        EXPECT_GE(r.y, 0);
        EXPECT_LE(r.x + r.width, w);
        EXPECT_LE(r.y + r.height, h);
    }
    for (const BrushRegion::Cell& cell : region.cells()) {
        const int x = int(cell.index) % w, y = int(cell.index) / w;
        int holders = 0;
        for (const CellRect& r : region.rects())
            holders += x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
        EXPECT_EQ(holders, 1) << "cell (" << x << ", " << y << ")";
    }
}

} // namespace

TEST(BrushRegion, DiscIsTheCellsWithinTheRadius) {
    const GridDomain grid(30, 20, EdgeMode::Clamped);
    const BrushRegion region = BrushRegion::disc(grid, 10.5f, 7.0f, 4.2f);
    std::set<std::uint32_t> expected;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 30; ++x)
            if ((x - 10.5f) * (x - 10.5f) + (y - 7.0f) * (y - 7.0f) <= 4.2f * 4.2f)
                expected.insert(std::uint32_t(y * 30 + x));
    std::set<std::uint32_t> got;
    for (const BrushRegion::Cell& c : region.cells()) {
        got.insert(c.index);
        EXPECT_EQ(c.weight, 1.0f);
    }
    EXPECT_EQ(got, expected);
    ASSERT_EQ(region.rects().size(), 1u);
    expectRectsPartitionCells(region);
}

TEST(BrushRegion, PeriodicDiscWrapsAcrossTheCornerInFourRectangles) {
    const GridDomain grid(16, 12, EdgeMode::Periodic);
    const BrushRegion region = BrushRegion::disc(grid, 0.0f, 0.0f, 2.5f);
    // 21 cells: the disc of radius 2.5 around a cell centre, wrapped.
    EXPECT_EQ(region.cells().size(), 21u);
    EXPECT_EQ(region.rects().size(), 4u);
    expectRectsPartitionCells(region);
    std::set<std::uint32_t> got;
    for (const BrushRegion::Cell& c : region.cells())
        got.insert(c.index);
    EXPECT_TRUE(got.count(11 * 16 + 15));  // (-1, -1)
    EXPECT_TRUE(got.count(0 * 16 + 14));   // (-2, 0)
    EXPECT_FALSE(got.count(10 * 16 + 14)); // (-2, -2): distance 2.83
}

TEST(BrushRegion, ClampedDiscIsCutAtTheEdge) {
    const GridDomain grid(16, 12, EdgeMode::Clamped);
    const BrushRegion region = BrushRegion::disc(grid, 0.0f, 0.0f, 2.5f);
    EXPECT_EQ(region.cells().size(), 8u); // the quarter disc with x, y >= 0
    EXPECT_EQ(region.rects().size(), 1u);
    expectRectsPartitionCells(region);
    EXPECT_TRUE(BrushRegion::disc(grid, -10.0f, -10.0f, 2.0f).empty());
}

TEST(BrushRegion, FalloffRampsTheWeightToTheRim) {
    const GridDomain grid(32, 32, EdgeMode::Periodic);
    const BrushRegion region = BrushRegion::disc(grid, 16.0f, 16.0f, 8.0f, 0.5f);
    for (const BrushRegion::Cell& c : region.cells()) {
        const float dx = float(int(c.index % 32)) - 16.0f, dy = float(int(c.index / 32)) - 16.0f;
        const float d = std::sqrt(dx * dx + dy * dy);
        EXPECT_NEAR(c.weight, d <= 4.0f ? 1.0f : (8.0f - d) / 4.0f, 1e-6f);
        EXPECT_GT(c.weight, 0.0f);
    }
}

TEST(BrushRegion, DiscLargerThanAPeriodicGridCoversEachCellOnce) {
    const GridDomain grid(8, 6, EdgeMode::Periodic);
    const BrushRegion region = BrushRegion::disc(grid, 3.0f, 3.0f, 40.0f);
    EXPECT_EQ(region.cells().size(), 48u);
    expectRectsPartitionCells(region);
}

TEST(BrushRegion, CellSetsAreCheckedAndBounded) {
    const GridDomain grid(10, 10, EdgeMode::Periodic);
    const BrushRegion region = BrushRegion::fromCells(grid, {{55, 1.0f}, {12, 0.5f}, {37, 1.0f}});
    ASSERT_EQ(region.rects().size(), 1u);
    const CellRect r = region.rects()[0];
    EXPECT_EQ(r.x, 2);
    EXPECT_EQ(r.y, 1);
    EXPECT_EQ(r.width, 6);
    EXPECT_EQ(r.height, 5);
    EXPECT_EQ(region.cells().front().index, 12u);
    EXPECT_THROW(BrushRegion::fromCells(grid, {{100, 1.0f}}), InputError);
    EXPECT_THROW(BrushRegion::fromCells(grid, {{5, 0.0f}}), InputError);
    EXPECT_THROW(BrushRegion::fromCells(grid, {{5, 1.0f}, {5, 1.0f}}), InputError);
}

TEST(CpuBrush, ChemicalWritesChangeExactlyTheRegion) {
    test::checkChemicalBrushes(cpu());
}

TEST(CpuBrush, RandomiseIsReproducibleAndLocal) {
    test::checkRandomiseReproducible(cpu());
}

TEST(CpuBrush, HeldCellsStayFixedWhileTheRestEvolves) {
    test::checkHoldAndRelease(cpu());
}

TEST(CpuBrush, PaintedParametersChangeTheDynamicsOnlyInTheRegion) {
    test::checkPaintedParameters(cpu());
}

TEST(CpuBrush, CellParamsAreTheValuesTheStepUses) {
    test::checkCellParams(cpu());
}

TEST(CpuBrush, BadBrushesAreRefused) {
    test::checkBadBrushes(cpu());
}
