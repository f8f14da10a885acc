#include "bench/bench_domains.hpp"
#include "bench/bench_backends.hpp"
#include "bench/bench_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/sim/brush.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/local_regrowth.hpp"
#include "core/sim/local_relax.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/sweep.hpp"
#include "core/surface/surface_perturb.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::bench {

namespace {

// Steps per second of run(batch), after a warm-up batch, for `seconds`.
double stepsPerSecond(const std::function<void(int)>& run, bool gpu, double seconds, int batch) {
    return measureStepsPerSecond(
        run,
        [gpu] {
            if (gpu)
                glFinish();
        },
        seconds, batch);
}

// Atlas texels per second over grid cells per second, same texture size.
nlohmann::json atlasRows(const std::vector<std::pair<std::string, Make>>& backends,
                         double seconds) {
    nlohmann::json rows = nlohmann::json::array();
    const int n = 128;
    std::printf("\n%-22s %-8s %-9s %14s %14s %10s\n", "atlas (tile 128)", "backend", "texture",
                "atlas texel/s", "grid cell/s", "fraction");
    const auto cube = std::make_shared<const Atlas>(Atlas::cube(n));
    const auto rotated = std::make_shared<const Atlas>(Atlas::rotatedTiles(n));
    // Weighted: per-texel weights (all 1; the cost does not depend on the values).
    const auto weightsOf = [](const Atlas& atlas) {
        return std::make_shared<const AtlasWeights>(uniformAtlasWeights(atlas));
    };
    struct Row {
        std::string name;
        std::shared_ptr<const Atlas> atlas;
        std::shared_ptr<const AtlasWeights> weights;
    };
    for (const Row& row :
         std::vector<Row>{{"cube", cube, nullptr},
                          {"rotated tiles", rotated, nullptr},
                          {"cube weighted", cube, weightsOf(*cube)},
                          {"rotated tiles weighted", rotated, weightsOf(*rotated)}}) {
        const std::string& name = row.name;
        const std::shared_ptr<const Atlas>& atlas = row.atlas;
        Session onAtlas = loadPreset("gs_coral");
        useAtlas(onAtlas, atlas, row.weights);
        Session grid = onAtlas;
        grid.atlas.reset();
        grid.atlasWeights.reset();
        std::size_t used = 0;
        for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
            used += atlas->used(i) ? 1 : 0;
        for (const auto& [backend, make] : backends) {
            const bool gpu = backend == "gpu";
            std::fprintf(stderr, "bench: %s atlas on the %s...\n", name.c_str(), backend.c_str());
            const double a = sessionStepsPerSecond(onAtlas, make, gpu, seconds) * double(used);
            const double g =
                sessionStepsPerSecond(grid, make, gpu, seconds) * double(grid.width * grid.height);
            std::printf("%-22s %-8s %4dx%-4d %14.3g %14.3g %10.3f\n", name.c_str(), backend.c_str(),
                        atlas->width(), atlas->height(), a, g, a / g);
            std::fflush(stdout);
            rows.push_back({{"atlas", name},
                            {"backend", backend},
                            {"tile", n},
                            {"texture", {atlas->width(), atlas->height()}},
                            {"atlas_texels_per_s", a},
                            {"grid_cells_per_s", g},
                            {"fraction_of_grid", a / g},
                            {"weighted", row.weights != nullptr}});
        }
    }
    return rows;
}

// --- Localized reaction-diffusion ---------------------------------------------------
//
// Re-equilibrium as relaxLocally has it (core/sim/local_relax.hpp): every 25
// steps, the largest change of any texel per step below 2e-5.

// One table of Lo's Table 1: `s` settled on each backend, then `stroke`
// (touching the tiles `touched`); time until settled again, globally and with
// the active set A1 = N(A0), A2, ... (growing every iterationsToCrossTile
// steps, global past 40% of the tiles).
nlohmann::json localizedTable(const std::string& label, const Session& s, const Atlas& atlas,
                              const Brush& stroke, const std::vector<int>& touched,
                              const std::vector<std::pair<std::string, Make>>& backends) {
    const TileNeighbourhoods neighbourhoods(atlas);
    const int growEvery = iterationsToCrossTile(StepConstants::fromSession(s));
    const RelaxOptions relax;
    nlohmann::json rows = nlohmann::json::array();
    auto shared = std::make_shared<const TileNeighbourhoods>(atlas);
    std::printf("\n%-22s %-8s %9s %9s %10s %9s %10s   %s\n", label.c_str(), "backend", "global s",
                "local s", "speed-up", "adapt s", "speed-up",
                "phases: it/s (tiles), A1 A2 A3 ... | adaptive");
    for (const auto& [backend, make] : backends) {
        const bool gpu = backend == "gpu";
        RelaxOptions options = relax;
        if (gpu)
            options.sync = [] { glFinish(); };
        std::fprintf(stderr, "bench: %s on the %s (settling first)...\n", label.c_str(),
                     backend.c_str());
        std::unique_ptr<Simulator> sim = make(s);
        sim->setState(initialState(s));
        relaxLocally(*sim, nullptr, atlas.tileCount(), options);
        const State settled = sim->state();
        sim->setState(settled);
        sim->applyBrush(stroke);
        const RelaxResult global = relaxLocally(*sim, nullptr, atlas.tileCount(), options);
        sim->setState(settled);
        sim->applyBrush(stroke);
        ActiveTileSchedule schedule(neighbourhoods, touched, growEvery, 0.4);
        const RelaxResult local = relaxLocally(*sim, &schedule, atlas.tileCount(), options);
        // The set grown where the change reaches its edge (core/sim/local_regrowth.hpp).
        sim->setState(settled);
        sim->applyBrush(stroke);
        LocalRegrowthOptions grow;
        grow.checkEvery = options.checkEvery;
        grow.settledBelow = options.settledBelow;
        LocalRegrowth regrowth(shared, s.domain().sharedAtlas(), touched, grow);
        const RelaxResult adaptive = relaxAdaptively(*sim, regrowth, options);
        const double tg = global.seconds, tl = local.seconds, ta = adaptive.seconds;
        std::printf("%-22s %-8s %9.3f %9.3f %10.2f %9.3f %10.2f  ", "", backend.c_str(), tg, tl,
                    tg / tl, ta, tg / ta);
        const auto phaseList = [](const RelaxResult& r) {
            nlohmann::json phases = nlohmann::json::array();
            for (const RelaxPhase& p : r.phases) {
                std::printf(" %.0f (%d)", p.iterationsPerSecond(), p.tiles);
                phases.push_back({{"tiles", p.tiles},
                                  {"iterations", p.iterations},
                                  {"iterations_per_s", p.iterationsPerSecond()}});
            }
            return phases;
        };
        const nlohmann::json phases = phaseList(local);
        std::printf(" |");
        const nlohmann::json adaptivePhases = phaseList(adaptive);
        std::printf("\n");
        std::fflush(stdout);
        rows.push_back({{"backend", backend},
                        {"tiles", atlas.tileCount()},
                        {"tile", atlas.tileSize()},
                        {"touched_tiles", touched.size()},
                        {"grow_every", growEvery},
                        {"settled_below_per_step", relax.settledBelow},
                        {"global_seconds", tg},
                        {"global_iterations", global.iterations},
                        {"global_iterations_per_s", global.iterations / tg},
                        {"localized_seconds", tl},
                        {"localized_iterations", local.iterations},
                        {"localized_settled", local.settled},
                        {"localized_phases", phases},
                        {"global_over_localized", tg / tl},
                        {"adaptive_seconds", ta},
                        {"adaptive_iterations", adaptive.iterations},
                        {"adaptive_settled", adaptive.settled},
                        {"adaptive_went_global", adaptive.global},
                        {"adaptive_phases", adaptivePhases},
                        {"global_over_adaptive", tg / ta}});
    }
    return rows;
}

// Lo's Table 1 on a 32 x 32 periodic plane of 8-texel tiles (1024 tiles):
// turk_small_spots, a randomising stroke (Lo's distort) of radius 6 texels
// at a tile corner.
nlohmann::json localizedRows(const std::vector<std::pair<std::string, Make>>& backends) {
    const int n = 8, side = 32;
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(n, side, side));
    Session s = loadPreset("turk_small_spots");
    useAtlas(s, atlas);
    Brush stroke;
    stroke.mode = BrushMode::Randomise;
    stroke.region =
        BrushRegion::disc(s.domain(), float(side / 2 * n) - 0.5f, float(side / 2 * n) - 0.5f, 6.0f);
    stroke.chemical = 0;
    stroke.value = 2.0f;
    stroke.seed = 3;
    return localizedTable("localized (1024 tiles)", s, *atlas, stroke,
                          touchedTiles(*atlas, stroke.region), backends);
}

