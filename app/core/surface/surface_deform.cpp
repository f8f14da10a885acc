#include "core/surface/surface_deform.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/base/errors.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen {

float SlabStretch::fadeWidth() const {
    return std::max(reach, 1.5f * std::fabs(factor - 1.0f) * radius);
}

SlabStretch::Fade SlabStretch::fade(const Eigen::Vector3f& p) const {
    Fade f;
    if (!(reach > 0))
        return f;
    const Eigen::Vector3f q = p - centre;
    const Eigen::Vector3f across = q - q.dot(direction) * direction;
    const float rho = across.norm();
    const float width = fadeWidth();
    const float x = std::clamp((rho - reach) / width, 0.0f, 1.0f);
    f.w = 1.0f - x * x * (3.0f - 2.0f * x);
    f.slope = -6.0f * x * (1.0f - x) / width;
    if (rho > 0)
        f.away = across / rho;
    return f;
}

Eigen::Vector3f SlabStretch::apply(const Eigen::Vector3f& p) const {
    const float t = (p - centre).dot(direction);
    const float clamped = std::clamp(t, -radius, radius);
    // Inside: t grows by (factor - 1) t; outside: by the rim's (factor - 1) (+-radius).
    return p + (factor - 1.0f) * clamped * fade(p).w * direction;
}

SlabStretch::Moved SlabStretch::move(const Eigen::Vector3f& p, const Eigen::Vector3f& n) const {
    const float t = (p - centre).dot(direction);
    const float clamped = std::clamp(t, -radius, radius);
    const bool inSlab = std::fabs(t) < radius;
    const Fade f = fade(p);
    Moved m;
    m.position = p + (factor - 1.0f) * clamped * f.w * direction;
    m.deforms = f.w > 0 && (inSlab || (f.slope != 0 && t != 0));
    // grad g = (factor - 1) (w d [inside] + clamp(t) w' away); J = I + d grad(g)^T,
    // J^-T n = n - grad(g) (d . n) / (1 + d . grad(g)).
    const Eigen::Vector3f grad =
        (factor - 1.0f) * ((inSlab ? f.w : 0.0f) * direction + clamped * f.slope * f.away);
    m.normal =
        grad.squaredNorm() == 0
            ? n
            : Eigen::Vector3f(
                  (n - grad * (direction.dot(n) / (1.0f + direction.dot(grad)))).normalized());
    return m;
}

std::vector<int> stretchSurface(SurfaceTiles& tiles, TriangleMesh& full,
                                const SlabStretch& stretchIn) {
    SlabStretch s = stretchIn;
    if (!s.centre.allFinite())
        throw InputError("stretch: the centre must be finite");
    if (!(s.radius > 0) || !std::isfinite(s.radius))
        throw InputError("stretch: radius " + std::to_string(s.radius) +
                         " is not accepted (a positive distance in mesh units)");
    if (!(s.factor > 0) || !std::isfinite(s.factor))
        throw InputError("stretch: factor " + std::to_string(s.factor) +
                         " is not accepted (a positive number; 1 leaves the surface as it is)");
    if (!(s.reach >= 0) || !std::isfinite(s.reach))
        throw InputError("stretch: reach " + std::to_string(s.reach) +
                         " is not accepted (a distance in mesh units from the stretch's axis; "
                         "0 stretches the whole slab across the model)");
    if (!s.direction.allFinite() || !(s.direction.norm() > 0))
        throw InputError("stretch: the direction must be a finite non-zero vector");
    s.direction.normalize();
    for (auto& p : full.positions)
        p = s.apply(p);
    for (auto& p : tiles.simplified.positions)
        p = s.apply(p);
    for (auto& p : tiles.quadVertices)
        p = s.apply(p);

    const Atlas& atlas = *tiles.atlas;
    const int n = atlas.tileSize();
    const std::size_t corners = std::size_t(n + 1) * std::size_t(n + 1);
    std::vector<int> deformed;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        Eigen::Vector3f* grid = tiles.gridPositions.data() + std::size_t(t) * corners;
        Eigen::Vector3f* gridN = tiles.gridNormals.data() + std::size_t(t) * corners;
        bool changed = false;
        for (std::size_t i = 0; i < corners; ++i) {
            const SlabStretch::Moved m = s.move(grid[i], gridN[i]);
            changed = changed || m.deforms;
            gridN[i] = m.normal;
            grid[i] = m.position;
        }
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const std::uint32_t c = atlas.tileCell(t, u, v);
                const Eigen::Vector3f& c00 = grid[v * (n + 1) + u];
                const Eigen::Vector3f& c10 = grid[v * (n + 1) + u + 1];
                const Eigen::Vector3f& c01 = grid[(v + 1) * (n + 1) + u];
                const Eigen::Vector3f& c11 = grid[(v + 1) * (n + 1) + u + 1];
                const SlabStretch::Moved m = s.move(tiles.texelPositions[c], tiles.texelNormals[c]);
                tiles.texelNormals[c] = m.normal;
                tiles.texelPositions[c] = m.position;
                if (changed) {
                    // As computeSurfaceGeometry: central differences of the corners.
                    const Eigen::Vector3f ju = 0.5f * ((c10 - c00) + (c11 - c01));
                    const Eigen::Vector3f jv = 0.5f * ((c01 - c00) + (c11 - c10));
                    tiles.jacobianU[c] = ju;
                    tiles.jacobianV[c] = jv;
                    tiles.texelArea[c] = ju.cross(jv).norm();
                }
            }
        if (changed)
            deformed.push_back(t);
    }
    tiles.surfaceArea = surfaceArea(full);
    return deformed;
}

DeformResult deformAndRegrow(Session& session, SurfaceSetup& setup,
                             const SurfaceWeightOptions& options, const SlabStretch& stretch,
                             const SimulatorFactory& make, const State& state,
                             const RelaxOptions& relax, int growEvery) {
    DeformResult result;
    result.deformed = stretchSurface(setup.tiles, setup.mesh.mesh, stretch);
    setup.weights = std::make_shared<const AtlasWeights>(surfaceWeights(setup.tiles, options));
    useAtlas(session, setup.tiles.atlas, setup.weights);
    const Atlas& atlas = *setup.tiles.atlas;
    // As it runs: dt split into the new weights' substeps.
    const Session running = segmentSessions(session).back();
    std::unique_ptr<Simulator> sim = make(running);
    sim->setState(state);
    const TileNeighbourhoods neighbourhoods(atlas);
    ActiveTileSchedule schedule(
        neighbourhoods, result.deformed,
        growEvery > 0 ? growEvery : iterationsToCrossTile(StepConstants::fromSession(running)));
    result.relax = relaxLocally(*sim, &schedule, atlas.tileCount(), relax);
    result.state = sim->takeState();
    return result;
}

} // namespace morphogen
