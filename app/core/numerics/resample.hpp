#pragma once

#include "core/base/state.hpp"
#include "core/domain/grid_domain.hpp"

namespace morphogen {

// Bilinear resampling of every chemical to width x height, cell centres
// aligned (the coarse-to-fine hand-over between levels). Periodic grids wrap
// at the edges so the result still tiles; clamped grids hold the edge value.
State resampleBilinear(const State& source, int width, int height, EdgeMode edges);

} // namespace morphogen
