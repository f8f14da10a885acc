#include "core/io/image_io.hpp"

#include <algorithm>
#include <cassert>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>

#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "core/base/errors.hpp"
#include "core/base/json_input.hpp"
#include "core/base/limits.hpp"
#include "core/io/exr_header_check.hpp"
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
    // The writers add a temporary suffix or prefix to the name: leave room for it.
    const std::size_t name = p.filename().string().size();
    if (name > std::size_t(kMaxOutputNameBytes))
        throw InputError(path + ": the file name is " + std::to_string(name) +
                         " bytes long; accepted are names of up to " +
                         std::to_string(kMaxOutputNameBytes) + " bytes");
    if (path.size() > std::size_t(kMaxOutputPathBytes))
        throw InputError(path.substr(0, 60) + "...: the path is " + std::to_string(path.size()) +
                         " bytes long; accepted are paths of up to " +
                         std::to_string(kMaxOutputPathBytes) + " bytes");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw InputError(path + ": cannot write here: folder '" + dir.string() +
                         "' does not exist");
    if (fs::is_directory(p, ec))
        throw InputError(path + ": cannot write here: it is a folder");
    // An existing file that may not be replaced (immutable, on a read-only
    // file system) fails only at the end of the run, when it is renamed over.
    if (fs::exists(p, ec) && ::access(path.c_str(), W_OK) != 0 &&
        (errno == EPERM || errno == EROFS))
        throw InputError(path + ": cannot replace the existing file: " + std::strerror(errno) +
                         (errno == EPERM ? " (is it immutable? lsattr shows it)" : ""));
    const std::string probe = (dir / (".~probe." + std::to_string(::getpid()))).string();
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0) {
        const int error = errno;
        throw InputError(path + ": cannot write here: folder '" + dir.string() +
                         "' is not writable (" + std::strerror(error) + ")");
    }
    ::close(fd);
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

// Reads the file just written back whole (defined below, beside the readers):
// OpenImageIO's PNG writer does not report a short write (a full disk, the
// file-size limit), so a truncated image would otherwise replace a good one.
void verifyWrittenImage(const std::string& written, const OIIO::ImageSpec& spec,
                        const std::string& shown);

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
        verifyWrittenImage(tmp, spec, shown);
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

