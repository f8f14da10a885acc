// The presets browser's thumbnail cache: a second start shows the pictures
// from disk without running the presets; an edited preset or a broken file
// is rendered again.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/io/image_io.hpp"
#include "core/session/session.hpp"
#include "gl_test_support.hpp"
#include "test_support.hpp"
#include "ui/thumbnails.hpp"

namespace morphogen {
namespace {

namespace fs = std::filesystem;

// Waits for the worker, then makes every texture (a model's picture is
// rendered, and cached, on this thread when its texture is asked for).
void finish(ui::Thumbnails& t, const std::vector<Session>& presets) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (t.rendered() < t.total() && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    ASSERT_EQ(t.rendered(), t.total());
    for (const Session& s : presets)
        EXPECT_NE(t.texture(s.name), 0u) << s.name;
}

std::vector<fs::path> cachedFiles(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(dir / "thumbnails"))
        files.push_back(e.path());
    return files;
}

TEST(Thumbnails, ASecondStartReadsTheCache) {
    test::glContext();
    const fs::path dir = test::scratchDir("thumbnails_cache");
    fs::remove_all(dir);
    Session flat = loadPreset("gs_coral");
    flat.steps = 400; // a thumbnail's picture, sooner
    Session model = loadPreset("surface_stripes_torus");
    model.steps = 200;
    std::vector<Session> presets = {flat, model};
    {
        ui::Thumbnails t;
        t.start(presets, dir.string());
        finish(t, presets);
        EXPECT_EQ(t.fromCache(), 0);
    }
    ASSERT_EQ(cachedFiles(dir).size(), 2u);
    // The cached pictures are the thumbnails: RGBA at kSize, not blank.
    for (const fs::path& p : cachedFiles(dir)) {
        const RawImage image = readRawImage(p.string());
        ASSERT_EQ(image.state.width(), ui::Thumbnails::kSize) << p;
        ASSERT_EQ(image.state.channels(), 4) << p;
        const float* red = image.state.plane(0);
        const auto [lo, hi] = std::minmax_element(red, red + image.state.cellCount());
        EXPECT_GT(*hi - *lo, 0.1f) << p << ": one flat colour";
    }
    {
        ui::Thumbnails t;
        t.start(presets, dir.string());
        finish(t, presets);
        EXPECT_EQ(t.fromCache(), 2);
    }
    // An edited preset gets a picture of its own; a broken file is rendered again.
    presets[0].steps = 401;
    for (const fs::path& p : cachedFiles(dir))
        if (p.filename().string().rfind("surface_stripes_torus-", 0) == 0)
            std::ofstream(p, std::ios::trunc) << "not a png";
    {
        ui::Thumbnails t;
        t.start(presets, dir.string());
        finish(t, presets);
        EXPECT_EQ(t.fromCache(), 0);
    }
    EXPECT_EQ(cachedFiles(dir).size(),
              3u); // the old gs_coral picture stays; the torus is rewritten
}

// gs_coral is 256 units wide: at 64 cells (4 units a cell) it grew scattered
// dots, not its labyrinth. The thumbnail runs at 128 cells (2 units a cell)
// and is averaged down, so the labyrinth covers a good part of the picture.
// Measured: 2.4% of the pixels bright at 64 cells, 57% at 128 averaged down.
TEST(Thumbnails, AWidePresetRunsAtTwoUnitsACellAndShowsItsPattern) {
    test::glContext();
    const fs::path dir = test::scratchDir("thumbnails_wide");
    fs::remove_all(dir);
    const std::vector<Session> presets = {loadPreset("gs_coral")};
    {
        ui::Thumbnails t;
        t.start(presets, dir.string());
        finish(t, presets);
    }
    ASSERT_EQ(cachedFiles(dir).size(), 1u);
    const RawImage image = readRawImage(cachedFiles(dir).front().string());
    ASSERT_EQ(image.state.width(), ui::Thumbnails::kSize);
    const float* red = image.state.plane(0);
    const std::size_t bright = std::size_t(
        std::count_if(red, red + image.state.cellCount(), [](float r) { return r > 0.5f; }));
    const double share = double(bright) / double(image.state.cellCount());
    std::printf("gs_coral thumbnail: %.1f%% of the pixels bright\n", 100 * share);
    EXPECT_GT(share, 0.2);
}

} // namespace
} // namespace morphogen
