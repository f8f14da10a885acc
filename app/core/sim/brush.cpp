#include "core/sim/brush.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/base/errors.hpp"
#include "core/base/names.hpp"
#include "core/base/random.hpp"
#include "core/session/param_map.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

namespace {

// Stream of brushNoise in random.hpp's counter scheme (initial conditions use others).
constexpr std::uint64_t kBrushNoiseStream = 0x6272757368ull; // "brush"

int floorMod(int i, int n) {
    const int m = i % n;
    return m < 0 ? m + n : m;
}

// The pieces of the unwrapped interval [lo, hi] on an axis of n cells:
// periodic edges wrap it (two pieces where it crosses the edge), clamped
// edges cut it (none where it misses the grid). Pieces are {first, count}.
std::vector<std::array<int, 2>> axisPieces(int lo, int hi, int n, EdgeMode edges) {
    if (edges == EdgeMode::Clamped) {
        lo = std::max(lo, 0);
        hi = std::min(hi, n - 1);
        if (lo > hi)
            return {};
        return {{lo, hi - lo + 1}};
    }
    if (hi - lo + 1 >= n)
        return {{0, n}};
    const int a = floorMod(lo, n), b = floorMod(hi, n);
    if (a <= b)
        return {{a, b - a + 1}};
    return {{a, n - a}, {0, b + 1}};
}

} // namespace

BrushRegion BrushRegion::disc(const Domain& domain, float centreX, float centreY, float radius,
                              float falloff) {
    if (!std::isfinite(centreX) || !std::isfinite(centreY))
        throw InputError("brush centre must be finite");
    if (!(radius >= 0.0f) || !std::isfinite(radius))
        throw InputError("brush radius " + std::to_string(radius) +
                         " is not accepted (a finite radius >= 0, in cells)");
    if (!(falloff >= 0.0f && falloff <= 1.0f))
        throw InputError("brush falloff " + std::to_string(falloff) +
                         " is not accepted (0 to 1: the fraction of the radius that ramps down)");
    const int w = domain.width(), h = domain.height();
    // A disc larger than the grid covers it; bounding it keeps the loops finite.
    const float r = std::min(radius, float(std::max(w, h)) * 2.0f);
    const int x0 = int(std::ceil(centreX - r)), x1 = int(std::floor(centreX + r));
    const int y0 = int(std::ceil(centreY - r)), y1 = int(std::floor(centreY + r));
    const float inner = r * (1.0f - falloff);

    BrushRegion region;
    region.m_gridWidth = w;
    region.m_gridHeight = h;
    // Indexed by cell: a periodic disc wider than the grid reaches a cell
    // more than once, and the nearest copy wins.
    std::vector<std::pair<std::uint32_t, float>> hits;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float dx = float(x) - centreX, dy = float(y) - centreY;
            const float d = std::sqrt(dx * dx + dy * dy);
            if (d > r)
                continue;
            const float weight = d <= inner ? 1.0f : (r - d) / (r - inner);
            if (!(weight > 0.0f))
                continue;
            int cx = x, cy = y;
            if (domain.edges() == EdgeMode::Periodic) {
                cx = floorMod(x, w);
                cy = floorMod(y, h);
            } else if (x < 0 || x >= w || y < 0 || y >= h) {
                continue;
            }
            hits.push_back({std::uint32_t(cy) * std::uint32_t(w) + std::uint32_t(cx), weight});
        }
    std::sort(hits.begin(), hits.end());
    for (const auto& [index, weight] : hits) {
        if (!region.m_cells.empty() && region.m_cells.back().index == index)
            region.m_cells.back().weight = std::max(region.m_cells.back().weight, weight);
        else
            region.m_cells.push_back({index, weight});
    }
    if (region.m_cells.empty())
        return region;
    for (const auto& [ry, rh] : axisPieces(y0, y1, h, domain.edges()))
        for (const auto& [rx, rw] : axisPieces(x0, x1, w, domain.edges()))
            region.m_rects.push_back({rx, ry, rw, rh});
    return region;
}

