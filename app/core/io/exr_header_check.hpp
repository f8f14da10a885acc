#pragma once

#include <string>

namespace morphogen {

// For a file that starts with OpenEXR's magic number: walks its header's
// attributes (name, type, byte count) and throws InputError naming the file
// and the attribute when one declares more bytes than the file has left.
// Why: OpenEXR allocates and clears an attribute's declared size before it
// reads it, so a corrupt count (found by image_fuzzer: a "string" attribute of
// 1.7 GB in a 250-byte file) costs seconds and gigabytes before any of our
// size checks can run. Other files are left to the image library.
void checkExrAttributeSizes(const std::string& path);

} // namespace morphogen
