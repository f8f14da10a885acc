#include "core/numerics/resample.hpp"

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

} // namespace morphogen
