#pragma once

#include <array>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class FieldReader;
struct Kernel5;

// Water drops on a tilted canvas (Lo et al. section 5.6): every chemical the
// model lets diffuse (one with a diffusion rate parameter: watercolour's water
// and suspended pigments) also drifts downhill at `strength` model units per
// unit time, in the
// direction `angle` (degrees counter-clockwise from +x on the displayed image;
// 270 runs down the page). The drift is upwind: a texel passes
// strength / h * max(0, g . e) of its amount per unit time to its neighbour in
// direction e (h the cell size), so the operator stays monotone (no new
// extrema) and conserves the total (on a periodic canvas; on a clamped one
// what reaches the downhill edge runs off). Lo biases the diffusion between
// neighbours by g . v_ij; this is that bias as a first-order upwind flux.
// On a model (a session with a surface) `direction` is gravity in the mesh's
// object space instead (glTF's y up: (0, -1, 0) falls down the model); its
// length does not matter. The drift is then g's projection on the surface at
// `strength` (core/surface/surface_drift.hpp).
//
// On a model, `carrier` (a chemical's name, e.g. watercolour's "w") makes the
// drift depend on it: what a texel passes downhill is scaled by the carrier's
// mobility there, m = w / (w + cling), so a drop's deep head runs while its
// thin edge and the film it leaves behind cling (Lo's wet trace): the front
// steepens and a trail stays behind. Empty: every texel drifts alike.
struct Gravity {
    double angle = 270.0;
    double strength = 0.0; // 0: off
    std::array<double, 3> direction = {0.0, -1.0, 0.0};
    std::string carrier;
    double cling = 0.2; // carrier depth at half speed (with a carrier)
    bool active() const { return strength > 0.0; }
    bool operator==(const Gravity& o) const {
        return angle == o.angle && strength == o.strength && direction == o.direction &&
               carrier == o.carrier && cling == o.cling;
    }
    bool operator!=(const Gravity& o) const { return !(*this == o); }
};

// Largest drift accepted, model units per unit time.
constexpr double kMaxGravityStrength = 100.0;

// The "gravity" block of a session: {"angle": degrees, "strength": speed,
// "direction": [x, y, z]} (a non-zero finite vector); errors name the field and
// what is accepted.
Gravity gravityFromJson(const FieldReader& top, const nlohmann::json& block);
nlohmann::json gravityToJson(const Gravity& gravity);

// Adds the drift of `gravity` on a grid of cells `cellSize` units wide to a
// chemical's 3x3 or 5x5 kernel (grid coordinates, rows growing down the image).
void addGravityDrift(Kernel5& kernel, const Gravity& gravity, double cellSize);

// Throws InputError naming `what` unless `direction` is finite and not zero.
void checkGravityDirection(const std::array<double, 3>& direction, const std::string& what);

} // namespace morphogen
