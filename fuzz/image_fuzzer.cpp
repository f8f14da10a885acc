// Fuzz target: the image readers, fed the input as a file. readRawImage reads
// the raw state `colour` recolours; loadLuminance reads every image a session
// names (parameter maps, orientation fields, diffusion maps) and resamples it
// to the grid. OpenImageIO picks the reader by the file's content (the name has
// no extension), so every format it reads is reached. Found and failed on: a
// crash, hang or sanitizer report, an exception other than InputError, and a
// luminance that is not finite or not the size asked for.
//
// OpenImageIO and the codecs are Debian's uninstrumented libraries: libFuzzer
// sees coverage in our code only, so this target mostly checks what we do
// with what the library returns (header sizes, channel counts, allocation).

#include <cmath>
#include <cstdint>
#include <exception>
#include <string>
#include <typeinfo>

#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "fuzz_support.hpp"

namespace {

namespace fuzz = morphogen::fuzz;

std::string describe(const std::exception& e) {
    return std::string(typeid(e).name()) + ": " + e.what();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "input");
    try {
        const morphogen::RawImage raw = morphogen::readRawImage(path);
        if (raw.state.width() < 1 || raw.state.height() < 1 || raw.state.channels() < 1)
            fuzz::fail("readRawImage returned an empty state");
    } catch (const morphogen::InputError&) {
    } catch (const std::exception& e) {
        fuzz::fail("readRawImage threw " + describe(e) + " instead of an InputError");
    }

    // An odd, small grid: resampling up and down, with a remainder.
    constexpr int width = 13, height = 7;
    try {
        const std::vector<float> l = morphogen::loadLuminance(path, width, height);
        if (l.size() != std::size_t(width) * height)
            fuzz::fail("loadLuminance returned " + std::to_string(l.size()) + " values for " +
                       std::to_string(width) + "x" + std::to_string(height));
        for (float v : l)
            if (!std::isfinite(v))
                fuzz::fail("loadLuminance returned a value that is not finite");
    } catch (const morphogen::InputError&) {
    } catch (const std::exception& e) {
        fuzz::fail("loadLuminance threw " + describe(e) + " instead of an InputError");
    }
    return 0;
}
