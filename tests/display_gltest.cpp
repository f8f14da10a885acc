// The display pass against the image writer's colours: GPU pass (min-max
// reduced on the GPU) and CPU path (applyColormap, uploaded).

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include <gtest/gtest.h>

#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "core/session/gradient.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "gl/display.hpp"
#include "gl/gpu_simulator.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// The writer's 8-bit pixels as RGBA (alpha 255).
std::vector<std::uint8_t> writerPixels(const State& state, int chemical, const ColorMapSpec& spec) {
    const std::vector<float> rgb = applyColormap(state, chemical, spec);
    std::vector<std::uint8_t> rgba(state.cellCount() * 4, 255);
    for (std::size_t i = 0; i < state.cellCount(); ++i)
        for (std::size_t k = 0; k < 3; ++k)
            rgba[i * 4 + k] = toUnorm8(rgb[i * 3 + k]);
    return rgba;
}

// Largest per-channel difference, and how many channels differ at all.
std::pair<int, int> compare(const std::vector<std::uint8_t>& a,
                            const std::vector<std::uint8_t>& b) {
    EXPECT_EQ(a.size(), b.size());
    int worst = 0, differing = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        const int d = std::abs(int(a[i]) - int(b[i]));
        worst = std::max(worst, d);
        differing += d != 0;
    }
    return {worst, differing};
}

int distinctColours(const std::vector<std::uint8_t>& rgba) {
    std::vector<std::uint32_t> colours;
    for (std::size_t i = 0; i < rgba.size(); i += 4)
        colours.push_back(std::uint32_t(rgba[i]) << 16 | std::uint32_t(rgba[i + 1]) << 8 |
                          rgba[i + 2]);
    std::sort(colours.begin(), colours.end());
    return int(std::unique(colours.begin(), colours.end()) - colours.begin());
}

struct Case {
    std::string map;
    std::string chemical;
    std::array<float, 2> levels;
    std::vector<std::array<float, 3>> colours = {}; // the "custom" map's stops
};

// GPU display of `state` (set on a GpuSimulator of s) against the writer,
// within 1 of 255 per channel: the shader's float arithmetic may round
// differently from the CPU's (fused multiply-adds, its 1 / range), and GL
// leaves the rounding of float to unorm8 to the implementation, while the
// writer rounds to nearest; either moves a channel by at most one step.
void expectGpuMatchesWriter(const Session& s, const State& state, const Case& c) {
    SCOPED_TRACE(s.reactionModel().name() + " " + c.map + " " + c.chemical + " levels " +
                 std::to_string(c.levels[0]) + ":" + std::to_string(c.levels[1]));
    gl::GpuSimulator gpu(s);
    gpu.setState(state);
    ColorMapSpec spec;
    spec.name = c.map;
    spec.chemical = c.chemical;
    spec.levels = c.levels;
    spec.low = {0.1f, 0.3f, 0.05f};
    spec.colours = c.colours;
    const int chemical = colormapChemical(spec, s.reactionModel());
    gl::Display display(s.width, s.height);
    display.render(gpu, chemical, spec);
    const std::vector<std::uint8_t> expected = writerPixels(state, chemical, spec);
    const auto [worst, differing] = compare(display.downloadRgba8(), expected);
    std::printf("%s %s %s: worst %d, %d of %zu channels differ\n", s.reactionModel().name().c_str(),
                c.map.c_str(), c.chemical.c_str(), worst, differing, expected.size());
    EXPECT_LE(worst, 1);
    // A real picture, not a flat field that would match trivially.
    EXPECT_GT(distinctColours(expected), 20);

    // The CPU path: the writer's colours through ColourMapRows::rowRgba8's
    // table, which moves a channel by at most one step.
    CpuSimulator cpu(s);
    cpu.setState(state);
    display.update(cpu, chemical, spec);
    EXPECT_LE(compare(display.downloadRgba8(), expected).first, 1);
    // And the front sends a GpuSimulator down the GPU path.
    display.update(gpu, chemical, spec);
    EXPECT_LE(compare(display.downloadRgba8(), expected).first, 1);
}