// The same on a mesh atlas (Lo section 5.3): turk_small_spots on the sample
// blob at the automatic tile budget and tile size (render --mesh's defaults),
// weighted by the surface metric; the distort is a ball of 0.1 mesh units
// (a few texels) round the surface point nearest (1, 0, 0).
nlohmann::json meshLocalizedRows(const std::vector<std::pair<std::string, Make>>& backends) {
    Session s = loadPreset("turk_small_spots");
    s.surface.mesh = "sample:blob";
    std::fprintf(stderr, "bench: building the blob's tiles...\n");
    const SurfaceSetup setup = setUpSurface(s);
    s = segmentSessions(s).back(); // as it runs: dt split into the weighted atlas's substeps
    const Atlas& atlas = *setup.tiles.atlas;
    Eigen::Vector3f centre = Eigen::Vector3f::Zero();
    float best = INFINITY;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        if (atlas.used(i)) {
            const float d = (setup.tiles.texelPositions[i] - Eigen::Vector3f(1, 0, 0)).norm();
            if (d < best) {
                best = d;
                centre = setup.tiles.texelPositions[i];
            }
        }
    const SurfacePerturbation p = perturbSurface(setup.tiles, s.domain(), centre, 0.1f, 0, 2.0f, 3);
    return localizedTable("localized, blob (" + std::to_string(atlas.tileCount()) + " tiles)", s,
                          atlas, p.brush, p.touched, backends);
}

