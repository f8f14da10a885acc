#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/base/state.hpp"

namespace morphogen {

// Checks on a finished state before it is written, so that a result that is
// not a pattern (NaN, infinite, or one flat value) is reported, never passed
// off as one.

// One plane's finite values' range, and how many cells are not finite.
struct PlaneRange {
    float min = 0, max = 0; // of the finite cells (0, 0 when there are none)
    std::size_t nonFinite = 0;
    std::size_t firstNonFinite = 0; // cell index, when nonFinite > 0
};
PlaneRange planeRange(const float* plane, std::size_t cells);

// Whether lo..hi is one value up to float round-off (relative to the values'
// magnitude, at least 1): ColourMapRows paints such a plane in one colour
// rather than stretch its round-off to the whole palette.
bool isFlatRange(float lo, float hi);

// "chemical v = 0.25 everywhere" when that channel of the state is flat and
// finite; nullopt otherwise. `name` names the channel.
std::optional<std::string> describeFlatChannel(const State& state, int channel,
                                               const std::string& name);

// Whether every channel of the state is flat.
bool allChannelsFlat(const State& state);

// "12 of 4096 cells of chemical u are NaN or infinite (the first at (3, 5))"
// for the first channel holding such values; nullopt when all are finite.
// `names` names the channels (a missing name reads "channel N").
std::optional<std::string> describeNonFinite(const State& state,
                                             const std::vector<std::string>& names);

} // namespace morphogen
