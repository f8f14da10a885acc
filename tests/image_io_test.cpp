// Output images through OpenImageIO: written files read back with the values
// they should hold; bad paths give InputError before anything is written.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/output/colormap.hpp"
#include "test_support.hpp"

using namespace morphogen;
namespace fs = std::filesystem;

namespace {

fs::path workDir() {
    return test::scratchDir("morphogen_image_io_test");
}

State ramp(int w, int h) {
    State st(w, h, 2);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            st.at(0, x, y) = float(x) / float(w - 1);
            st.at(1, x, y) = -3.5f + float(y);
        }
    return st;
}

} // namespace

TEST(ImageIo, EightBitQuantisationRoundsAsLround) {
    // toUnorm8 rounds without libm; it must give lround's byte for every
    // input, the half-way values (k + 0.5) / 255 and their float neighbours
    // included, so the PNG writer's bytes did not change with it.
    auto reference = [](float v) {
        return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    int checked = 0;
    for (int k = 0; k < 256; ++k) {
        const float half = (float(k) + 0.5f) / 255.0f;
        for (float v :
             {half, std::nextafter(half, 0.0f), std::nextafter(half, 1.0f), float(k) / 255.0f}) {
            EXPECT_EQ(toUnorm8(v), reference(v)) << v;
            ++checked;
        }
    }
    for (float v = -0.5f; v <= 1.5f; v = std::nextafter(v, 2.0f) + 1e-7f) {
        ASSERT_EQ(toUnorm8(v), reference(v)) << v;
        ++checked;
    }
    EXPECT_GT(checked, 1000000);
    EXPECT_EQ(toUnorm8(std::nanf("")), 0);
}

TEST(ImageIo, FormatFollowsTheExtension) {
    EXPECT_EQ(imageFormatForPath("a/b.png"), ImageFormat::Png);
    EXPECT_EQ(imageFormatForPath("b.TIFF"), ImageFormat::Tiff);
    EXPECT_EQ(imageFormatForPath("b.tif"), ImageFormat::Tiff);
    EXPECT_EQ(imageFormatForPath("b.exr"), ImageFormat::Exr);
    try {
        imageFormatForPath("out.jpg");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(".png, .tif, .tiff, .exr"), std::string::npos);
    }
}

TEST(ImageIo, UnwritableDestinationsAreRefusedUpFront) {
    EXPECT_THROW(checkWritable("/nonexistent-folder/x.png"), InputError);
    EXPECT_THROW(checkWritable(workDir().string()), InputError); // a folder
    EXPECT_NO_THROW(checkWritable((workDir() / "ok.png").string()));
    EXPECT_FALSE(fs::exists(workDir() / "ok.png.probe"));
}

TEST(ImageIo, PngEightAndSixteenBitHoldTheColourMap) {
    const State st = ramp(16, 4);
    ColorMapSpec grey;
    const auto rgb = applyColormap(st, 0, grey);
    for (int bits : {8, 16}) {
        SCOPED_TRACE(bits);
        const std::string path = (workDir() / ("ramp" + std::to_string(bits) + ".png")).string();
        writeRgbImage(path, rgb, 16, 4, bits);
        auto in = OIIO::ImageInput::open(path);
        ASSERT_TRUE(in);
        const OIIO::ImageSpec& spec = in->spec();
        EXPECT_EQ(spec.width, 16);
        EXPECT_EQ(spec.nchannels, 3);
        EXPECT_EQ(spec.format, bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
        std::vector<float> px(16 * 4 * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, px.data()));
        // de Kleine min-max: the first column is black, the last white.
        EXPECT_FLOAT_EQ(px[0], 0.0f);
        EXPECT_FLOAT_EQ(px[15 * 3], 1.0f);
        // Quantisation tolerance: half a step at the bit depth.
        EXPECT_NEAR(px[5 * 3], 5.0f / 15.0f, bits == 8 ? 0.5f / 255 : 0.5f / 65535);
    }
}

TEST(ImageIo, ExrHoldsRawFloatsWithChemicalNames) {
    const State st = ramp(8, 8);
    const std::string path = (workDir() / "raw.exr").string();
    writeRawImage(path, st, {"u", "v"});
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    ASSERT_EQ(in->spec().nchannels, 2);
    EXPECT_EQ(in->spec().channelnames[0], "u");
    EXPECT_EQ(in->spec().channelnames[1], "v");
    std::vector<float> px(8 * 8 * 2);
    ASSERT_TRUE(in->read_image(0, 0, 0, 2, OIIO::TypeDesc::FLOAT, px.data()));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(px[std::size_t(y * 8 + x) * 2 + 0], st.at(0, x, y));
            EXPECT_EQ(px[std::size_t(y * 8 + x) * 2 + 1], st.at(1, x, y));
        }
    EXPECT_THROW(writeRawImage((workDir() / "raw.png").string(), st, {"u", "v"}), InputError);
}

