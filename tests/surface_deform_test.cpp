// Deformation-aware reaction-diffusion (core/surface/surface_deform.hpp, Lo
// et al. section 5.5): a settled spot pattern on a sphere atlas, a slab of the
// sphere stretched 2x; the pattern re-grown with localized RD keeps its spots'
// size in world units (so there are about twice as many in the stretched
// region, and in texels each spot is smaller), and tiles far away keep their
// values bit for bit.

#include <cmath>
#include <set>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/simulator.hpp"
#include "core/surface/surface_deform.hpp"

using namespace morphogen;

namespace {

constexpr int kB = 1; // Turk's b

// Spots: the connected components (across tile edges) of texels on the
// minority side of chemical b's mean. Returns, per used texel, its
// component's id, or -1.
std::vector<int> spotComponents(const State& s, const Atlas& atlas, int& count) {
    double mean = 0;
    std::size_t used = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            mean += s.plane(kB)[i];
            ++used;
        }
    mean /= double(used);
    std::size_t above = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        above += atlas.used(i) && s.plane(kB)[i] > mean;
    const bool high = above * 2 < used;
    const auto inSpot = [&](std::uint32_t i) {
        return atlas.used(i) && ((s.plane(kB)[i] > mean) == high);
    };
    std::vector<int> id(atlas.cellCount(), -1);
    count = 0;
    std::vector<std::uint32_t> stack;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (!inSpot(i) || id[i] >= 0)
            continue;
        id[i] = count;
        stack.push_back(i);
        while (!stack.empty()) {
            const std::uint32_t c = stack.back();
            stack.pop_back();
            for (int d = 0; d < 4; ++d) {
                const std::uint32_t m = atlas.step(c, Direction(d)).cell;
                if (inSpot(m) && id[m] < 0) {
                    id[m] = count;
                    stack.push_back(m);
                }
            }
        }
        ++count;
    }
    return id;
}

// In a region of texels (a mask): spots per unit of world area and per
// texel, each spot counted by the fraction of its texels inside.
struct Density {
    double perWorldArea = 0, perTexel = 0, spots = 0;
};

Density spotDensity(const State& s, const SurfaceTiles& tiles, const std::vector<bool>& region) {
    const Atlas& atlas = *tiles.atlas;
    int count = 0;
    const std::vector<int> id = spotComponents(s, atlas, count);
    std::vector<double> size(std::size_t(count), 0), inside(std::size_t(count), 0);
    double area = 0, texels = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i) {
        if (id[i] >= 0) {
            size[std::size_t(id[i])] += 1;
            inside[std::size_t(id[i])] += region[i] ? 1 : 0;
        }
        if (region[i]) {
            area += tiles.texelArea[i];
            texels += 1;
        }
    }
    Density d;
    for (int k = 0; k < count; ++k)
        d.spots += inside[std::size_t(k)] / size[std::size_t(k)];
    d.perWorldArea = d.spots / area;
    d.perTexel = d.spots / texels;
    return d;
}

} // namespace

