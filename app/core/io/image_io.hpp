#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/base/state.hpp"

namespace morphogen {

enum class ImageFormat { Png, Tiff, Exr };

// The format for an output path by its extension; throws InputError naming
// the accepted extensions (.png, .tif, .tiff, .exr).
ImageFormat imageFormatForPath(const std::string& path);

// Fails early (before a long run) when the output cannot be created: the
// folder is missing or not writable. Throws InputError naming the path.
void checkWritable(const std::string& path);

// An 8-bit image's value for v in [0, 1] (clamped; rounded to nearest): the
// PNG writer's and the display's CPU path's quantisation.
inline std::uint8_t toUnorm8(float v) {
    // lround's half away from zero, without its libm call (it kept the
    // display's per-frame loop from vectorising): x + 0.5 is exact in double
    // for any float x in [0, 255], so truncating it rounds as lround does.
    // NaN gives 0 (a float-to-int conversion of NaN would be undefined).
    const float x = v > 0.0f ? std::min(v, 1.0f) * 255.0f : 0.0f;
    return std::uint8_t(int(double(x) + 0.5));
}

// Fills row y (0 at the top) of an image: width * channels interleaved values.
using ImageRowFn = std::function<void(int y, float* row)>;

// Writes an image a row at a time, asking `row` for each in order: values in
// [0, 1] as 8- or 16-bit PNG/TIFF (quantised as toUnorm8 / to 65535), raw
// floats for EXR. A big image costs a row of memory, not a whole-image
// buffer. Atomic like writeRgbImage; an exception from `row` removes the
// temporary file and propagates.
void writeImageRows(const std::string& path, int width, int height, int channels, int bitDepth,
                    const ImageRowFn& row);

// The same with raw float values, named channels (OpenEXR, or float TIFF;
// InputError for PNG).
void writeRawRows(const std::string& path, int width, int height, int channels,
                  const std::vector<std::string>& channelNames, const ImageRowFn& row);

// Writes interleaved RGB in [0, 1] as 8- or 16-bit PNG/TIFF. Written to a
// temporary file and renamed, so a failed write leaves no half-written image.
void writeRgbImage(const std::string& path, const std::vector<float>& rgb, int width, int height,
                   int bitDepth);

// Writes one channel in [0, 1] as an 8- or 16-bit grey PNG/TIFF (or float EXR),
// atomically like writeRgbImage.
void writeGreyImage(const std::string& path, const std::vector<float>& grey, int width, int height,
                    int bitDepth);

// Writes the raw float concentrations, one channel per chemical with its name
// (OpenEXR, or float TIFF).
void writeRawImage(const std::string& path, const State& state,
                   const std::vector<std::string>& channelNames);

} // namespace morphogen

namespace morphogen {

// Refuses an image whose header declares a size past the limits
// (kMaxImageSide per side, kMaxImagePixels in all, kMaxImageChannels), an
// empty one or a volume: the readers call it before decoding any pixel.
// Throws InputError naming the file and the accepted sizes.
void checkImageSize(const std::string& path, long long width, long long height, long long depth,
                    long long channels);

// Opens an image the run will read and checks its header (checkImageSize)
// without decoding it: a missing, unreadable or oversized image is an
// InputError before the run instead of at the start of its segment.
void checkImageFile(const std::string& path);

// Loads an image's luminance (Rec. 709 weights over its first three
// channels, or its only channel) resampled to width x height, row 0 at the
// top, values as stored (0..1 for 8/16-bit files). Throws InputError naming
// the file for a missing, unreadable or empty image.
std::vector<float> loadLuminance(const std::string& path, int width, int height);

// A raw state written by writeRawImage (.exr or float .tif): one plane per
// channel, row 0 at the top, with the file's channel names. Throws InputError
// naming the file for a missing or unreadable image.
struct RawImage {
    State state;
    std::vector<std::string> channelNames;
};
RawImage readRawImage(const std::string& path);

} // namespace morphogen