State ranState(const Session& s, int steps) {
    CpuSimulator sim(s);
    sim.setState(makeInitialState(s.init, s.reactionModel(), s.params, s.width, s.height, s.seed));
    sim.run(steps);
    return sim.state();
}

} // namespace

TEST(Display, GpuPassMatchesTheWriterForEveryMapChemicalAndLevels) {
    test::glContext();
    // Sizes that are not multiples of 4 exercise the reduction's edges, and
    // 37 > 16 needs three reduction levels.
    Session s = test::smallSession("gs_coral", 23, 0);
    s.width = 37;
    const State state = ranState(s, 60);
    for (const Case& c : {Case{"grey", "u", {0.0f, 1.0f}}, Case{"two-colour", "v", {0.0f, 1.0f}},
                          Case{"viridis", "v", {0.0f, 1.0f}}, Case{"magma", "u", {0.2f, 0.7f}},
                          Case{"inferno", "v", {0.1f, 0.5f}}, Case{"coolwarm", "v", {0.3f, 0.9f}}})
        expectGpuMatchesWriter(s, state, c);
}

TEST(Display, SecondStateTextureOfMeinhardtStripes) {
    test::glContext();
    Session s = test::smallSession("meinhardt_random_stripes", 20, 0);
    s.width = 26;
    State state = ranState(s, 200);
    // Chemicals 4 and 5 (s2, substrate) live in the second state texture.
    expectGpuMatchesWriter(s, state, {"viridis", "s2", {0.0f, 1.0f}});
    expectGpuMatchesWriter(s, state, {"magma", "substrate", {0.1f, 0.9f}});
}

TEST(Display, NonFiniteCellsAreLeftOutOfTheRangeAndShownAtTheLowEnd) {
    test::glContext();
    Session s = test::smallSession("gs_coral", 18, 0);
    State state = ranState(s, 40);
    state.at(1, 3, 4) = std::numeric_limits<float>::quiet_NaN();
    state.at(1, 9, 2) = std::numeric_limits<float>::infinity();
    state.at(1, 17, 17) = -std::numeric_limits<float>::infinity();
    expectGpuMatchesWriter(s, state, {"viridis", "v", {0.0f, 1.0f}});
}

TEST(Display, FlatFieldMapsToTheLowEnd) {
    test::glContext();
    Session s = test::smallSession("gs_coral", 9, 0);
    State state(9, 9, 2);
    std::fill(state.plane(0), state.plane(0) + state.cellCount(), 0.75f);
    gl::GpuSimulator gpu(s);
    gpu.setState(state);
    ColorMapSpec spec;
    spec.name = "magma";
    gl::Display display(9, 9);
    display.render(gpu, 0, spec);
    EXPECT_LE(compare(display.downloadRgba8(), writerPixels(state, 0, spec)).first, 1);
    const std::vector<std::uint8_t> px = display.downloadRgba8();
    EXPECT_LE(px[0] + px[1] + px[2], 6); // magma's near-black end
}

TEST(Display, CustomGradientsUpToTheAnchorLimit) {
    test::glContext();
    Session s = test::smallSession("gs_coral", 23, 0);
    s.width = 31;
    const State state = ranState(s, 60);
    expectGpuMatchesWriter(
        s, state, {"custom", "v", {0.0f, 1.0f}, parseGradient("#1b1b1b,#d9a441,#f4e8c1", "test")});
    // Sixteen stops (the uniform array's size), alternating, so every anchor shows.
    std::string sixteen;
    for (int i = 0; i < kMaxGradientStops; ++i)
        sixteen += std::string(sixteen.empty() ? "" : ",") + (i % 2 ? "#f4e8c1" : "#203a80");
    expectGpuMatchesWriter(s, state, {"custom", "v", {0.1f, 0.9f}, parseGradient(sixteen, "test")});
}