namespace {

// libpng (under OIIO) prints its own "libpng error: ..." line on stderr
// before OIIO reports the same error, which the InputError then quotes:
// while an image is opened and read, stderr goes to a temporary file, and
// what was printed there is passed on afterwards, less libpng's own lines
// when the read failed. One image at a time (stderr is the process's).
class QuietStderr {
public:
    QuietStderr() : m_lock(mutex()) {
        std::fflush(stderr);
        m_file = std::tmpfile();
        m_saved = m_file ? ::dup(STDERR_FILENO) : -1;
        if (m_saved >= 0 && ::dup2(::fileno(m_file), STDERR_FILENO) < 0) {
            ::close(m_saved);
            m_saved = -1;
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;
    // A read that threw.
    ~QuietStderr() { end(false); }
    // A read that worked: libpng's warnings are passed on too.
    void passOn() { end(true); }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    void end(bool succeeded) {
        if (m_saved >= 0) {
            std::fflush(stderr);
            ::dup2(m_saved, STDERR_FILENO);
            ::close(m_saved);
            m_saved = -1;
            std::rewind(m_file);
            char line[4096];
            while (std::fgets(line, sizeof line, m_file))
                if (succeeded || std::strncmp(line, "libpng ", 7) != 0)
                    std::fputs(line, stderr);
        }
        if (m_file)
            std::fclose(m_file);
        m_file = nullptr;
    }
    std::lock_guard<std::mutex> m_lock;
    std::FILE* m_file = nullptr;
    int m_saved = -1;
};

void checkImageHeader(const std::string& path, const OIIO::ImageSpec& spec) {
    checkImageSize(path, spec.width, spec.height, std::max(1, spec.depth), spec.nchannels);
}

void verifyWrittenImage(const std::string& written, const OIIO::ImageSpec& spec,
                        const std::string& shown) {
    std::error_code ec;
    const std::string incomplete = shown +
                                   ": writing the image failed: the file on disk is incomplete (" +
                                   std::to_string(fs::file_size(written, ec)) +
                                   " bytes; is the disk full, or the file over a size limit?)";
    QuietStderr quiet;
    auto input = OIIO::ImageInput::open(written);
    if (!input)
        throw InputError(incomplete);
    const OIIO::ImageSpec& read = input->spec();
    if (read.width != spec.width || read.height != spec.height || read.nchannels != spec.nchannels)
        throw InputError(incomplete);
    // Row by row: the check holds one row, whatever the image's size.
    std::vector<float> row(std::size_t(read.width) * std::size_t(read.nchannels));
    for (int y = 0; y < read.height; ++y)
        if (!input->read_scanline(y, 0, OIIO::TypeDesc::FLOAT, row.data()))
            throw InputError(incomplete);
    input->close();
}

} // namespace

void checkImageSize(const std::string& path, long long width, long long height, long long depth,
                    long long channels) {
    if (width < 1 || height < 1 || channels < 1)
        throw InputError(path + ": the image is empty");
    if (depth != 1)
        throw InputError(path + ": a volume image (" + std::to_string(depth) +
                         " slices); accepted are 2D images");
    // 64-bit: a header may declare sides whose product wraps an int.
    if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
        throw InputError(path + ": the image is " + std::to_string(width) + " x " +
                         std::to_string(height) + " pixels; accepted are up to " +
                         std::to_string(kMaxImageSide) + " pixels per side and " +
                         std::to_string(kMaxImagePixels) +
                         " in all (checked from its header, before reading it)");
    if (channels > kMaxImageChannels)
        throw InputError(path + ": the image has " + std::to_string(channels) +
                         " channels; accepted are up to " + std::to_string(kMaxImageChannels));
}

void checkImageFile(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw InputError(path + ": image not found");
    QuietStderr quiet;
    checkExrAttributeSizes(path);
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        throw InputError(path + ": cannot read the image (" + oneLine(OIIO::geterror()) +
                         "); accepted: any format OpenImageIO reads, e.g. PNG, TIFF, EXR, JPEG");
    checkImageHeader(path, input->spec());
    input->close();
    quiet.passOn();
}

std::vector<float> loadLuminance(const std::string& path, int width, int height) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        throw InputError(path + ": image not found");
    // ImageInput rather than ImageBuf(path): the latter goes through OIIO's
    // process-wide image cache, which keeps stale entries for a file that was
    // rewritten and crashed after reading a truncated PNG.
    QuietStderr quiet;
    checkExrAttributeSizes(path);
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        throw InputError(path + ": cannot read the image (" + oneLine(OIIO::geterror()) +
                         "); accepted: any format OpenImageIO reads, e.g. PNG, TIFF, EXR, JPEG");
    const OIIO::ImageSpec spec = input->spec();
    checkImageHeader(path, spec);
    // Luminance needs the first three channels (or the only one): the rest
    // (alpha, extra EXR layers) are not decoded.
    const int channels = spec.nchannels >= 3 ? 3 : 1;
    std::vector<float> original(std::size_t(spec.width) * std::size_t(spec.height) *
                                std::size_t(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, original.data()))
        throw InputError(path + ": cannot read the image's pixels (" + oneLine(input->geterror()) +
                         "); is the file truncated?");
    input->close();
    quiet.passOn();
    OIIO::ImageSpec floatSpec(spec.width, spec.height, channels, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf source(floatSpec, original.data());
    OIIO::ImageBuf resized;
    const OIIO::ROI roi(0, width, 0, height, 0, 1, 0, channels);
    if (!OIIO::ImageBufAlgo::resize(resized, source, "", 0.0f, roi))
        throw InputError(path + ": cannot resample the image to " + std::to_string(width) + "x" +
                         std::to_string(height) + ": " + oneLine(resized.geterror()));
    std::vector<float> pixels(std::size_t(width) * height * std::size_t(channels));
    resized.get_pixels(roi, OIIO::TypeDesc::FLOAT, pixels.data());
    std::vector<float> luminance(std::size_t(width) * height);
    const std::size_t nc = std::size_t(channels);
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
    QuietStderr quiet;
    checkExrAttributeSizes(path);
    auto input = OIIO::ImageInput::open(path);
    if (!input)
        throw InputError(path + ": cannot read the image (" + oneLine(OIIO::geterror()) +
                         "); accepted: the .exr (or float .tif) that render --out writes");
    const OIIO::ImageSpec spec = input->spec();
    checkImageHeader(path, spec);
    if (spec.nchannels > kMaxChemicals)
        throw InputError(path + ": " + std::to_string(spec.nchannels) +
                         " channels, more than any model has chemicals (" +
                         std::to_string(kMaxChemicals) + ")");
    const std::size_t nc = std::size_t(spec.nchannels);
    std::vector<float> px(std::size_t(spec.width) * std::size_t(spec.height) * nc);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
        throw InputError(path + ": cannot read the image's pixels (" + oneLine(input->geterror()) +
                         "); is the file truncated?");
    input->close();
    quiet.passOn();
    RawImage raw{State(spec.width, spec.height, spec.nchannels), spec.channelnames};
    for (int c = 0; c < spec.nchannels; ++c) {
        float* p = raw.state.plane(c);
        for (std::size_t i = 0; i < raw.state.cellCount(); ++i)
            p[i] = px[i * nc + std::size_t(c)];
    }
    return raw;
}

} // namespace morphogen
