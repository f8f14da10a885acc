#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/base/state.hpp"
#include "core/session/session.hpp"
#include "core/surface/display_atlas.hpp"
#include "core/surface/textured_surface.hpp"

namespace morphogen {

class Atlas;

// Per atlas cell: the display chemical min-max normalised over the used texels
// (the height of the relief) and its colour through the session's map (the
// colour map of the final state's model). What a surface screenshot, a GLB
// export and the designer's 3D view show.
//
// Watercolour (a model with standing water "w" and the watercolour map: Lo
// 5.6's drops and washes) shows its water as water instead: `wetness` per
// cell, 0 on dry texels to 1 where the water stands kWetDepth or deeper, and
// the relief is the water's height (not the paint's), at `relief` =
// kWaterRelief times the deepest water over kWetDepth (at most 1) of the
// bump: drops bulge more than a pattern's relief, and a drying wash flattens
// instead of showing its last film magnified.
struct SurfaceColours {
    std::vector<float> height;
    std::vector<std::array<std::uint8_t, 4>> colours;
    std::vector<float> wetness; // empty: no water to show
    float relief = 1.0f;        // scales SurfaceLook::bump
    // At a look's scale above 1: every chemical interpolated to the texels
    // of `displayAtlas` and mapped there, so a contour is as sharp as the
    // texture allows instead of the atlas texels' colours blended (alpha 0
    // where no tile is). Empty at scale 1: `colours` are padded as they are.
    std::shared_ptr<const DisplayAtlas> displayAtlas;
    std::vector<std::array<std::uint8_t, 4>> display;
};

// Water this deep (model units of the "w" chemical) looks fully wet.
constexpr float kWetDepth = 0.5f;
// Standing water's relief against a pattern's (SurfaceLook::bump).
constexpr float kWaterRelief = 3.0f;

// `levels`, when given, replace the min-max range of the display chemical (a
// frame sequence's locked levels). `reuse`, a display atlas an earlier call
// made for the same atlas and look (SurfaceColours::displayAtlas), saves
// building it again (a frame sequence's every frame).
SurfaceColours surfaceColours(const State& state, const Session& session, const Atlas& atlas,
                              const std::optional<std::pair<float, float>>& levels = {},
                              const SurfaceLook& look = {},
                              std::shared_ptr<const DisplayAtlas> reuse = nullptr);

} // namespace morphogen
