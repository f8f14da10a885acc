#include "core/surface/tile_split.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace morphogen {

namespace {

// Texels per quad side in the estimate: enough to see a quad's taper and
// corners; the real tile size does not change which point is best by much.
constexpr int kSamples = 6;
// Each barycentric coordinate of p stays in [kMargin, 1/2 - kMargin]: inside
// the medial triangle (1/2: a quad's corner at a midpoint reaches 180 degrees)
// and off the triangle's edges.
constexpr double kMargin = 0.02;

using Vec2 = Eigen::Vector2d;

double cost2d(const Vec2 corner[3], const Vec2& p) {
    const Vec2 m[3] = {0.5 * (corner[0] + corner[1]), 0.5 * (corner[1] + corner[2]),
                       0.5 * (corner[2] + corner[0])};
    double worst = 0;
    for (int k = 0; k < 3; ++k) {
        // Corner k's quad: its vertex, the leaving midpoint, p, the arriving midpoint.
        const Vec2 q0 = corner[k], q1 = m[k], q2 = p, q3 = m[(k + 2) % 3];
        for (int j = 0; j < kSamples; ++j)
            for (int i = 0; i < kSamples; ++i) {
                const double s = (i + 0.5) / kSamples, t = (j + 0.5) / kSamples;
                const Vec2 ju = (1 - t) * (q1 - q0) + t * (q2 - q3);
                const Vec2 jv = (1 - s) * (q3 - q0) + s * (q2 - q1);
                const double cross = ju.x() * jv.y() - ju.y() * jv.x();
                const double lu = ju.squaredNorm(), lv = jv.squaredNorm();
                if (!(cross > 0) || !(lu > 0) || !(lv > 0))
                    return std::numeric_limits<double>::infinity();
                const double sine = cross / std::sqrt(lu * lv);
                worst = std::max(worst, 2 * (1 / lu + 1 / lv) / sine);
            }
    }
    return worst;
}

// The triangle in its own plane: a at the origin, b on +x, c above (counter-clockwise).
bool flatten(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
             Vec2 out[3]) {
    const Eigen::Vector3d ab = (b - a).cast<double>(), ac = (c - a).cast<double>();
    const double len = ab.norm();
    const Eigen::Vector3d n = ab.cross(ac);
    if (!(len > 0) || !(n.norm() > 0))
        return false;
    const Eigen::Vector3d x = ab / len, y = n.normalized().cross(x);
    out[0] = Vec2(0, 0);
    out[1] = Vec2(len, 0);
    out[2] = Vec2(ac.dot(x), ac.dot(y));
    return true;
}

Vec2 at(const Vec2 corner[3], double b0, double b1) {
    return b0 * corner[0] + b1 * corner[1] + (1 - b0 - b1) * corner[2];
}

bool allowed(double b0, double b1) {
    const double b2 = 1 - b0 - b1;
    const double lo = kMargin, hi = 0.5 - kMargin;
    return b0 >= lo && b0 <= hi && b1 >= lo && b1 <= hi && b2 >= lo && b2 <= hi;
}

} // namespace

double quadSplitCost(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                     const Eigen::Vector3f& bary) {
    Vec2 corner[3];
    if (!flatten(a, b, c, corner))
        return std::numeric_limits<double>::infinity();
    return cost2d(corner, at(corner, double(bary[0]), double(bary[1])));
}

Eigen::Vector3f quadSplitPoint(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                               const Eigen::Vector3f& c) {
    const Eigen::Vector3f centroid = Eigen::Vector3f::Constant(1.0f / 3.0f);
    Vec2 corner[3];
    if (!flatten(a, b, c, corner))
        return centroid;
    double best0 = 1.0 / 3.0, best1 = 1.0 / 3.0;
    double best = cost2d(corner, at(corner, best0, best1));
    // A grid over the allowed region, then two finer grids round the best point so far.
    double step = 1.0 / 24.0;
    double c0 = 1.0 / 3.0, c1 = 1.0 / 3.0;
    int reach = 12;
    for (int level = 0; level < 3; ++level) {
        for (int i = -reach; i <= reach; ++i)
            for (int j = -reach; j <= reach; ++j) {
                const double b0 = c0 + i * step, b1 = c1 + j * step;
                if (!allowed(b0, b1))
                    continue;
                const double cost = cost2d(corner, at(corner, b0, b1));
                // Strictly better only: the centroid wins ties (an equilateral triangle).
                if (cost < best * (1 - 1e-9)) {
                    best = cost;
                    best0 = b0;
                    best1 = b1;
                }
            }
        c0 = best0;
        c1 = best1;
        step /= 6;
        reach = 6;
    }
    return Eigen::Vector3f(float(best0), float(best1), float(1 - best0 - best1));
}

} // namespace morphogen
