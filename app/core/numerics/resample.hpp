#pragma once

#include <cstdint>
#include <vector>

#include "core/base/state.hpp"
#include "core/domain/grid_domain.hpp"

namespace morphogen {

// Bilinear resampling of every chemical to width x height, cell centres
// aligned (the coarse-to-fine hand-over between levels). Periodic grids wrap
// at the edges so the result still tiles; clamped grids hold the edge value.
State resampleBilinear(const State& source, int width, int height, EdgeMode edges);

// A per-cell mask (frozen cells) from sourceWidth x sourceHeight to width x
// height: bilinear, cell centres aligned, then halved at 0.5, so an enlarged
// mask's outlines are cut diagonally between cell centres instead of copying
// the coarse cells' stairs.
std::vector<std::uint8_t> resampleMask(const std::vector<std::uint8_t>& mask, int sourceWidth,
                                       int sourceHeight, int width, int height);

} // namespace morphogen
