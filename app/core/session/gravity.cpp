#include "core/session/gravity.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/json_fields.hpp"
#include "core/numerics/kernel.hpp"

namespace morphogen {

Gravity gravityFromJson(const FieldReader& top, const nlohmann::json& block) {
    FieldReader reader(block, top.source(), "gravity");
    reader.rejectUnknown({"angle", "strength", "direction", "carrier", "cling"});
    Gravity g;
    g.angle = reader.number("angle", g.angle, -360.0, 360.0);
    g.strength = reader.number("strength", g.strength, 0.0, kMaxGravityStrength);
    if (const nlohmann::json* d = reader.find("direction")) {
        const auto bad = [&](const std::string& got) {
            reader.failField("direction", "must be three numbers [x, y, z] in the mesh's object "
                                          "space, not all zero (e.g. [0, -1, 0]), got " +
                                              got);
        };
        if (!d->is_array() || d->size() != 3)
            bad(d->dump());
        for (std::size_t i = 0; i < 3; ++i) {
            if (!(*d)[i].is_number())
                bad(d->dump());
            g.direction[i] = (*d)[i].get<double>();
        }
        try {
            checkGravityDirection(g.direction, "direction");
        } catch (const InputError&) {
            bad(d->dump());
        }
    }
    g.carrier = reader.string("carrier", "");
    g.cling = reader.number("cling", g.cling, 1e-4, 1e3);
    return g;
}

nlohmann::json gravityToJson(const Gravity& gravity) {
    nlohmann::json j = {{"angle", gravity.angle}, {"strength", gravity.strength}};
    if (gravity.direction != Gravity{}.direction)
        j["direction"] = gravity.direction;
    if (!gravity.carrier.empty())
        j["carrier"] = gravity.carrier;
    // Written whenever it is not the default, so a session reads back equal.
    if (!gravity.carrier.empty() || gravity.cling != Gravity{}.cling)
        j["cling"] = gravity.cling;
    return j;
}

void checkGravityDirection(const std::array<double, 3>& direction, const std::string& what) {
    double length2 = 0;
    for (double v : direction) {
        if (!std::isfinite(v) || std::fabs(v) > 1e6)
            throw InputError("gravity " + what +
                             ": components must be finite numbers up to 1e6 "
                             "in size");
        length2 += v * v;
    }
    if (!(length2 > 1e-12))
        throw InputError("gravity " + what + ": must not be zero (e.g. 0,-1,0: down the model)");
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