TEST(SurfaceDeform, StretchedSpotsKeepTheirWorldSize) {
    // turk_small_spots on the unit sphere, 480 tiles of 8 x 8 texels, length 120.
    Session session = loadPreset("turk_small_spots");
    session.length = 120;
    session.surface.mesh = "sample:sphere";
    session.surface.tiles = 480;
    session.surface.tileSize = 8;
    SurfaceSetup setup = setUpSurface(session);
    RelaxOptions relax;
    relax.settledBelow = 1e-4f; // as in local_relax_test: 2e-5 takes too long for a unit test
    relax.maxSteps = 60000;     // measured: the stretched band re-settles after some 40,000
    const Atlas& atlas = *setup.tiles.atlas;
    const SimulatorFactory make = [](const Session& s) {
        return std::make_unique<CpuSimulator>(s);
    };
    State settled;
    {
        const Session running = segmentSessions(session).back(); // dt split into substeps
        std::unique_ptr<Simulator> sim = make(running);
        sim->setState(initialState(running));
        sim->run(running.steps); // the pattern first: the start's noise changes slowly
        const RelaxResult r = relaxLocally(*sim, nullptr, atlas.tileCount(), relax);
        ASSERT_TRUE(r.settled) << r.iterations;
        settled = sim->state();
    }
    SlabStretch stretch;
    stretch.centre = Eigen::Vector3f(0, 0, 0.75f);
    stretch.radius = 0.1f;
    stretch.direction = Eigen::Vector3f::UnitZ();
    stretch.factor = 2;
    // The region measured: texels well inside the slab (|t| < 0.08), taken before.
    std::vector<bool> region(atlas.cellCount(), false);
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        region[i] = atlas.used(i) && std::fabs(setup.tiles.texelPositions[i].z() - 0.75f) < 0.08f;
    const Density before = spotDensity(settled, setup.tiles, region);

    SurfaceWeightOptions options;
    options.unitsPerWorld = setup.unitsPerWorld;
    const SurfaceTiles original = setup.tiles;
    // The set held at A1 = N(A0) (growth beyond the run's steps): on this small sphere,
    // Lo's schedule (m = iterationsToCrossTile) and even one 40 times slower pass 40% of
    // the tiles long before the stretched spots have re-formed (some 35,000 steps), and go
    // global; a fixed set shows what stays untouched.
    const int growEvery = relax.maxSteps + 1;
    const DeformResult r =
        deformAndRegrow(session, setup, options, stretch, make, settled, relax, growEvery);
    ASSERT_TRUE(r.relax.settled) << r.relax.iterations;
    // Stretched as the pattern was (no re-growth): half the spots per area.
    const Density stretchedOnly = spotDensity(settled, setup.tiles, region);
    const Density after = spotDensity(r.state, setup.tiles, region);
    std::printf("spots in the region: before %.1f (%.4f per area, %.5f per texel); stretched "
                "%.4f per area; re-grown %.1f (%.4f per area, %.5f per texel); %zu tiles "
                "deformed, %d steps in %zu phases, %s\n",
                before.spots, before.perWorldArea, before.perTexel, stretchedOnly.perWorldArea,
                after.spots, after.perWorldArea, after.perTexel, r.deformed.size(),
                r.relax.iterations, r.relax.phases.size(), r.relax.global ? "global" : "local");
    ASSERT_GT(before.spots, 8) << "too few spots to measure";
    // The band's meridians stretch by about 1.5 (the sphere's tangent there is tilted from
    // z), so the stretched pattern has some 2/3 of the spots per area (measured 0.66).
    EXPECT_LT(stretchedOnly.perWorldArea / before.perWorldArea, 0.75);
    // World size kept: spots per world area within 20% of before, against 0.66 for the
    // stretched pattern. The region holds some 20-24 spots, so the ratio is noisy: on the
    // tiles of issue #11 (docs/tile_quality.md) seeds 1, 2, 3 measured 1.19, 1.15 and 0.97
    // (the same re-grown density as before those tiles, 25.4 against 25.3 per area at
    // seed 1; the settled pattern's count in the region differs by a spot or two); the
    // tiles before measured 1.10 at seed 1.
    EXPECT_NEAR(after.perWorldArea / before.perWorldArea, 1.0, 0.2);
    // So in texels each spot is smaller: about 1.5x the spots per texel (measured 1.53).
    EXPECT_GT(after.perTexel / before.perTexel, 1.3);

    // Tiles outside the slab translate: same Jacobians; tiles the run never
    // stepped keep their values bit for bit.
    const std::set<int> deformed(r.deformed.begin(), r.deformed.end());
    const std::set<int> stepped(r.relax.finalTiles.begin(), r.relax.finalTiles.end());
    int untouched = 0;
    for (int t = 0; t < atlas.tileCount(); ++t) {
        const std::uint32_t c = atlas.tileCell(t, 2, 2);
        if (!deformed.count(t))
            EXPECT_LT((setup.tiles.jacobianU[c] - original.jacobianU[c]).norm(),
                      1e-5f * original.jacobianU[c].norm() + 1e-6f);
        if (r.relax.global || stepped.count(t))
            continue;
        ++untouched;
        for (int ch = 0; ch < settled.channels(); ++ch)
            for (int v = 0; v < atlas.tileSize(); ++v)
                for (int u = 0; u < atlas.tileSize(); ++u) {
                    const std::uint32_t i = atlas.tileCell(t, u, v);
                    ASSERT_EQ(r.state.plane(ch)[i], settled.plane(ch)[i]) << "tile " << t;
                }
    }
    EXPECT_FALSE(r.relax.global);
    EXPECT_GT(untouched, atlas.tileCount() / 3);
    EXPECT_GT(setup.tiles.surfaceArea, original.surfaceArea * 1.03);
}