BrushRegion BrushRegion::fromCells(const Domain& domain, std::vector<Cell> cells) {
    const std::uint32_t n = std::uint32_t(domain.cellCount());
    std::sort(cells.begin(), cells.end(),
              [](const Cell& a, const Cell& b) { return a.index < b.index; });
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (cells[i].index >= n)
            throw InputError("brush cell " + std::to_string(cells[i].index) +
                             " is outside the grid of " + std::to_string(n) + " cells");
        if (!(cells[i].weight > 0.0f && cells[i].weight <= 1.0f))
            throw InputError("brush cell weight " + std::to_string(cells[i].weight) +
                             " is not accepted (0 < weight <= 1)");
        if (i > 0 && cells[i].index == cells[i - 1].index)
            throw InputError("brush cell " + std::to_string(cells[i].index) + " is listed twice");
    }
    BrushRegion region;
    region.m_gridWidth = domain.width();
    region.m_gridHeight = domain.height();
    region.m_cells = std::move(cells);
    if (region.m_cells.empty())
        return region;
    const int w = domain.width();
    int x0 = w, x1 = -1, y0 = domain.height(), y1 = -1;
    for (const Cell& c : region.m_cells) {
        const int x = int(c.index % std::uint32_t(w)), y = int(c.index / std::uint32_t(w));
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
    }
    region.m_rects.push_back({x0, y0, x1 - x0 + 1, y1 - y0 + 1});
    return region;
}

void checkBrush(const Brush& brush, const ReactionModel& model, const Domain& domain) {
    const BrushRegion& region = brush.region;
    if (!region.empty() &&
        (region.gridWidth() != domain.width() || region.gridHeight() != domain.height()))
        throw InputError("brush region was made for a " + std::to_string(region.gridWidth()) +
                         " x " + std::to_string(region.gridHeight()) + " grid, not " +
                         std::to_string(domain.width()) + " x " + std::to_string(domain.height()));
    if (!std::isfinite(brush.value))
        throw InputError("brush value must be finite (got " + std::to_string(brush.value) + ")");
    switch (brush.mode) {
    case BrushMode::Add:
    case BrushMode::Remove:
    case BrushMode::Set:
    case BrushMode::Randomise:
        if (brush.chemical < 0 || brush.chemical >= int(model.chemicals().size()))
            throw InputError("brush chemical " + std::to_string(brush.chemical) +
                             " is not one of " + model.name() + "'s chemicals (0 to " +
                             std::to_string(model.chemicals().size() - 1) + ": " +
                             model.chemicalNames() + ")");
        break;
    case BrushMode::Paint: {
        const ParamSpec* p = model.param(brush.param);
        if (!p)
            throw InputError("brush parameter '" + brush.param + "' is not a parameter of " +
                             model.name() + " (accepted: " + model.paramNames() + ")" +
                             didYouMean(brush.param, splitNameList(model.paramNames())));
        if (brush.value < p->min || brush.value > p->max)
            throw InputError("brush value " + std::to_string(brush.value) + " for '" + brush.param +
                             "' is outside its range [" + std::to_string(p->min) + ", " +
                             std::to_string(p->max) + "]");
        break;
    }
    case BrushMode::Hold:
    case BrushMode::Release:
        break;
    }
}

float brushNoise(std::uint64_t seed, std::uint32_t cell) {
    return float(uniformSigned(seed, kBrushNoiseStream, cell));
}

float brushChemical(BrushMode mode, float c, float weight, float value, float noise, float lo,
                    float hi) {
    float out = c;
    switch (mode) {
    case BrushMode::Add:
        out = c + value * weight;
        break;
    case BrushMode::Remove:
        out = c - value * weight;
        break;
    case BrushMode::Set:
        out = blend(c, value, weight);
        break;
    case BrushMode::Randomise:
        out = c + value * weight * noise;
        break;
    default:
        break;
    }
    return std::clamp(out, lo, hi);
}

int mappedIndex(const StepConstants& k, const ReactionModel& model, const std::string& name) {
    for (std::size_t m = 0; m < k.mappedParams.size(); ++m)
        if (model.params()[std::size_t(k.mappedParams[m])].name == name)
            return int(m);
    return -1;
}

StepConstants withParamMap(Session& session, const StepConstants& k, const std::string& name) {
    const ReactionModel& model = session.reactionModel();
    Session updated = session;
    for (std::size_t p = 0; p < model.params().size(); ++p)
        updated.params[model.params()[p].name] = k.params[p];
    ParamMapSpec constant;
    constant.field = ParamMapSpec::Field::LinearX;
    constant.min = constant.max = updated.params.at(name);
    updated.paramMaps[name] = constant;
    StepConstants next = StepConstants::fromSession(updated); // throws where it cannot run
    next.dt = k.dt;
    for (std::size_t m = 0; m < k.mappedParams.size(); ++m) {
        const int to =
            mappedIndex(next, model, model.params()[std::size_t(k.mappedParams[m])].name);
        std::copy(k.paramMaps.plane(int(m)), k.paramMaps.plane(int(m)) + k.paramMaps.cellCount(),
                  next.paramMaps.plane(to));
    }
    session = std::move(updated);
    return next;
}

} // namespace morphogen
