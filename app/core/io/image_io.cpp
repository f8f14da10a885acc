#include "core/io/image_io.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

#include <OpenImageIO/imageio.h>

#include "core/base/errors.hpp"
#include "core/io/output_files.hpp"

namespace morphogen {

namespace fs = std::filesystem;

ImageFormat imageFormatForPath(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".png")
        return ImageFormat::Png;
    if (ext == ".tif" || ext == ".tiff")
        return ImageFormat::Tiff;
    if (ext == ".exr")
        return ImageFormat::Exr;
    throw InputError(path + ": unsupported image extension '" + ext +
                     "' (accepted: .png, .tif, .tiff, .exr)");
}

void checkWritable(const std::string& path) {
    const fs::path p(path);
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(path + ": cannot write here: folder '" + dir.string() +
                         "' does not exist");
    if (fs::is_directory(p, ec))
        throw InputError(path + ": cannot write here: it is a folder");
    const std::string probe = path + ".probe";
    {
        std::ofstream out(probe);
        if (!out)
            throw InputError(path + ": cannot write here: folder '" + dir.string() +
                             "' is not writable");
    }
    fs::remove(probe, ec);
}

namespace {

// A library's message on one line (libpng's come in several).
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
        text.replace(at, 1, "; ");
    return text;
}

// Writes the image through writeFileAtomically (a temporary next to `path`
// with the real extension, which OIIO picks the format by, renamed into
// place), so a failed or interrupted write leaves no half-written image.
void writeAtomically(const std::string& path, const OIIO::ImageSpec& spec,
                     const std::function<bool(OIIO::ImageOutput&)>& pixels) {
    const std::string shown = finalPathOf(path);
    writeFileAtomically(path, [&](const std::string& tmp) {
        auto out = OIIO::ImageOutput::create(tmp);
        if (!out)
            throw InputError(shown + ": no image writer for this format: " + OIIO::geterror());
        // An exception from `pixels` closes the file (unique_ptr) before the
        // temporary is removed.
        if (!(out->open(tmp, spec) && pixels(*out) && out->close()))
            throw InputError(shown + ": writing the image failed: " + oneLine(out->geterror()));
    });
}

// Quantises one row of values into `typed`: 8- or 16-bit, clamped to [0, 1].
template <class T> const T* quantise(const std::vector<float>& row, std::vector<T>& typed) {
    typed.resize(row.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
        if constexpr (sizeof(T) == 1)
            typed[i] = toUnorm8(row[i]);
        else
            typed[i] = T(std::lround(std::clamp(row[i], 0.0f, 1.0f) * 65535.0f));
    }
    return typed.data();
}

// Writes rows of `type` (FLOAT: raw values; UINT8/UINT16: quantised).
void writeTypedRows(const std::string& path, int width, int height, int channels,
                    OIIO::TypeDesc type, const std::vector<std::string>& channelNames,
                    const ImageRowFn& row) {
    OIIO::ImageSpec spec(width, height, channels, type);
    if (!channelNames.empty())
        spec.channelnames.assign(channelNames.begin(), channelNames.end());
    writeAtomically(path, spec, [&](OIIO::ImageOutput& out) {
        std::vector<float> values(std::size_t(width) * std::size_t(channels));
        std::vector<unsigned char> bytes;
        std::vector<unsigned short> shorts;
        for (int y = 0; y < height; ++y) {
            row(y, values.data());
            const void* data = values.data();
            if (type == OIIO::TypeDesc::UINT8)
                data = quantise(values, bytes);
            else if (type == OIIO::TypeDesc::UINT16)
                data = quantise(values, shorts);
            if (!out.write_scanline(y, 0, type, data))
                return false;
        }
        return true;
    });
}

} // namespace

void writeImageRows(const std::string& path, int width, int height, int channels, int bitDepth,
                    const ImageRowFn& row) {
    if (imageFormatForPath(path) == ImageFormat::Exr) {
        writeTypedRows(path, width, height, channels, OIIO::TypeDesc::FLOAT, {}, row);
        return;
    }
    if (bitDepth != 8 && bitDepth != 16)
        throw InputError("bit depth " + std::to_string(bitDepth) +
                         " is not supported (accepted: 8, 16)");
    writeTypedRows(path, width, height, channels,
                   bitDepth == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16, {}, row);
}

void writeRawRows(const std::string& path, int width, int height, int channels,
                  const std::vector<std::string>& channelNames, const ImageRowFn& row) {
    if (imageFormatForPath(path) == ImageFormat::Png)
        throw InputError(finalPathOf(path) +
                         ": PNG cannot hold raw float concentrations (use .exr or .tif)");
    writeTypedRows(path, width, height, channels, OIIO::TypeDesc::FLOAT, channelNames, row);
}

