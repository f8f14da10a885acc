#include "core/session/gravity.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/base/json_fields.hpp"
#include "core/numerics/kernel.hpp"

namespace morphogen {

Gravity gravityFromJson(const FieldReader& top, const nlohmann::json& block) {
    FieldReader reader(block, top.source(), "gravity");
    reader.rejectUnknown({"angle", "strength"});
    Gravity g;
    g.angle = reader.number("angle", g.angle, -360.0, 360.0);
    g.strength = reader.number("strength", g.strength, 0.0, kMaxGravityStrength);
    return g;
}

nlohmann::json gravityToJson(const Gravity& gravity) {
    return {{"angle", gravity.angle}, {"strength", gravity.strength}};
}

void addGravityDrift(Kernel5& kernel, const Gravity& gravity, double cellSize) {
    constexpr double kDegree = 3.14159265358979323846 / 180.0;
    // Display y points up the image; the grid's rows grow down it.
    const double vx = gravity.strength / cellSize * std::cos(gravity.angle * kDegree);
    const double vy = -gravity.strength / cellSize * std::sin(gravity.angle * kDegree);
    // A texel receives from the neighbour upstream of it and loses downstream.
    kernel.at(-1, 0) += std::max(0.0, vx);
    kernel.at(1, 0) += std::max(0.0, -vx);
    kernel.at(0, -1) += std::max(0.0, vy);
    kernel.at(0, 1) += std::max(0.0, -vy);
    kernel.at(0, 0) -= std::fabs(vx) + std::fabs(vy);
}

} // namespace morphogen
