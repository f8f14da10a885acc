// Atlas domains on the GPU (the ATLAS variant of glsl/step.frag): it must
// agree with the CPU backend on the cube and on rotated tiles, conserve mass,
// and copy unused texels through.

#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "atlas_checks.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/mesh/mesh_samples.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/param_map.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/surface/surface_setup.hpp"
#include "core/surface/surface_weights.hpp"
#include "core/surface/tile_builder.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

template <class Sim> State runOn(const Session& s, const State& start, int steps) {
    test::glContext();
    Sim sim(s);
    sim.setState(start);
    sim.run(steps);
    return sim.state();
}

// Runs `s` from `start` for 60 steps on both backends; they must agree (the
// same sums in the same order, but llvmpipe and drivers may contract
// multiply-adds: relative 1e-5 of the value range) and the state must move.
// Returns the GPU's state.
State expectBackendsAgree(const Session& s, const State& start) {
    const State cpu = runOn<CpuSimulator>(s, start, 60);
    const State gpu = runOn<gl::GpuSimulator>(s, start, 60);
    EXPECT_LT(test::maxAbsDifference(cpu, gpu), 1e-5f * test::maxAbsValue(cpu));
    EXPECT_GT(test::maxAbsDifference(cpu, start), 1e-3f) << "nothing happened";
    return gpu;
}

void expectBackendsAgree(std::shared_ptr<const Atlas> atlas, Stencil stencil) {
    SCOPED_TRACE(stencil == Stencil::FivePoint ? "5-point" : "9-point");
    const Session s = test::atlasSession(atlas, stencil);
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
    expectBackendsAgree(s, start);
}

} // namespace

TEST(AtlasGpu, AgreesWithTheCpuOnTheCube) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint})
        expectBackendsAgree(std::make_shared<const Atlas>(Atlas::cube(16)), stencil);
}

TEST(AtlasGpu, AgreesWithTheCpuOnRotatedTiles) {
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint})
        expectBackendsAgree(std::make_shared<const Atlas>(Atlas::rotatedTiles(8)), stencil);
}

TEST(AtlasGpu, AgreesWithTheCpuAroundAValence5Corner) {
    // Five tiles around one vertex, every quad's corner 0 at it; outer edges open.
    std::vector<std::array<int, 4>> quads;
    for (int i = 0; i < 5; ++i)
        quads.push_back({0, 1 + i, 6 + i, 1 + (i + 1) % 5});
    for (Stencil stencil : {Stencil::FivePoint, Stencil::NinePoint})
        expectBackendsAgree(std::make_shared<const Atlas>(Atlas::fromQuads(8, quads)), stencil);
}

TEST(AtlasGpu, ConservesMassOnTheCubeAndSpreadsSymmetricallyAtACorner) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    const std::vector<std::uint32_t> corner = test::cornerTexels(*atlas, 0);
    State start(atlas->width(), atlas->height(), 2);
    for (std::uint32_t c : corner)
        start.plane(0)[c] = 1.0f;
    const State end = runOn<gl::GpuSimulator>(test::pureDiffusionSession(atlas), start, 40);
    EXPECT_NEAR(test::usedSum(end, *atlas, 0), 3.0, 3e-5);
    for (std::uint32_t c : corner)
        EXPECT_NEAR(end.plane(0)[c], end.plane(0)[corner[0]], 1e-6f);
    EXPECT_LT(end.plane(0)[corner[0]], 0.5f) << "nothing diffused";
}

TEST(AtlasGpu, UnusedTexelsCopyThrough) {
    auto open = std::make_shared<Atlas>(8, 3, 2);
    open->glue(0, TileEdge::PlusX, 1, TileEdge::MinusX);
    open->glue(0, TileEdge::PlusY, 2, TileEdge::MinusY);
    const std::shared_ptr<const Atlas> atlas = open;
    const State start = test::randomUsedState(*atlas, 4);
    const Session s = test::pureDiffusionSession(atlas);
    const State gpu = runOn<gl::GpuSimulator>(s, start, 30);
    const State cpu = runOn<CpuSimulator>(s, start, 30);
    for (std::uint32_t i = 0; i < atlas->cellCount(); ++i)
        if (!atlas->used(i))
            ASSERT_EQ(gpu.plane(0)[i], 7.0f);
    EXPECT_LT(test::maxAbsDifference(cpu, gpu), 1e-5f * test::maxAbsValue(cpu));
}