namespace {

void writeInterleaved(const std::string& path, const std::vector<float>& values, int width,
                      int height, int channels, int bitDepth) {
    assert(values.size() == std::size_t(width) * std::size_t(height) * std::size_t(channels));
    const std::size_t rowLength = std::size_t(width) * std::size_t(channels);
    writeImageRows(path, width, height, channels, bitDepth, [&](int y, float* row) {
        std::copy_n(values.data() + std::size_t(y) * rowLength, rowLength, row);
    });
}

} // namespace

void writeRgbImage(const std::string& path, const std::vector<float>& rgb, int width, int height,
                   int bitDepth) {
    writeInterleaved(path, rgb, width, height, 3, bitDepth);
}

void writeGreyImage(const std::string& path, const std::vector<float>& grey, int width, int height,
                    int bitDepth) {
    writeInterleaved(path, grey, width, height, 1, bitDepth);
}

void writeRawImage(const std::string& path, const State& state,
                   const std::vector<std::string>& channelNames) {
    const int nc = state.channels();
    const std::size_t w = std::size_t(state.width());
    writeRawRows(path, state.width(), state.height(), nc, channelNames, [&](int y, float* row) {
        for (int c = 0; c < nc; ++c) {
            const float* p = state.plane(c) + std::size_t(y) * w;
            for (std::size_t x = 0; x < w; ++x)
                row[x * std::size_t(nc) + std::size_t(c)] = p[x];
        }
    });
}

} // namespace morphogen

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

namespace morphogen {

std::vector<float> loadLuminance(const std::string& path, int width, int height) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw InputError(path + ": image not found");
    // ImageInput rather than ImageBuf(path): the latter goes through OIIO's
    // process-wide image cache, which keeps stale entries for a file that was
    // rewritten and crashed after reading a truncated PNG.
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        throw InputError(path + ": cannot read the image (" + OIIO::geterror() +
                         "); accepted: any format OpenImageIO reads, e.g. PNG, TIFF, EXR, JPEG");
    const OIIO::ImageSpec spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
        throw InputError(path + ": the image is empty");
    std::vector<float> original(std::size_t(spec.width) * spec.height *
                                std::size_t(spec.nchannels));
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, original.data()))
        throw InputError(path + ": cannot read the image's pixels (" + input->geterror() +
                         "); is the file truncated?");
    input->close();
    OIIO::ImageSpec floatSpec(spec.width, spec.height, spec.nchannels, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf source(floatSpec, original.data());
    OIIO::ImageBuf resized;
    const OIIO::ROI roi(0, width, 0, height, 0, 1, 0, spec.nchannels);
    if (!OIIO::ImageBufAlgo::resize(resized, source, "", 0.0f, roi))
        throw InputError(path + ": cannot resample the image to " + std::to_string(width) + "x" +
                         std::to_string(height) + ": " + resized.geterror());
    std::vector<float> pixels(std::size_t(width) * height * std::size_t(spec.nchannels));
    resized.get_pixels(roi, OIIO::TypeDesc::FLOAT, pixels.data());
    std::vector<float> luminance(std::size_t(width) * height);
    const std::size_t nc = std::size_t(spec.nchannels);
    for (std::size_t i = 0; i < luminance.size(); ++i) {
        const float* p = &pixels[i * nc];
        const float l = nc >= 3 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[0];
        if (!std::isfinite(l))
            throw InputError(path + ": the image holds NaN or infinite values");
        luminance[i] = l;
    }
    return luminance;
}

} // namespace morphogen

namespace morphogen {

RawImage readRawImage(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw InputError(path + ": raw state image not found");
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        throw InputError(path + ": cannot read the image (" + OIIO::geterror() +
                         "); accepted: the .exr (or float .tif) that render --out writes");
    const OIIO::ImageSpec spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
        throw InputError(path + ": the image is empty");
    if (spec.nchannels > kMaxChemicals)
        throw InputError(path + ": " + std::to_string(spec.nchannels) +
                         " channels, more than any model has chemicals (" +
                         std::to_string(kMaxChemicals) + ")");
    const std::size_t nc = std::size_t(spec.nchannels);
    std::vector<float> px(std::size_t(spec.width) * std::size_t(spec.height) * nc);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
        throw InputError(path + ": cannot read the image's pixels (" + input->geterror() +
                         "); is the file truncated?");
    input->close();
    RawImage raw{State(spec.width, spec.height, spec.nchannels), spec.channelnames};
    for (int c = 0; c < spec.nchannels; ++c) {
        float* p = raw.state.plane(c);
        for (std::size_t i = 0; i < raw.state.cellCount(); ++i)
            p[i] = px[i * nc + std::size_t(c)];
    }
    return raw;
}

} // namespace morphogen
