// Images read as diffusion maps: real files through OpenImageIO, broken ones
// rejected with the file named.

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/operators/orientation_field.hpp"
#include "test_support.hpp"

using namespace morphogen;
namespace fs = std::filesystem;

namespace {

fs::path workDir() {
    return test::scratchDir("morphogen_image_loader_test");
}

// Vertical stripes: luminance varies along x only.
std::string writeStripes(int w, int h) {
    std::vector<float> rgb(std::size_t(w) * h * 3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                rgb[(std::size_t(y) * w + x) * 3 + c] =
                    float(0.5 + 0.5 * std::sin(2 * 3.14159265 * x / 8.0));
    const std::string path = (workDir() / "stripes.png").string();
    writeRgbImage(path, rgb, w, h, 16);
    return path;
}

std::string errorOf(const std::string& path) {
    try {
        loadLuminance(path, 8, 8);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(ImageLoader, ReadsAndResamplesLuminance) {
    const std::string path = writeStripes(64, 32);
    const std::vector<float> lum = loadLuminance(path, 64, 32);
    ASSERT_EQ(lum.size(), 64u * 32u);
    // 16-bit quantisation: half a step.
    EXPECT_NEAR(lum[2], 1.0f, 1e-4f);            // sin peak at x = 2
    EXPECT_NEAR(lum[6], 0.0f, 1e-4f);            // trough at x = 6
    EXPECT_NEAR(lum[2], lum[5 * 64 + 2], 1e-6f); // constant down a column
    const std::vector<float> half = loadLuminance(path, 32, 16);
    EXPECT_EQ(half.size(), 32u * 16u);
}

TEST(ImageLoader, BrokenFilesNameTheFile) {
    const std::string missing = (workDir() / "missing.png").string();
    EXPECT_NE(errorOf(missing).find("missing.png: image not found"), std::string::npos);

    const std::string garbage = (workDir() / "garbage.png").string();
    std::ofstream(garbage, std::ios::binary) << "this is not a PNG at all";
    const std::string message = errorOf(garbage);
    EXPECT_NE(message.find("garbage.png: cannot read the image"), std::string::npos) << message;

    const std::string empty = (workDir() / "empty.exr").string();
    std::ofstream(empty, std::ios::binary).close();
    EXPECT_NE(errorOf(empty).find("empty.exr"), std::string::npos);

    // A truncated PNG: a real header, then nothing.
    const std::string good = writeStripes(16, 16);
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string truncated = (workDir() / "truncated.png").string();
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, 40);
    EXPECT_NE(errorOf(truncated).find("truncated.png"), std::string::npos);

    EXPECT_NE(errorOf(workDir().string()).find("image not found"), std::string::npos);
}

TEST(ImageLoader, GradientFieldFollowsTheIsolines) {
    // Vertical stripes: isolines run vertically, 90 degrees on the display.
    OrientationField field;
    field.type = OrientationField::Type::ImageGradient;
    field.image = writeStripes(64, 64);
    const std::vector<float> angles = orientationAngles(field, 64, 64, "");
    double c = 0, s = 0;
    for (float a : angles) {
        c += std::cos(2 * a);
        s += std::sin(2 * a);
    }
    const double mean = 0.5 * std::atan2(s, c) * 180 / 3.14159265;
    EXPECT_NEAR(std::fabs(mean), 90.0, 2.0);
    EXPECT_GT(std::hypot(c, s) / angles.size(), 0.95); // coherent
}

TEST(ImageLoader, SessionImagePathsResolveAgainstTheSessionFolder) {
    OrientationField field;
    field.type = OrientationField::Type::ImageGradient;
    writeStripes(16, 16);
    field.image = "stripes.png";
    EXPECT_NO_THROW(orientationAngles(field, 16, 16, workDir().string()));
    EXPECT_THROW(orientationAngles(field, 16, 16, "/nonexistent"), InputError);
}
