#pragma once
// Checks shared by cascade_test (CPU) and cascade_gltest (GPU): the same
// semantics must hold on both backends.

#include "core/runner.hpp"

namespace morphogen::test {

// Cells frozen by a stage's rule keep every chemical bit for bit through the
// following stage, while the others keep changing.
void checkFrozenCellsExact(const SimulatorFactory& make);
// A stage's reset values land on exactly the frozen cells.
void checkLeopardReset(const SimulatorFactory& make);
// With F mapped over x and no diffusion, one Gray-Scott step from u = v = 0
// gives u = dt F(x): the parameter each cell used, read back.
void checkParamMapReadBack(const SimulatorFactory& make);

} // namespace morphogen::test
