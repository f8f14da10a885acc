#pragma once
// Checks shared by cascade_test (CPU) and cascade_gltest (GPU): the same
// semantics must hold on both backends.

#include "core/sim/runner.hpp"

namespace morphogen::test {

// Cells frozen by a stage's rule keep every chemical bit for bit through the
// following stage, while the others keep changing.
void checkFrozenCellsExact(const SimulatorFactory& make);
// A stage's reset values land on exactly the frozen cells.
void checkLeopardReset(const SimulatorFactory& make);
// A stage that changes model (Turk's giraffe: Turing spots, then Meinhardt's
// stripes): its freeze rule reads the Turing result, the frozen cells hold the
// reset values of the new model's chemicals bit for bit (and the new model's
// start for chemicals not reset), the other cells run the new model.
void checkModelChangeFreezesAndResets(const SimulatorFactory& make);
// With F mapped over x and no diffusion, one Gray-Scott step from u = v = 0
// gives u = dt F(x): the parameter each cell used, read back.
void checkParamMapReadBack(const SimulatorFactory& make);

} // namespace morphogen::test