// A 4 x 4 gs_coral sweep of 64-cell tiles: one batched simulation against
// the 16 tiles stepped one after the other.
nlohmann::json sweepRows(const std::vector<std::pair<std::string, Make>>& backends,
                         double seconds) {
    SweepSpec spec;
    spec.base = loadPreset("gs_coral");
    spec.x = {"k", 0.05f, 0.065f};
    spec.y = {"F", 0.02f, 0.05f};
    spec.columns = spec.rows = 4;
    spec.tile = 64;
    spec.base.width = spec.base.height = spec.tile;
    const Session batched = batchedSession(spec);
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-22s %-8s %14s %14s %10s\n", "sweep 4x4 of 64^2", "backend", "batched it/s",
                "1-by-1 it/s", "ratio");
    for (const auto& [backend, make] : backends) {
        const bool gpu = backend == "gpu";
        std::fprintf(stderr, "bench: sweep batched vs one by one on the %s...\n", backend.c_str());
        const double together = sessionStepsPerSecond(batched, make, gpu, seconds);
        std::vector<std::unique_ptr<Simulator>> tiles;
        for (int row = 0; row < spec.rows; ++row)
            for (int column = 0; column < spec.columns; ++column) {
                const Session t = tileSession(batched, column, row);
                tiles.push_back(make(t));
                tiles.back()->setState(initialState(t));
            }
        const double apart = stepsPerSecond(
            [&](int n) {
                for (auto& t : tiles)
                    t->run(n);
            },
            gpu, seconds, 20);
        std::printf("%-22s %-8s %14.1f %14.1f %10.3f\n", "", backend.c_str(), together, apart,
                    together / apart);
        std::fflush(stdout);
        rows.push_back({{"backend", backend},
                        {"tiles", {spec.columns, spec.rows}},
                        {"tile", spec.tile},
                        {"batched_steps_per_s", together},
                        {"one_by_one_steps_per_s", apart},
                        {"batched_over_one_by_one", together / apart}});
    }
    return rows;
}

} // namespace

nlohmann::json benchDomains(bool gpu, bool cpu, double seconds) {
    const std::vector<std::pair<std::string, Make>> backends = simulatorBackends(gpu, cpu);
    return {{"atlas", atlasRows(backends, seconds)},
            {"localized", localizedRows(backends)},
            {"localized_mesh", meshLocalizedRows(backends)},
            {"sweep", sweepRows(backends, seconds)}};
}

} // namespace morphogen::bench
