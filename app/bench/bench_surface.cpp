#include "bench/bench_surface.hpp"
#include "bench/bench_backends.hpp"
#include "bench/bench_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <unistd.h>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/domain/atlas_diagonals.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/session/session.hpp"
#include "core/sim/cpu_kernels.hpp"
#include "core/sim/cpu_padded_atlas.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/segments.hpp"
#include "core/sim/vector_clones.hpp"
#include "core/surface/surface_setup.hpp"
#include "gl/gpu_simulator.hpp"

namespace morphogen::bench {

namespace {

using Clock = std::chrono::steady_clock;

// The blob at level 6: 81,920 triangles, an organic shape near the issue's
// 100k-triangle model that the simplifier has real work on.
constexpr int kLargeMeshLevel = 6;

std::size_t usedTexels(const Atlas& atlas) {
    std::size_t used = 0;
    for (std::uint32_t i = 0; i < atlas.cellCount(); ++i)
        used += atlas.used(i) ? 1 : 0;
    return used;
}

// A temporary file removed when it goes out of scope.
struct TemporaryFile {
    std::string path;
    ~TemporaryFile() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
};

// Mesh to atlas: the phases setUpSurface reports (read and weld the file;
// simplify; tiles: the closest-point tree, reshaping and the atlas with its
// connectivity; projection: positions, Jacobians (the metric) and curvature;
// weights: the diffusion weights and useAtlas), each timed from its start to
// the next one's.
nlohmann::json meshToAtlasRow(const TriangleMesh& mesh, const std::string& path) {
    std::fprintf(stderr, "bench: mesh to atlas, %zu triangles...\n", mesh.triangles.size());

    Session s = loadPreset("turk_large_spots");
    s.surface.mesh = path;
    std::vector<std::pair<std::string, Clock::time_point>> marks;
    const auto start = Clock::now();
    // setUpSurface reports "projection" done (1) before it computes the
    // weights: the time from there on is the weights'.
    SurfaceSetup setup = setUpSurface(s, [&](const std::string& phase, double fraction) {
        const std::string name = phase == "projection" && fraction >= 1 ? "weights" : phase;
        if (marks.empty() || marks.back().first != name)
            marks.emplace_back(name, Clock::now());
    });
    const auto end = Clock::now();
    marks.emplace_back("end", end);
    const double total = std::chrono::duration<double>(end - start).count();

    std::printf("\n%-22s %9s %7s %9s %8s  %s\n", "mesh to atlas", "triangles", "tiles", "texels",
                "seconds", "phases (s)");
    const std::size_t used = usedTexels(*setup.tiles.atlas);
    std::printf("%-22s %9zu %7d %9zu %8.2f ", "blob level 6 (OBJ)", mesh.triangles.size(),
                setup.tiles.atlas->tileCount(), used, total);
    nlohmann::json phases = nlohmann::json::object();
    for (std::size_t k = 0; k + 1 < marks.size(); ++k) {
        const double t =
            std::chrono::duration<double>(marks[k + 1].second - marks[k].second).count();
        phases[marks[k].first] = t;
        std::printf(" %s %.2f", marks[k].first.c_str(), t);
    }
    std::printf("\n");
    std::fflush(stdout);
    return {{"mesh", "sample blob level " + std::to_string(kLargeMeshLevel) + " as OBJ"},
            {"triangles", mesh.triangles.size()},
            {"tiles", setup.tiles.atlas->tileCount()},
            {"tile_size", setup.tiles.atlas->tileSize()},
            {"texels", used},
            {"seconds", total},
            {"phases", phases}};
}

// The holes model's sample preset on its atlas, set up once for the rows
// that time it, with its count of used texels.
struct HolesAtlas {
    Session session;
    SurfaceSetup setup;
    std::size_t used = 0;
};

// At the automatic tile size and at 16x16, with the explicit kernel whatever
// setUpSurface would choose.
std::vector<HolesAtlas> holesAtlases() {
    std::vector<HolesAtlas> out;
    for (const int tileSize : {0, 16}) {
        HolesAtlas h;
        h.session = loadPreset("surface_curvature_spots_holes");
        h.session.surface.tileSize = tileSize;
        h.session.integratorGiven = true;
        h.setup = setUpSurface(h.session);
        h.used = usedTexels(*h.setup.tiles.atlas);
        out.push_back(std::move(h));
    }
    return out;
}

// Global steps on the holes model's atlas (automatic budget, metric weights
// with curvature scaling: its sample preset) against a flat grid of about as
// many cells as the atlas has used texels, same model; at the automatic tile
// size (4x4 texels at the preset's length: three quarters of the texels are
// on a tile border and go through the connectivity map) and at 16x16. Steps
// are engine steps: a session step on the atlas takes `substeps` of them
// (the weights' stability bound), shown beside the fraction.
nlohmann::json throughputRows(const std::vector<std::pair<std::string, Make>>& backends,
                              const std::vector<HolesAtlas>& holes, double seconds) {
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-22s %-8s %9s %9s %14s %14s %9s %9s\n", "surface atlas", "backend", "texels",
                "texture", "atlas texel/s", "grid cell/s", "fraction", "substeps");
    for (const HolesAtlas& h : holes) {
        const Session& onAtlas = h.session;
        const SurfaceSetup& setup = h.setup;
        const Atlas& atlas = *setup.tiles.atlas;
        const int substeps = weightedSubsteps(*setup.weights);
        const std::size_t used = h.used;
        Session grid = loadPreset("surface_curvature_spots_holes");
        grid.surface = {};
        const int side = int(std::lround(std::sqrt(double(used))));
        grid.width = grid.height = side;
        const std::string name = "holes, tiles " + std::to_string(atlas.tileSize()) + "x" +
                                 std::to_string(atlas.tileSize());
        for (const auto& [backend, make] : backends) {
            const bool gpu = backend == "gpu";
            std::fprintf(stderr, "bench: %s atlas on the %s...\n", name.c_str(), backend.c_str());
            const double a = sessionStepsPerSecond(onAtlas, make, gpu, seconds) * double(used);
            const double g = sessionStepsPerSecond(grid, make, gpu, seconds) * double(side) * side;
            const std::string texture =
                std::to_string(atlas.width()) + "x" + std::to_string(atlas.height());
            std::printf("%-22s %-8s %9zu %9s %14.3g %14.3g %9.3f %9d\n", name.c_str(),
                        backend.c_str(), used, texture.c_str(), a, g, a / g, substeps);
            std::fflush(stdout);
            rows.push_back({{"mesh", "sample:holes"},
                            {"backend", backend},
                            {"tiles", atlas.tileCount()},
                            {"tile_size", atlas.tileSize()},
                            {"texels", used},
                            {"texture", {atlas.width(), atlas.height()}},
                            {"grid", side},
                            {"atlas_texels_per_s", a},
                            {"grid_cells_per_s", g},
                            {"fraction_of_grid", a / g},
                            {"substeps", substeps}});
        }
    }
    return rows;
}

// The least a weighted atlas step can do: the same planes read at the same
// texels (each chemical's row and the rows above and below it, every weight
// plane, and the right-hand side for a relaxation pass) and the same planes
// written, with one add per value read instead of the stencil, the reaction,
// the division and the clamps. Run through the same PaddedAtlasStep (its
// halo fills included), so that the ratio of the two is the kernels' own cost
// over the memory traffic they cannot avoid.
template <int N, bool Cross, bool Rhs>
MORPHOGEN_VECTOR_CLONES void probeRows(const StepConstants& k, const std::uint8_t* chemicals,
                                       const State& in, const State* rhs, State& out, int y0,
                                       int y1, int x0, int x1) {
    const int w = in.width();
    const std::size_t cells = in.cellCount();
    for (int y = y0; y < y1; ++y) {
        const std::size_t row = std::size_t(y) * std::size_t(w);
        const float* weight[8] = {};
        for (int p = 0; p < (Cross ? 8 : 4); ++p)
            weight[p] = (p < 4 ? k.weightPlanes->data() + std::size_t(p) * cells
                               : k.diagonalPlanes->data() + std::size_t(p - 4) * cells) +
                        row;
        const float* mid[N];
        const float* b[N];
        float* next[N];
        for (int i = 0; i < N; ++i) {
            const int c = chemicals ? chemicals[i] : i;
            mid[i] = in.plane(c) + row;
            b[i] = Rhs ? rhs->plane(c) + row : mid[i];
            next[i] = out.plane(c) + row;
        }
#pragma omp simd
        for (int x = x0; x < x1; ++x) {
            float sum = (weight[0][x] + weight[1][x]) + (weight[2][x] + weight[3][x]);
            if constexpr (Cross)
                sum += (weight[4][x] + weight[5][x]) + (weight[6][x] + weight[7][x]);
#pragma GCC unroll 4
            for (int i = 0; i < N; ++i) {
                const float v = (mid[i][x - w] + mid[i][x + w]) + mid[i][x];
                next[i][x] = 0.25f * (Rhs ? v + b[i][x] : v) + sum;
            }
        }
    }
}

// The explicit probe for `k`'s chemicals and weight planes.
void probeStep(const StepConstants& k, const State& in, State& out, int y0, int y1, int x0,
               int x1) {
    using Kernel = void (*)(const StepConstants&, const std::uint8_t*, const State&, const State*,
                            State&, int, int, int, int);
    constexpr Kernel plain[] = {&probeRows<1, false, false>, &probeRows<2, false, false>,
                                &probeRows<3, false, false>, &probeRows<4, false, false>};
    constexpr Kernel cross[] = {&probeRows<1, true, false>, &probeRows<2, true, false>,
                                &probeRows<3, true, false>, &probeRows<4, true, false>};
    if (k.chemicals < 1 || k.chemicals > 4)
        throw std::logic_error("bench: the kernel probe takes 1 to 4 chemicals");
    (k.crossWeighted() ? cross : plain)[k.chemicals - 1](k, nullptr, in, nullptr, out, y0, y1, x0,
                                                         x1);
}

// The relaxation pass's probe for n of the chemicals, as RelaxTileKernels.
template <int N, bool Cross>
void probeRelax(const StepConstants& k, const std::uint8_t* chemicals, const State& in,
                const State& rhs, State& out, int y0, int y1, int x0, int x1) {
    probeRows<N, Cross, true>(k, chemicals, in, &rhs, out, y0, y1, x0, x1);
}

RelaxTileKernels probeRelaxation(const StepConstants& k) {
    if (k.chemicals < 1 || k.chemicals > 4)
        throw std::logic_error("bench: the kernel probe takes 1 to 4 chemicals");
    if (k.crossWeighted())
        return {{nullptr, &probeRelax<1, true>, &probeRelax<2, true>, &probeRelax<3, true>,
                 &probeRelax<4, true>}};
    return {{nullptr, &probeRelax<1, false>, &probeRelax<2, false>, &probeRelax<3, false>,
             &probeRelax<4, false>}};
}

// The CPU's explicit step and semi-implicit relaxation pass on the holes
// model's atlas (as throughputRows; metric weights with the cross term: eight
// weight planes), each against its probe, all four through the same
// PaddedAtlasStep with the simulator's threading rule.
nlohmann::json kernelProbeRows(const std::vector<HolesAtlas>& holes, double seconds) {
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-22s %-14s %14s %14s %9s\n", "atlas kernel (cpu)", "kernel", "texel/s",
                "probe texel/s", "fraction");
    for (const HolesAtlas& h : holes) {
        const Session& s = h.session;
        const Atlas& atlas = *h.setup.tiles.atlas;
        const std::size_t used = h.used;
        const StepConstants k = StepConstants::fromSession(s);
        const std::vector<std::array<std::uint32_t, 8>> diagonals =
            k.crossWeighted() ? atlasDiagonals(atlas) : std::vector<std::array<std::uint32_t, 8>>{};
        const ReactionModel& model = s.reactionModel();
        const StepTileKernel step = fusedWeightedStep(model, k);
        const RelaxTileKernels relax = weightedRelaxation(k);
        if (step == nullptr || !relax)
            throw std::logic_error("bench: the holes preset has no fused atlas kernel");
        State state = initialState(s);
        const State rhs = state;
        const bool threaded = state.cellCount() >= 65536; // CpuSimulator's rule
        PaddedAtlasStep padded(atlas, diagonals, k);
        const auto rate = [&](const std::function<void(int)>& run) {
            return measureStepsPerSecond(
                       run, [] {}, seconds, 20) *
                   double(used);
        };
        const std::string name = "holes, tiles " + std::to_string(atlas.tileSize()) + "x" +
                                 std::to_string(atlas.tileSize());
        std::fprintf(stderr, "bench: kernel probes on %s...\n", name.c_str());
        State probeState = state; // the probes' values grow each step
        const double stepRate =
            rate([&](int n) { padded.run(step, k, state, n, {}, {}, threaded); });
        const double stepProbe =
            rate([&](int n) { padded.run(&probeStep, k, probeState, n, {}, {}, threaded); });
        const double relaxRate =
            rate([&](int n) { padded.relax(relax, k, state, rhs, n, {}, threaded); });
        const double relaxProbe = rate(
            [&](int n) { padded.relax(probeRelaxation(k), k, probeState, rhs, n, {}, threaded); });
        for (const auto& [kernel, a, p] :
             {std::tuple<const char*, double, double>{"explicit step", stepRate, stepProbe},
              {"relaxation pass", relaxRate, relaxProbe}}) {
            std::printf("%-22s %-14s %14.3g %14.3g %9.3f\n", name.c_str(), kernel, a, p, a / p);
            rows.push_back({{"mesh", "sample:holes"},
                            {"tile_size", atlas.tileSize()},
                            {"texels", used},
                            {"kernel", kernel},
                            {"texels_per_s", a},
                            {"probe_texels_per_s", p},
                            {"fraction_of_probe", a / p}});
        }
        std::fflush(stdout);
    }
    return rows;
}