namespace {

Session withWeights(Session s, const AtlasWeights& weights) {
    useAtlas(s, s.atlas, std::make_shared<const AtlasWeights>(weights));
    return s;
}

} // namespace

// Per-texel weights (the ATLAS_WEIGHTS variant): non-uniform, flux-symmetric
// weights on the cube and on rotated tiles, gs_coral for 60 steps.
TEST(AtlasGpu, AgreesWithTheCpuWithNonUniformWeights) {
    for (auto atlas : {std::make_shared<const Atlas>(Atlas::cube(16)),
                       std::make_shared<const Atlas>(Atlas::rotatedTiles(8))}) {
        const Session s = withWeights(test::atlasSession(atlas), test::symmetricWeights(*atlas, 5));
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
        const State gpu = expectBackendsAgree(s, start);
        // The weights matter: the unweighted run differs by far more.
        const State plain = runOn<gl::GpuSimulator>(test::atlasSession(atlas), start, 60);
        EXPECT_GT(test::maxAbsDifference(plain, gpu), 1e-3f);
    }
}

// The same with diagonals (the ATLAS_CROSS variant, the 9-point stencil of
// sheared surface texels): interior texels read the grid's diagonals, border
// texels one order of the diagonal maps.
TEST(AtlasGpu, AgreesWithTheCpuWithNinePointWeights) {
    for (auto atlas : {std::make_shared<const Atlas>(Atlas::cube(16)),
                       std::make_shared<const Atlas>(Atlas::rotatedTiles(8))}) {
        const Session s =
            withWeights(test::atlasSession(atlas), test::symmetricNinePointWeights(*atlas, 5));
        const State start =
            makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
        const State gpu = expectBackendsAgree(s, start);
        // The diagonals matter: the same weights without them differ by far more.
        AtlasWeights five = test::symmetricNinePointWeights(*atlas, 5);
        five.diagonal.clear();
        const State plain =
            runOn<gl::GpuSimulator>(withWeights(test::atlasSession(atlas), five), start, 60);
        EXPECT_GT(test::maxAbsDifference(plain, gpu), 1e-3f);
    }
}

// The surface's own weights (surfaceWeights on a simplified sphere: sheared
// kites, valence 3 and 5+ corners where the cross term stays out, the blend):
// both backends agree as with the synthetic ones.
TEST(AtlasGpu, AgreesWithTheCpuWithSurfaceNinePointWeights) {
    TileOptions options;
    options.tileSize = 6;
    options.tiles = 300;
    const SurfaceTiles tiles = buildSurfaceTiles(icosphere(3), options);
    auto weights = surfaceWeights(tiles, {});
    ASSERT_TRUE(weights.hasDiagonals());
    Session s = test::atlasSession(tiles.atlas);
    // Within the explicit limit of the weights (a unit sphere: sums in the hundreds).
    s.dt = 0.9f / (s.params.at("Du") * maxCoefficientSum(weights));
    s = withWeights(s, weights);
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
    expectBackendsAgree(s, start);
}

