// The start noise as a field in model units (core/base/noise_field.hpp).

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/noise_field.hpp"
#include "core/base/random.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/session.hpp"

using namespace morphogen;

TEST(NoiseField, AtOneCellPerUnitItIsThePerCellDraw) {
    const NoiseField field(7, 40, 30, 1.0, true), perCell(7, 40, 30, 0.0, true);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            ASSERT_EQ(field.at(3, x, y), perCell.at(3, x, y));
            ASSERT_EQ(perCell.at(3, x, y), uniformSigned(7, 3, std::uint64_t(y) * 40 + x));
        }
}

TEST(NoiseField, TwiceTheResolutionIsTheSameFieldInFinerCells) {
    const int n = 64;
    const NoiseField coarse(3, n, n, 1.0, true), fine(3, 2 * n, 2 * n, 0.5, true);
    // Each coarse cell against the mean of the four fine cells over it.
    double sab = 0, saa = 0, sbb = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double a = coarse.at(0, x, y);
            const double b =
                0.25 * (fine.at(0, 2 * x, 2 * y) + fine.at(0, 2 * x + 1, 2 * y) +
                        fine.at(0, 2 * x, 2 * y + 1) + fine.at(0, 2 * x + 1, 2 * y + 1));
            sab += a * b;
            saa += a * a;
            sbb += b * b;
        }
    const double correlation = sab / std::sqrt(saa * sbb);
    // Per-cell draws at the two sizes would correlate about 0.
    EXPECT_GT(correlation, 0.7);
    // A per-cell field at the fine size, for contrast.
    const NoiseField perCell(3, 2 * n, 2 * n, 0.0, true);
    double pab = 0, pbb = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double b = perCell.at(0, 2 * x, 2 * y);
            pab += coarse.at(0, x, y) * b;
            pbb += b * b;
        }
    EXPECT_LT(std::abs(pab / std::sqrt(saa * pbb)), 0.1);
}

TEST(NoiseField, APeriodicFieldWrapsWithoutASeam) {
    const int n = 32;
    const NoiseField fine(5, 2 * n, 2 * n, 0.5, true);
    // The last column interpolates towards the first lattice column.
    double jump = 0, inside = 0;
    for (int y = 0; y < 2 * n; ++y) {
        jump += std::abs(fine.at(0, 2 * n - 1, y) - fine.at(0, 0, y));
        inside += std::abs(fine.at(0, n, y) - fine.at(0, n - 1, y));
    }
    EXPECT_LT(jump, 1.5 * inside);
}

TEST(InitialCondition, SpotRadiiAreInUnits) {
    Session s = loadPreset("gs_coral"); // seed spots of radius 4 units
    const ReactionModel& model = s.reactionModel();
    auto seeded = [&](int size, double cellSize) {
        const State st = makeInitialState(s.init, model, s.params, size, size, 1, cellSize);
        int n = 0;
        for (std::size_t i = 0; i < st.cellCount(); ++i)
            n += st.plane(1)[i] > 0.2f;
        return n;
    };
    const int own = seeded(128, 1.0), twice = seeded(256, 0.5);
    EXPECT_GT(own, 0);
    // Four times the cells cover the same discs (within the discs' pixel edges).
    EXPECT_NEAR(double(twice) / own, 4.0, 0.4);
}
