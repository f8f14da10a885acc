#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace morphogen {

// What a brush write does to its cells (core/sim/brush.hpp applies it). Kept
// apart from the brush itself so that sessions can record strokes
// (live_edit.hpp) without the session layer knowing the simulator.
enum class BrushMode {
    Add,       // chemical += value * weight
    Remove,    // chemical -= value * weight
    Set,       // chemical -> value (blended by weight)
    Hold,      // cells keep their values, exactly like frozen cells
    Release,   // held cells evolve again
    Randomise, // chemical += value * weight * noise, noise in [-1, 1) from seed (Lo's distort)
    Paint,     // parameter `param` -> value per cell (blended by weight); a parameter that is a
               // diffusion rate paints that chemical's diffusion-rate map
};
std::string toString(BrushMode mode);
std::optional<BrushMode> parseBrushMode(std::string_view name);
std::string brushModeNames();

// Whether the mode writes a chemical (else the frozen mask or a parameter map).
inline bool writesChemical(BrushMode mode) {
    return mode == BrushMode::Add || mode == BrushMode::Remove || mode == BrushMode::Set ||
           mode == BrushMode::Randomise;
}

} // namespace morphogen
