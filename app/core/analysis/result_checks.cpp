#include "core/analysis/result_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace morphogen {

PlaneRange planeRange(const float* plane, std::size_t cells) {
    PlaneRange r;
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < cells; ++i) {
        const float v = plane[i];
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        } else if (r.nonFinite++ == 0) {
            r.firstNonFinite = i;
        }
    }
    if (lo <= hi) {
        r.min = lo;
        r.max = hi;
    }
    return r;
}

bool isFlatRange(float lo, float hi) {
    // 1e-5 of the magnitude: a few hundred float ulps, well above the
    // round-off a uniform field keeps, well below any visible structure.
    const float magnitude = std::max({1.0f, std::fabs(lo), std::fabs(hi)});
    return !(hi - lo > 1e-5f * magnitude);
}

std::optional<std::string> describeFlatChannel(const State& state, int channel,
                                               const std::string& name) {
    const PlaneRange r = planeRange(state.plane(channel), state.cellCount());
    if (r.nonFinite > 0 || !isFlatRange(r.min, r.max))
        return std::nullopt;
    std::ostringstream os;
    os << "chemical " << name << " = " << 0.5 * (double(r.min) + double(r.max)) << " everywhere";
    return os.str();
}

bool allChannelsFlat(const State& state) {
    for (int c = 0; c < state.channels(); ++c) {
        const PlaneRange r = planeRange(state.plane(c), state.cellCount());
        if (r.nonFinite > 0 || !isFlatRange(r.min, r.max))
            return false;
    }
    return true;
}

std::optional<std::string> describeNonFinite(const State& state,
                                             const std::vector<std::string>& names) {
    for (int c = 0; c < state.channels(); ++c) {
        const PlaneRange r = planeRange(state.plane(c), state.cellCount());
        if (r.nonFinite == 0)
            continue;
        const std::size_t w = std::size_t(std::max(1, state.width()));
        std::ostringstream os;
        os << r.nonFinite << " of " << state.cellCount() << " cells of "
           << (std::size_t(c) < names.size() ? "chemical " + names[std::size_t(c)]
                                             : "channel " + std::to_string(c))
           << " are NaN or infinite (the first at (" << r.firstNonFinite % w << ", "
           << r.firstNonFinite / w << "))";
        return os.str();
    }
    return std::nullopt;
}

} // namespace morphogen
