#include "cli/bench_domains.hpp"
#include "cli/bench_timing.hpp"

#include <cstdio>
#include <functional>
#include <memory>

#include <nlohmann/json.hpp>

#include "core/domain/atlas.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
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
    for (const auto& [name, atlas] :
         std::vector<std::pair<std::string, std::shared_ptr<const Atlas>>>{
             {"cube", std::make_shared<const Atlas>(Atlas::cube(n))},
             {"rotated tiles", std::make_shared<const Atlas>(Atlas::rotatedTiles(n))}}) {
        Session onAtlas = loadPreset("gs_coral");
        useAtlas(onAtlas, atlas);
        Session grid = onAtlas;
        grid.atlas.reset();
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
                            {"fraction_of_grid", a / g}});
        }
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
    return {{"atlas", atlasRows(backends, seconds)}, {"sweep", sweepRows(backends, seconds)}};
}

} // namespace morphogen::cli
