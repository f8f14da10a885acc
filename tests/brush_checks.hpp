#pragma once
// Checks shared by brush_test (CPU) and brush_gltest (GPU): brush writes must
// mean the same on both backends.

#include "core/sim/runner.hpp"

namespace morphogen::test {

// Add, remove, set and randomise change exactly the disc's cells of the
// brushed chemical, as an expectation computed here cell by cell (distance,
// falloff, periodic wrap, clamping), and leave every other value bit for
// bit; on Gray-Scott and on Meinhardt's six chemicals (a second state
// texture), with discs inside the grid and across a periodic corner.
void checkChemicalBrushes(const SimulatorFactory& make);
// Randomise: the same seed gives the same bits, another seed other values,
// and only the region changes.
void checkRandomiseReproducible(const SimulatorFactory& make);
// Held cells keep every chemical bit for bit while the rest evolves;
// released, they evolve again.
void checkHoldAndRelease(const SimulatorFactory& make);
// Painting F (a reaction parameter) or Du (a diffusion rate) in a disc:
// after one step only the disc's cells differ from a run whose map holds the
// uniform value everywhere; that map run stays close to the unmapped one.
void checkPaintedParameters(const SimulatorFactory& make);
// Simulator::cellParam (the designer's readout): nullopt for a uniform
// parameter; a session's param map's values; a painted disc's value inside it
// and the uniform value round it; nullopt off the grid.
void checkCellParams(const SimulatorFactory& make);
// Bad brushes throw InputError and leave the state as it was.
void checkBadBrushes(const SimulatorFactory& make);

} // namespace morphogen::test