// Seconds per session step of `s` (its last segment: substeps included).
double secondsPerSessionStep(const Session& s, const Make& make, bool gpu, double seconds) {
    const Segment segment = segmentsOf(s).back();
    return double(segment.substeps) / sessionStepsPerSecond(segment.session, make, gpu, seconds);
}

// The cost of a session step on a model, both integrators, against a flat
// grid with as many cells as the atlas has texels, each cell a texel's mean
// side (its own explicit substeps; no coarse-to-fine): turk_large_spots on
// the blob (5k triangles), the scan-like sample (30k) and the blob at level 6
// (82k). A settled pattern takes about as many session steps on either
// integrator (docs/surfaces.md), so these ratios are those of the time to it.
nlohmann::json stepCostRows(const std::vector<std::pair<std::string, Make>>& backends,
                            const std::string& largeMesh, double seconds) {
    nlohmann::json rows = nlohmann::json::array();
    std::printf("\n%-24s %-8s %8s %9s %12s %12s %10s %10s %9s\n", "session step", "backend",
                "texels", "substeps", "explicit ms", "semi-impl ms", "grid ms", "x grid",
                "speed-up");
    const std::vector<std::pair<std::string, std::string>> models = {
        {"blob (5k triangles)", "sample:blob"},
        {"scan (30k)", "sample:scan"},
        {"blob level 6 (82k)", largeMesh}};
    for (const auto& [name, mesh] : models) {
        Session onAtlas = loadPreset("turk_large_spots");
        onAtlas.surface.mesh = mesh;
        onAtlas.integratorGiven = true;
        std::fprintf(stderr, "bench: session steps on %s...\n", name.c_str());
        const SurfaceSetup setup = setUpSurface(onAtlas);
        const std::size_t used = usedTexels(*setup.tiles.atlas);
        Session semi = onAtlas;
        semi.integrator = Integrator::SemiImplicit;
        Session grid = loadPreset("turk_large_spots");
        const int side = int(std::lround(std::sqrt(double(used))));
        grid.width = grid.height = side;
        grid.length = side * setup.texelUnits;
        grid.coarseToFine = false;
        const int substeps = segmentsOf(onAtlas).back().substeps;
        for (const auto& [backend, make] : backends) {
            const bool gpu = backend == "gpu";
            const double e = secondsPerSessionStep(onAtlas, make, gpu, seconds);
            const double i = secondsPerSessionStep(semi, make, gpu, seconds);
            const double g = secondsPerSessionStep(grid, make, gpu, seconds);
            const double best = std::min(e, i);
            std::printf("%-24s %-8s %8zu %9d %12.3f %12.3f %10.3f %10.2f %9.2f\n", name.c_str(),
                        backend.c_str(), used, substeps, 1e3 * e, 1e3 * i, 1e3 * g, best / g,
                        e / i);
            std::fflush(stdout);
            rows.push_back({{"mesh", name},
                            {"backend", backend},
                            {"texels", used},
                            {"explicit_substeps", substeps},
                            {"relaxation_passes", semi.relaxationPasses},
                            {"explicit_seconds_per_step", e},
                            {"semi_implicit_seconds_per_step", i},
                            {"grid_side", side},
                            {"grid_substeps", segmentsOf(grid).back().substeps},
                            {"grid_seconds_per_step", g},
                            {"best_over_grid", best / g},
                            {"semi_implicit_speedup", e / i}});
        }
    }
    return rows;
}

} // namespace

nlohmann::json benchSurface(bool gpu, bool cpu, double seconds) {
    const std::vector<std::pair<std::string, Make>> backends = simulatorBackends(gpu, cpu);
    const TriangleMesh large = sampleMesh("blob", kLargeMeshLevel);
    TemporaryFile file{(std::filesystem::temp_directory_path() /
                        ("morphogen_bench_" + std::to_string(::getpid()) + ".obj"))
                           .string()};
    writeObj(large, file.path);
    const std::vector<HolesAtlas> holes = holesAtlases();
    return {{"mesh_to_atlas", meshToAtlasRow(large, file.path)},
            {"throughput", throughputRows(backends, holes, seconds)},
            {"kernel_probe", cpu ? kernelProbeRows(holes, seconds) : nlohmann::json::array()},
            {"session_step", stepCostRows(backends, file.path, seconds)}};
}

} // namespace morphogen::bench