// Semi-implicit steps on the surface's weights (the JACOBI_PASS variant with
// a texel's own Jacobi weight 1 / (1 + dt r S)): at 10x the explicit limit and
// with frozen texels both backends agree.
TEST(AtlasGpu, SemiImplicitStepsAgreeWithTheCpuPastTheExplicitLimit) {
    TileOptions options;
    options.tileSize = 6;
    options.tiles = 300;
    const SurfaceTiles tiles = buildSurfaceTiles(icosphere(3), options);
    auto weights = surfaceWeights(tiles, {});
    Session s = test::atlasSession(tiles.atlas);
    s.dt = 10.0f / (s.params.at("Du") * maxCoefficientSum(weights));
    s = withWeights(s, weights);
    s.integrator = Integrator::SemiImplicit;
    s.relaxationPasses = 4;
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
    std::vector<std::uint8_t> frozen(tiles.atlas->cellCount(), 0);
    for (int t = 0; t < tiles.atlas->tileCount(); t += 7)
        frozen[tiles.atlas->tileCell(t, 2, 3)] = 1;
    test::glContext();
    CpuSimulator cpu(s);
    gl::GpuSimulator gpu(s);
    for (Simulator* sim : {static_cast<Simulator*>(&cpu), static_cast<Simulator*>(&gpu)}) {
        sim->setFrozen(frozen);
        sim->setState(start);
        sim->run(30);
    }
    const State a = cpu.state(), b = gpu.state();
    EXPECT_LT(test::maxAbsDifference(a, b), 1e-5f * test::maxAbsValue(a));
    EXPECT_GT(test::maxAbsDifference(a, start), 1e-3f) << "nothing happened";
    for (std::uint32_t i = 0; i < tiles.atlas->cellCount(); ++i)
        if (frozen[i])
            EXPECT_EQ(b.plane(0)[i], start.plane(0)[i]) << "frozen cell " << i;

    // Localized: a few tiles solve alone on both, the rest keep their values.
    const std::vector<int> active = {3, 4, 5, 40, 41};
    CpuSimulator cpuLocal(s);
    gl::GpuSimulator gpuLocal(s);
    for (Simulator* sim :
         {static_cast<Simulator*>(&cpuLocal), static_cast<Simulator*>(&gpuLocal)}) {
        sim->setState(start);
        sim->setActiveTiles(active);
        sim->run(10);
    }
    const State c = cpuLocal.state(), g = gpuLocal.state();
    EXPECT_LT(test::maxAbsDifference(c, g), 1e-5f * test::maxAbsValue(c));
    EXPECT_GT(test::maxAbsDifference(g, start), 1e-3f) << "nothing happened locally";
    for (std::uint32_t i = 0; i < tiles.atlas->cellCount(); ++i) {
        const int tile = tiles.atlas->tileOf(i);
        if (std::find(active.begin(), active.end(), tile) == active.end())
            EXPECT_EQ(g.plane(0)[i], start.plane(0)[i]) << "cell " << i << " outside";
    }
}

TEST(AtlasGpu, NinePointWeightsConserveTheAreaWeightedAmount) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    const AtlasWeights weights = test::symmetricNinePointWeights(*atlas, 9);
    const Session s = withWeights(test::pureDiffusionSession(atlas), weights);
    const State start = test::randomUsedState(*atlas, 3);
    const State end = runOn<gl::GpuSimulator>(s, start, 200);
    const double before = test::areaWeightedSum(start, *atlas, weights, 0);
    EXPECT_NEAR(test::areaWeightedSum(end, *atlas, weights, 0), before, 1e-5 * before);
    EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
}

TEST(AtlasGpu, SymmetricWeightsConserveTheAreaWeightedAmount) {
    auto atlas = std::make_shared<const Atlas>(Atlas::cube(8));
    const AtlasWeights weights = test::symmetricWeights(*atlas, 9);
    const Session s = withWeights(test::pureDiffusionSession(atlas), weights);
    const State start = test::randomUsedState(*atlas, 3);
    const State end = runOn<gl::GpuSimulator>(s, start, 200);
    const double before = test::areaWeightedSum(start, *atlas, weights, 0);
    EXPECT_NEAR(test::areaWeightedSum(end, *atlas, weights, 0), before, 1e-5 * before);
    EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
}

// Anisotropic diffusion on a surface (the ATLAS_TENSOR variant): the tensor
// weights of a direction field on a simplified sphere (the field fades to zero
// at its poles), each chemical with its own Witkin-Kass tensor: both backends
// agree, and the tensor matters.
TEST(AtlasGpu, AgreesWithTheCpuWithSurfaceTensorWeights) {
    TileOptions options;
    options.tileSize = 6;
    options.tiles = 300;
    const SurfaceTiles tiles = buildSurfaceTiles(icosphere(3), options);
    SurfaceWeightOptions weightOptions;
    weightOptions.direction = SurfaceDirection{}; // along y
    auto weights = std::make_shared<const AtlasWeights>(surfaceWeights(tiles, weightOptions));
    ASSERT_TRUE(weights->tensor);

    Session s = test::atlasSession(tiles.atlas);
    s.diffusion.type = DiffusionType::Anisotropic;
    s.diffusion.anisotropic = {{"u", {30.0f, 2.0f, 1.0f}}, {"v", {90.0f, 1.5f, 1.0f}}};
    const float rates[2] = {s.params.at("Du"), s.params.at("Dv")};
    double largest = 0;
    for (const auto& mix : sessionTensorMixes(s, rates))
        largest = std::max(largest, maxTensorSum(*weights, mix));
    // Within the explicit limit of the combined operators (Gershgorin: 2 * sum).
    s.dt = float(0.9 / largest);
    useAtlas(s, s.atlas, weights);

    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
    const State gpu = expectBackendsAgree(s, start);

    // The tensors matter: the same run with isotropic tensors differs by far more.
    Session isotropic = s;
    isotropic.diffusion.anisotropic = {{"u", {0.0f, 1.0f, 1.0f}}, {"v", {0.0f, 1.0f, 1.0f}}};
    const State plain = runOn<gl::GpuSimulator>(isotropic, start, 60);
    EXPECT_GT(test::maxAbsDifference(plain, gpu), 1e-3f);
}