TEST(ImageIo, FailedWriteLeavesNoFile) {
    const State st = ramp(4, 4);
    const auto rgb = applyColormap(st, 0, ColorMapSpec{});
    const std::string path = (workDir() / "no-such-dir" / "x.png").string();
    EXPECT_THROW(writeRgbImage(path, rgb, 4, 4, 8), InputError);
    EXPECT_FALSE(fs::exists(path));
    EXPECT_THROW(writeRgbImage((workDir() / "x.png").string(), rgb, 4, 4, 12), InputError);
}

// Images are written a row at a time: the rows arrive in order, top first,
// and a row that throws leaves neither the image nor its temporary file.
TEST(ImageIo, RowsAreAskedForInOrderAndAFailingRowLeavesNoFile) {
    const fs::path dir = workDir() / "rows";
    fs::create_directories(dir);
    const std::string path = (dir / "rows.png").string();
    std::vector<int> asked;
    writeImageRows(path, 3, 4, 1, 16, [&](int y, float* row) {
        asked.push_back(y);
        for (int x = 0; x < 3; ++x)
            row[x] = float(y) / 3.0f;
    });
    EXPECT_EQ(asked, (std::vector<int>{0, 1, 2, 3}));
    auto in = OIIO::ImageInput::open(path);
    ASSERT_TRUE(in);
    std::vector<unsigned short> px(12);
    ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT16, px.data()));
    EXPECT_EQ(px[0], 0);
    EXPECT_EQ(px[3], 21845); // row 1: 1/3 of 65535
    EXPECT_EQ(px[11], 65535);
    in->close();

    const std::string failing = (dir / "failing.png").string();
    EXPECT_THROW(writeImageRows(failing, 3, 4, 3, 8,
                                [](int y, float* row) {
                                    if (y == 2)
                                        throw std::runtime_error("row 2");
                                    std::fill(row, row + 9, 0.5f);
                                }),
                 std::runtime_error);
    EXPECT_FALSE(fs::exists(failing));
    std::size_t files = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(dir))
        files += e.path().filename() != "rows.png" ? 1 : 0;
    EXPECT_EQ(files, 0u) << "a temporary file was left behind";
}

TEST(Colormap, NamesAreCheckedAndFlatFieldsStayFlat) {
    EXPECT_THROW(canonicalColormapName("rainbow"), InputError);
    for (const std::string& name : colormapNames())
        EXPECT_EQ(canonicalColormapName(name), name);
    EXPECT_EQ(canonicalColormapName("gray"), "grey");
    EXPECT_EQ(canonicalColormapName("Two-Color"), "two-colour");
    EXPECT_EQ(canonicalColormapName("VIRIDIS"), "viridis");
    State flat(4, 4, 1);
    for (std::size_t i = 0; i < flat.cellCount(); ++i)
        flat.plane(0)[i] = 0.3f + (i % 2) * 1e-7f; // round-off, not a pattern
    ColorMapSpec spec;
    const auto rgb = applyColormap(flat, 0, spec);
    for (float v : rgb)
        EXPECT_EQ(v, rgb[0]);
}

TEST(Colormap, PalettesRunFromDarkToLight) {
    const State st = ramp(32, 2);
    for (const char* name : {"viridis", "magma", "inferno"}) {
        ColorMapSpec spec;
        spec.name = name;
        const auto rgb = applyColormap(st, 0, spec);
        auto luma = [&](int x) { return rgb[x * 3] + rgb[x * 3 + 1] + rgb[x * 3 + 2]; };
        for (int x = 1; x < 32; ++x)
            EXPECT_GT(luma(x), luma(x - 1) - 1e-3f) << name << " at " << x;
    }
}

TEST(Colormap, LevelsWindowTheNormalisedValue) {
    // A ramp 0..1 over 11 columns: with levels [0.3, 0.5] everything at or
    // below 0.3 is the low colour, at or above 0.5 the high colour, and 0.4
    // is half way.
    State st(11, 1, 1);
    for (int x = 0; x < 11; ++x)
        st.at(0, x, 0) = float(x) / 10.0f;
    ColorMapSpec spec;
    spec.name = "grey";
    spec.levels = {0.3f, 0.5f};
    const auto rgb = applyColormap(st, 0, spec);
    for (int x = 0; x <= 3; ++x)
        EXPECT_EQ(rgb[std::size_t(x) * 3], 0.0f) << x;
    EXPECT_NEAR(rgb[4 * 3], 0.5f, 1e-5f);
    for (int x = 5; x <= 10; ++x)
        EXPECT_EQ(rgb[std::size_t(x) * 3], 1.0f) << x;
    // The default window changes nothing.
    spec.levels = ColorMapSpec{}.levels;
    const auto plain = applyColormap(st, 0, spec);
    for (int x = 0; x < 11; ++x)
        EXPECT_FLOAT_EQ(plain[std::size_t(x) * 3], float(x) / 10.0f);
}
