#include "core/sim/stroke_brush.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"

namespace morphogen {

namespace {

int floorMod(int i, int n) {
    const int m = i % n;
    return m < 0 ? m + n : m;
}

// Distance from p to the segment a-b.
double segmentDistance(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = px - (ax + t * dx), ey = py - (ay + t * dy);
    return std::sqrt(ex * ex + ey * ey);
}

} // namespace

namespace {

// The distance from p to the polyline `path` (one point: to that point).
double pathDistance(const std::array<float, 3>& p, const std::vector<std::array<double, 3>>& path) {
    double d = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < path.size(); ++k) {
        const std::array<double, 3>& a = path[k];
        const std::array<double, 3>& b = path[std::min(k + 1, path.size() - 1)];
        const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double q[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
        const double len2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        double t = len2 > 0 ? (q[0] * e[0] + q[1] * e[1] + q[2] * e[2]) / len2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        const double x = q[0] - t * e[0], y = q[1] - t * e[1], z = q[2] - t * e[2];
        d = std::min(d, std::sqrt(x * x + y * y + z * z));
    }
    return d;
}

} // namespace

double nearestTexelDistance(const StrokeSpec& stroke, const AtlasPositions& positions,
                            const Atlas* atlas) {
    double nearest = std::numeric_limits<double>::infinity();
    if (stroke.surfacePoints.empty())
        return nearest;
    for (std::uint32_t i = 0; i < positions.size(); ++i)
        if (!atlas || (i < atlas->cellCount() && atlas->used(i)))
            nearest = std::min(nearest, pathDistance(positions[i], stroke.surfacePoints));
    return nearest;
}

BrushRegion surfaceStrokeRegion(const StrokeSpec& stroke, const Domain& domain,
                                const AtlasPositions& positions) {
    const double r = stroke.radius, inner = r * (1.0 - stroke.falloff);
    const std::vector<std::array<double, 3>>& path = stroke.surfacePoints;
    std::vector<BrushRegion::Cell> cells;
    const Atlas* atlas = domain.atlasMap();
    for (std::uint32_t i = 0; i < positions.size() && i < std::uint32_t(domain.cellCount()); ++i) {
        if (atlas && !atlas->used(i))
            continue;
        const double d = pathDistance(positions[i], path);
        if (d > r)
            continue;
        const float weight = d <= inner ? 1.0f : float((r - d) / (r - inner));
        if (weight > 0.0f)
            cells.push_back({i, std::min(weight, 1.0f)});
    }
    return BrushRegion::fromCells(domain, std::move(cells));
}

BrushRegion strokeRegion(const StrokeSpec& stroke, const Domain& domain,
                         const AtlasPositions* positions) {
    if (stroke.surface) {
        if (!positions || positions->size() != std::size_t(domain.cellCount()))
            throw InputError("a stroke on a surface needs the session's mesh (its texel "
                             "positions): this run has none");
        return surfaceStrokeRegion(stroke, domain, *positions);
    }
    const int w = domain.width(), h = domain.height();
    // A stroke wider than the canvas covers it; bounding it keeps the loops finite.
    const double r = std::min(stroke.radius * w, double(std::max(w, h)) * 2.0);
    const double inner = r * (1.0 - stroke.falloff);
    const bool periodic = domain.edges() == EdgeMode::Periodic;
    std::unordered_map<std::uint32_t, float> weights;
    auto toCells = [&](const std::array<double, 2>& p) {
        // Cell centres sit at x + 0.5 of the canvas: fraction f is cell f * w - 0.5.
        return std::array<double, 2>{p[0] * w - 0.5, p[1] * h - 0.5};
    };
    const std::size_t n = stroke.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto a = toCells(stroke.points[i]);
        const auto b = toCells(stroke.points[std::min(i + 1, n - 1)]);
        if (i + 1 == n && n > 1)
            break; // the last point is the end of the segment before it
        const int x0 = int(std::ceil(std::min(a[0], b[0]) - r));
        const int x1 = int(std::floor(std::max(a[0], b[0]) + r));
        const int y0 = int(std::ceil(std::min(a[1], b[1]) - r));
        const int y1 = int(std::floor(std::max(a[1], b[1]) + r));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double d = segmentDistance(x, y, a[0], a[1], b[0], b[1]);
                if (d > r)
                    continue;
                const float weight = d <= inner ? 1.0f : float((r - d) / (r - inner));
                if (!(weight > 0.0f))
                    continue;
                int cx = x, cy = y;
                if (periodic) {
                    cx = floorMod(x, w);
                    cy = floorMod(y, h);
                } else if (x < 0 || x >= w || y < 0 || y >= h) {
                    continue;
                }
                float& slot = weights[std::uint32_t(cy) * std::uint32_t(w) + std::uint32_t(cx)];
                slot = std::max(slot, std::min(weight, 1.0f));
            }
    }
    std::vector<BrushRegion::Cell> cells;
    cells.reserve(weights.size());
    for (const auto& [index, weight] : weights)
        cells.push_back({index, weight});
    return BrushRegion::fromCells(domain, std::move(cells));
}

BrushRegion uncoveredPart(const BrushRegion& piece, StrokeCoverage& coverage,
                          const Domain& domain) {
    std::vector<BrushRegion::Cell> cells;
    for (const BrushRegion::Cell& c : piece.cells()) {
        float& covered = coverage[c.index];
        if (c.weight > covered) {
            cells.push_back({c.index, std::min(1.0f, c.weight - covered)});
            covered = c.weight;
        }
    }
    return BrushRegion::fromCells(domain, std::move(cells));
}

Brush strokeBrush(const StrokeSpec& stroke, const ReactionModel& model, const Domain& domain,
                  const AtlasPositions* positions) {
    Brush brush;
    brush.mode = stroke.mode;
    brush.value = stroke.value;
    brush.seed = stroke.seed;
    if (writesChemical(stroke.mode)) {
        brush.chemical = model.chemicalIndex(stroke.chemical);
        if (brush.chemical < 0)
            throw InputError("stroke chemical '" + stroke.chemical + "' is not a chemical of " +
                             "model '" + model.name() + "' (accepted: " + model.chemicalNames() +
                             ")");
    }
    if (stroke.mode == BrushMode::Paint) {
        if (!model.param(stroke.param))
            throw InputError("stroke parameter '" + stroke.param + "' is not a parameter of " +
                             "model '" + model.name() + "' (accepted: " + model.paramNames() + ")");
        brush.param = stroke.param;
    }
    brush.region = strokeRegion(stroke, domain, positions);
    return brush;
}

} // namespace morphogen