// Pure anisotropic diffusion conserves the area-weighted amount on the GPU: the
// tensor operators' fluxes are the same from both sides of every pair.
TEST(AtlasGpu, SurfaceTensorWeightsConserveTheAreaWeightedAmount) {
    TileOptions options;
    options.tileSize = 6;
    options.tiles = 200;
    const SurfaceTiles tiles = buildSurfaceTiles(torus(24), options);
    SurfaceWeightOptions weightOptions;
    weightOptions.direction =
        SurfaceDirection{SurfaceDirection::Type::Around, {0, 0, 1}, {0, 0, 0}};
    auto weights = std::make_shared<const AtlasWeights>(surfaceWeights(tiles, weightOptions));
    Session s = test::pureDiffusionSession(tiles.atlas);
    s.diffusion.type = DiffusionType::Anisotropic;
    s.diffusion.anisotropic = {{"u", {20.0f, 2.0f, 0.5f}}, {"v", {0.0f, 1.0f, 1.0f}}};
    const float rates[2] = {s.params.at("Du"), s.params.at("Dv")};
    s.dt = float(0.9 / maxTensorSum(*weights, sessionTensorMixes(s, rates)[0]));
    useAtlas(s, s.atlas, weights);
    const State start = test::randomUsedState(*tiles.atlas, 3);
    const State end = runOn<gl::GpuSimulator>(s, start, 200);
    const double before = test::areaWeightedSum(start, *tiles.atlas, *weights, 0);
    // Float sums of ~10^4 texels over 200 steps: relative 1e-5.
    EXPECT_NEAR(test::areaWeightedSum(end, *tiles.atlas, *weights, 0), before, 1e-5 * before);
    EXPECT_GT(test::maxAbsDifference(end, start), 0.05f) << "nothing diffused";
}

// Parameter maps on a mesh (fields in space, evaluateSurfaceParamMap): a map of
// a reaction parameter and one of a diffusion rate, on the sample sphere's
// weighted atlas; both backends agree over the whole atlas and over a set of
// active tiles (localized steps), and the maps matter.
TEST(AtlasGpu, AgreesWithTheCpuWithParamMapsOnAMesh) {
    Session s = loadPreset("gs_coral");
    s.length = 60;
    s.surface.mesh = "sample:sphere";
    s.surface.tiles = 120;
    s.surface.tileSize = 4;
    ParamMapSpec k{ParamMapSpec::Field::LinearY, 0.055f, 0.065f};
    ParamMapSpec du{ParamMapSpec::Field::Noise, 0.1f, 0.2f};
    du.scale = 10;
    s.paramMaps = {{"k", k}, {"Du", du}};
    (void)setUpSurface(s);
    // Within the explicit limit of the weights at the map's largest rate.
    s.dt = 0.9f / (0.2f * maxCoefficientSum(*s.atlasWeights));
    const State start =
        makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, 11);
    const State gpu = expectBackendsAgree(s, start);
    Session plain = s;
    plain.paramMaps.clear();
    EXPECT_GT(test::maxAbsDifference(runOn<gl::GpuSimulator>(plain, start, 60), gpu), 1e-3f)
        << "the maps changed nothing";

    // Localized: the first 20 tiles only.
    std::vector<int> tiles(20);
    std::iota(tiles.begin(), tiles.end(), 0);
    auto local = [&](auto simulator) {
        simulator.setState(start);
        simulator.setActiveTiles(tiles);
        simulator.run(60);
        return simulator.state();
    };
    test::glContext();
    const State cpuLocal = local(CpuSimulator(s));
    const State gpuLocal = local(gl::GpuSimulator(s));
    EXPECT_LT(test::maxAbsDifference(cpuLocal, gpuLocal), 1e-5f * test::maxAbsValue(cpuLocal));
    EXPECT_GT(test::maxAbsDifference(cpuLocal, start), 1e-3f) << "nothing happened";
}
