#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/base/state.hpp"
#include "core/session/session.hpp"

namespace morphogen {

class Atlas;

// Per atlas cell: the display chemical min-max normalised over the used texels
// (the height of the relief) and its colour through the session's map (the
// colour map of the final state's model). What a surface screenshot, a GLB
// export and the designer's 3D view show.
struct SurfaceColours {
    std::vector<float> height;
    std::vector<std::array<std::uint8_t, 4>> colours;
};

SurfaceColours surfaceColours(const State& state, const Session& session, const Atlas& atlas);

} // namespace morphogen
