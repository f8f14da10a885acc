#include "core/surface/surface_perturb.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/sim/localized_rd.hpp"

namespace morphogen {

SurfacePerturbation perturbSurface(const SurfaceTiles& tiles, const Domain& domain,
                                   const Eigen::Vector3f& centre, float radius, int chemical,
                                   float value, std::uint64_t seed, const char* what) {
    if (!centre.allFinite())
        throw InputError(std::string(what) + ": the centre must be finite");
    if (!(radius > 0) || !std::isfinite(radius))
        throw InputError(std::string(what) + ": radius " + std::to_string(radius) +
                         " is not accepted (a positive distance in mesh units)");
    const Atlas& atlas = *tiles.atlas;
    const float r2 = radius * radius;
    std::vector<BrushRegion::Cell> cells;
    Eigen::Vector3f lo = Eigen::Vector3f::Constant(INFINITY), hi = -lo;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!atlas.used(i))
            continue;
        const Eigen::Vector3f& p = tiles.texelPositions[i];
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
        if ((p - centre).squaredNorm() <= r2)
            cells.push_back({i, 1.0f});
    }
    if (cells.empty()) {
        std::ostringstream os;
        os << what << ": no texel of the surface lies within " << radius << " of (" << centre.x()
           << ", " << centre.y() << ", " << centre.z() << "); the mesh spans (" << lo.x() << ", "
           << lo.y() << ", " << lo.z() << ") to (" << hi.x() << ", " << hi.y() << ", " << hi.z()
           << ") in its own units";
        throw InputError(os.str());
    }
    SurfacePerturbation p;
    p.brush.mode = BrushMode::Randomise;
    p.brush.region = BrushRegion::fromCells(domain, std::move(cells));
    p.brush.chemical = chemical;
    p.brush.value = value;
    p.brush.seed = seed;
    p.touched = touchedTiles(atlas, p.brush.region);
    return p;
}

std::vector<Brush> erasingBrushes(const SurfacePerturbation& perturbation, const State& state,
                                  int chemicals) {
    std::vector<Brush> brushes;
    const std::vector<BrushRegion::Cell>& cells = perturbation.brush.region.cells();
    if (cells.empty())
        return brushes;
    for (int c = 0; c < std::min(chemicals, state.channels()); ++c) {
        const float* plane = state.plane(c);
        double sum = 0;
        for (const BrushRegion::Cell& cell : cells)
            sum += double(plane[cell.index]);
        Brush b;
        b.mode = BrushMode::Set;
        b.region = perturbation.brush.region;
        b.chemical = c;
        b.value = float(sum / double(cells.size()));
        brushes.push_back(std::move(b));
    }
    return brushes;
}

} // namespace morphogen
