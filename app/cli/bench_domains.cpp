#include "cli/bench_domains.hpp"
#include "cli/bench_timing.hpp"

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
#include "core/sim/localized_rd.hpp"
#include "core/sim/sweep.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::cli {

namespace {

using Make = std::function<std::unique_ptr<Simulator>(const Session&)>;

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

double sessionStepsPerSecond(const Session& s, const Make& make, bool gpu, double seconds) {
    std::unique_ptr<Simulator> sim = make(s);
    sim->setState(initialState(s));
    return stepsPerSecond([&](int n) { sim->run(n); }, gpu, seconds, 20);
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
// Re-equilibrium: checked every kCheckEvery steps, the largest change of any
// texel of any chemical since the previous check, per step, below kSettled.
// (A settled Turing pattern drifts by far less; a pattern still re-forming
// after a perturbation changes by 1e-3 or more per step.)
constexpr int kCheckEvery = 25;
constexpr float kSettled = 2e-5f;
constexpr int kMaxSettleSteps = 40000;

using Clock = std::chrono::steady_clock;

float maxChangePerStep(const State& a, const State& b, int steps) {
    float worst = 0;
    for (int c = 0; c < a.channels(); ++c)
        for (std::size_t i = 0; i < a.cellCount(); ++i)
            worst = std::max(worst, std::fabs(a.plane(c)[i] - b.plane(c)[i]));
    return worst / float(steps);
}

struct Phase {
    int tiles = 0; // 0: global
    int iterations = 0;
    double seconds = 0;
};

// Runs until settled, the active set following `schedule` (null: global
// throughout); returns the phases (one per active set) and the total seconds.
std::vector<Phase> runToEquilibrium(Simulator& sim, ActiveTileSchedule* schedule, bool gpu,
                                    int tileCount) {
    std::vector<Phase> phases;
    State previous = sim.state();
    int total = 0;
    int sinceCheck = 0;
    bool settled = false;
    while (!settled && total < kMaxSettleSteps) {
        const bool global = !schedule || schedule->global();
        const int tiles = global ? tileCount : int(schedule->tiles().size());
        if (phases.empty() || phases.back().tiles != tiles) {
            phases.push_back({tiles, 0, 0});
            sim.setActiveTiles(global ? std::vector<int>{} : schedule->tiles());
        }
        int n = kCheckEvery - sinceCheck;
        if (!global)
            n = std::min(n, schedule->iterationsLeft());
        const auto start = Clock::now();
        sim.run(n);
        sinceCheck += n;
        if (sinceCheck == kCheckEvery) {
            const State now = sim.state(); // waits for the GPU
            settled = maxChangePerStep(now, previous, kCheckEvery) < kSettled;
            previous = now;
            sinceCheck = 0;
        } else if (gpu) {
            glFinish();
        }
        phases.back().seconds += std::chrono::duration<double>(Clock::now() - start).count();
        phases.back().iterations += n;
        total += n;
        if (schedule)
            schedule->advance(n);
    }
    return phases;
}

// Lo's Table 1 on a 32 x 32 periodic plane of 8-texel tiles (1024 tiles):
// turk_small_spots settled, then a randomising stroke (Lo's distort) of
// radius 6 texels at a tile corner; time until settled again, globally and
// with the active set A1 = N(A0), A2, ... (growing every
// iterationsToCrossTile steps, global past 40% of the tiles).
nlohmann::json localizedRows(const std::vector<std::pair<std::string, Make>>& backends) {
    const int n = 8, side = 32;
    auto atlas = std::make_shared<const Atlas>(Atlas::periodicPlane(n, side, side));
    const TileNeighbourhoods neighbourhoods(*atlas);
    Session s = loadPreset("turk_small_spots");
    useAtlas(s, atlas);
    Brush stroke;
    stroke.mode = BrushMode::Randomise;
    stroke.region =
        BrushRegion::disc(s.domain(), float(side / 2 * n) - 0.5f, float(side / 2 * n) - 0.5f, 6.0f);
    stroke.chemical = 0;
    stroke.value = 2.0f;
    stroke.seed = 3;
    const std::vector<int> touched = touchedTiles(*atlas, stroke.region);
    const int growEvery = iterationsToCrossTile(StepConstants::fromSession(s));
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-22s %-8s %9s %9s %10s   %s\n", "localized (1024 tiles)", "backend", "global s",
                "local s", "speed-up", "phases: it/s (tiles), A1 A2 A3 ...");
    for (const auto& [backend, make] : backends) {
        const bool gpu = backend == "gpu";
        std::fprintf(stderr, "bench: localized RD on the %s (settling first)...\n",
                     backend.c_str());
        std::unique_ptr<Simulator> sim = make(s);
        sim->setState(initialState(s));
        runToEquilibrium(*sim, nullptr, gpu, atlas->tileCount());
        const State settled = sim->state();
        const auto timeOf = [](const std::vector<Phase>& phases) {
            double t = 0;
            for (const Phase& p : phases)
                t += p.seconds;
            return t;
        };
        sim->setState(settled);
        sim->applyBrush(stroke);
        const std::vector<Phase> global = runToEquilibrium(*sim, nullptr, gpu, atlas->tileCount());
        sim->setState(settled);
        sim->applyBrush(stroke);
        ActiveTileSchedule schedule(neighbourhoods, touched, growEvery, 0.4);
        const std::vector<Phase> local = runToEquilibrium(*sim, &schedule, gpu, atlas->tileCount());
        const double tg = timeOf(global), tl = timeOf(local);
        std::printf("%-22s %-8s %9.3f %9.3f %10.2f  ", "", backend.c_str(), tg, tl, tg / tl);
        nlohmann::json phases = nlohmann::json::array();
        for (const Phase& p : local) {
            std::printf(" %.0f (%d)", p.iterations / p.seconds, p.tiles);
            phases.push_back({{"tiles", p.tiles},
                              {"iterations", p.iterations},
                              {"iterations_per_s", p.iterations / p.seconds}});
        }
        std::printf("\n");
        std::fflush(stdout);
        int globalIterations = 0;
        for (const Phase& p : global)
            globalIterations += p.iterations;
        rows.push_back({{"backend", backend},
                        {"tiles", atlas->tileCount()},
                        {"tile", n},
                        {"touched_tiles", touched.size()},
                        {"grow_every", growEvery},
                        {"settled_below_per_step", kSettled},
                        {"global_seconds", tg},
                        {"global_iterations", globalIterations},
                        {"global_iterations_per_s", globalIterations / tg},
                        {"localized_seconds", tl},
                        {"localized_phases", phases},
                        {"global_over_localized", tg / tl}});
    }
    return rows;
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
    std::vector<std::pair<std::string, Make>> backends;
    if (gpu)
        backends.emplace_back(
            "gpu", [](const Session& s) { return std::make_unique<gl::GpuSimulator>(s); });
    if (cpu)
        backends.emplace_back("cpu",
                              [](const Session& s) { return std::make_unique<CpuSimulator>(s); });
    return {{"atlas", atlasRows(backends, seconds)},
            {"localized", localizedRows(backends)},
            {"sweep", sweepRows(backends, seconds)}};
}

} // namespace morphogen::cli
