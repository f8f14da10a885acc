#pragma once

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/session/session.hpp"

namespace morphogen::cli {

// `render`'s flags for what a session's JSON holds beyond parameters and size:
// the orientation of anisotropic diffusion, parameter maps and the initial
// condition. Each flag edits the session's JSON block ("diffusion",
// "param_maps", "init") and reads it back through that block's reader, so a
// flag accepts exactly what the JSON accepts, with the same ranges and
// messages (prefixed with the flag). Numbers are kept as text until then so
// every message names the flag.
struct KnobFlags {
    std::string theta;                    // --theta DEG
    std::vector<std::string> orientation; // --orientation KIND[:...], repeatable: a blend
    std::string anisotropy;               // --anisotropy RATIO
    std::vector<std::string> paramMaps;   // --param-map NAME=FIELD:..., repeatable
    std::string init;                     // --init TYPE
    std::string spots;                    // --spots N
    std::string spotRadius;               // --spot-radius R
    std::string spacing;                  // --spacing S
    std::string jitter;                   // --jitter J
    std::string square;                   // --square FRACTION
    std::vector<std::string> initBase;    // --init-base CHEM=V,... (repeatable)
    std::vector<std::string> initNoise;   // --init-noise CHEM=V,...
    std::vector<std::string> initInside;  // --init-inside CHEM=V,...
    std::string gravity;                  // --gravity ANGLE:STRENGTH, or off
    std::string gravityDirection;         // --gravity-direction X,Y,Z (on a model)
};

// The rate ratio (along / across) --theta and --orientation give a session
// whose diffusion is isotropic when --anisotropy is not given.
constexpr double kDefaultAnisotropy = 4.0;

// Registers the flags on `cmd`, in three help groups.
void addKnobFlags(CLI::App& cmd, KnobFlags& flags);

// Applies the flags to `session` (diffusion, then parameter maps, then the
// initial condition, then gravity). Returns notes for stderr about what was changed beyond
// the flag's own key (an isotropic session made anisotropic, an orientation
// field replaced). Throws InputError naming the flag.
std::vector<std::string> applyKnobFlags(const KnobFlags& flags, Session& session);

// The JSON orientation field ("diffusion.map.orientation") one --orientation
// value stands for: "constant:DEG", "radial[:CX,CY]", "concentric[:CX,CY]",
// "spiral:TWIST[:CX,CY]", "vortex:TWIST[:CX,CY]", "image:FILE" (the parts after
// the kind in either order). Checks the syntax only; ranges are the reader's.
nlohmann::json orientationFlagJson(const std::string& text);

// The parameter and its JSON map ("param_maps.NAME") one --param-map value
// stands for: "NAME=linear_x:LOW:HIGH", "NAME=linear_y:LOW:HIGH",
// "NAME=radial:LOW:HIGH[:CX,CY]", "NAME=noise:LOW:HIGH[:SCALE]",
// "NAME=image:FILE:LOW:HIGH"; "NAME=none" gives a null map (remove it).
std::pair<std::string, nlohmann::json> paramMapFlagJson(const std::string& text);

// The JSON "gravity" block one --gravity value stands for: "ANGLE:STRENGTH"
// (degrees, units per unit time) or "off" (strength 0). Ranges are the reader's.
nlohmann::json gravityFlagJson(const std::string& text);

} // namespace morphogen::cli
