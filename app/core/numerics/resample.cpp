#include "core/numerics/resample.hpp"

#include <algorithm>
#include <cmath>

namespace morphogen {

State resampleBilinear(const State& source, int width, int height, EdgeMode edges) {
    State out(width, height, source.channels());
    const int sw = source.width(), sh = source.height();
    const double sx = double(sw) / width, sy = double(sh) / height;
    for (int y = 0; y < height; ++y) {
        const double fy = (y + 0.5) * sy - 0.5;
        const int y0 = int(std::floor(fy));
        const float ty = float(fy - y0);
        const int ya = GridDomain::wrapOrClamp(y0, sh, edges);
        const int yb = GridDomain::wrapOrClamp(y0 + 1, sh, edges);
        for (int x = 0; x < width; ++x) {
            const double fx = (x + 0.5) * sx - 0.5;
            const int x0 = int(std::floor(fx));
            const float tx = float(fx - x0);
            const int xa = GridDomain::wrapOrClamp(x0, sw, edges);
            const int xb = GridDomain::wrapOrClamp(x0 + 1, sw, edges);
            for (int c = 0; c < source.channels(); ++c) {
                const float top = source.at(c, xa, ya) * (1 - tx) + source.at(c, xb, ya) * tx;
                const float bottom = source.at(c, xa, yb) * (1 - tx) + source.at(c, xb, yb) * tx;
                out.at(c, x, y) = top * (1 - ty) + bottom * ty;
            }
        }
    }
    return out;
}

std::vector<std::uint8_t> resampleMask(const std::vector<std::uint8_t>& mask, int sourceWidth,
                                       int sourceHeight, int width, int height) {
    std::vector<std::uint8_t> out(std::size_t(width) * height);
    const double sx = double(sourceWidth) / width, sy = double(sourceHeight) / height;
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, sourceWidth - 1);
        y = std::clamp(y, 0, sourceHeight - 1);
        return double(mask[std::size_t(y) * sourceWidth + x] != 0);
    };
    for (int y = 0; y < height; ++y) {
        const double fy = (y + 0.5) * sy - 0.5;
        const int y0 = int(std::floor(fy));
        const double ty = fy - y0;
        for (int x = 0; x < width; ++x) {
            const double fx = (x + 0.5) * sx - 0.5;
            const int x0 = int(std::floor(fx));
            const double tx = fx - x0;
            const double v = (1 - ty) * ((1 - tx) * at(x0, y0) + tx * at(x0 + 1, y0)) +
                             ty * ((1 - tx) * at(x0, y0 + 1) + tx * at(x0 + 1, y0 + 1));
            out[std::size_t(y) * width + x] = v >= 0.5 ? 1 : 0;
        }
    }
    return out;
}

} // namespace morphogen