TEST(SurfaceDeform, ALocalStretchActsUnderItAndNeverFolds) {
    // The unit sphere, 480 tiles of 8 x 8; stretched along x round the pole
    // (0, 0, 1), within `reach` of the x axis through it.
    Session session = loadPreset("turk_small_spots");
    session.surface.mesh = "sample:sphere";
    session.surface.tiles = 480;
    session.surface.tileSize = 8;
    const SurfaceSetup setup = setUpSurface(session);
    const Atlas& atlas = *setup.tiles.atlas;
    const Eigen::Vector3f pole(0, 0, 1);
    const auto rho = [&](const Eigen::Vector3f& p) {
        const Eigen::Vector3f q = p - pole;
        return std::hypot(q.y(), q.z());
    };
    for (const float factor : {2.0f, 0.25f, 1.5f}) {
        SurfaceTiles tiles = setup.tiles;
        TriangleMesh full = setup.mesh.mesh;
        SlabStretch s;
        s.centre = pole;
        s.direction = Eigen::Vector3f::UnitX();
        s.radius = 0.2f;
        s.reach = 0.15f;
        s.factor = factor;
        const std::vector<int> deformed = stretchSurface(tiles, full, s);
        const std::set<int> changed(deformed.begin(), deformed.end());
        ASSERT_FALSE(deformed.empty());
        double centreRatio = 0;
        int centreTexels = 0;
        for (int t = 0; t < atlas.tileCount(); ++t)
            for (int v = 0; v < atlas.tileSize(); ++v)
                for (int u = 0; u < atlas.tileSize(); ++u) {
                    const std::uint32_t c = atlas.tileCell(t, u, v);
                    const Eigen::Vector3f& p = setup.tiles.texelPositions[c];
                    // Beyond the fade nothing moves, bit for bit.
                    if (rho(p) >= s.reach + s.fadeWidth()) {
                        ASSERT_EQ(tiles.texelPositions[c], p) << factor;
                        ASSERT_EQ(tiles.texelNormals[c], setup.tiles.texelNormals[c]) << factor;
                    }
                    // Never folds: each texel's parallelogram faces the way the
                    // map carries the normal (J^-T n, with det J = 1 + (factor - 1)
                    // w > 0), though a sheared texel may turn far from where it faced.
                    const Eigen::Vector3f n1 = tiles.jacobianU[c].cross(tiles.jacobianV[c]);
                    ASSERT_GT(n1.normalized().dot(tiles.texelNormals[c]), 0.5f)
                        << "texel " << c << " folded at x" << factor;
                    ASSERT_GT(tiles.texelArea[c], 0.0f);
                    ASSERT_NEAR(tiles.texelNormals[c].norm(), 1.0f, 1e-5f);
                    if (!changed.count(t))
                        ASSERT_EQ(tiles.jacobianU[c], setup.tiles.jacobianU[c]);
                    // Under the brush: stretched by the factor along x (the
                    // sphere's tangent plane at the pole), so the area too.
                    if (rho(p) < 0.5f * s.reach && std::fabs(p.x()) < 0.5f * s.radius) {
                        centreRatio += tiles.texelArea[c] / setup.tiles.texelArea[c];
                        ++centreTexels;
                    }
                }
        ASSERT_GT(centreTexels, 4);
        centreRatio /= centreTexels;
        std::printf("x%.2f: fade %.2f, %zu tiles deformed of %d, texel area under the brush "
                    "x%.3f (%d)\n",
                    factor, s.fadeWidth(), deformed.size(), atlas.tileCount(), centreRatio,
                    centreTexels);
        EXPECT_NEAR(centreRatio, factor, 0.05 * factor);
        // The slab across the model (a band round the whole sphere) changes more
        // tiles than the local stretch (measured 152 against 100, 76 and 54).
        SurfaceTiles acrossTiles = setup.tiles;
        TriangleMesh acrossMesh = setup.mesh.mesh;
        s.reach = 0;
        EXPECT_GT(stretchSurface(acrossTiles, acrossMesh, s).size(), deformed.size());
    }
}

TEST(SurfaceDeform, RefusesBadStretches) {
    TriangleMesh mesh;
    SurfaceTiles tiles;
    SlabStretch s;
    s.factor = 0;
    EXPECT_THROW(stretchSurface(tiles, mesh, s), InputError);
    s.factor = 2;
    s.radius = -1;
    EXPECT_THROW(stretchSurface(tiles, mesh, s), InputError);
    s.radius = 1;
    s.direction = Eigen::Vector3f::Zero();
    EXPECT_THROW(stretchSurface(tiles, mesh, s), InputError);
    s.direction = Eigen::Vector3f::UnitX();
    s.reach = -0.5f;
    EXPECT_THROW(stretchSurface(tiles, mesh, s), InputError);
    s.reach = std::nanf("");
    EXPECT_THROW(stretchSurface(tiles, mesh, s), InputError);
}
