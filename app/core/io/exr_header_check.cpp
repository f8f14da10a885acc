#include "core/io/exr_header_check.hpp"

#include <cstdint>
#include <fstream>

#include "core/base/errors.hpp"

namespace morphogen {

namespace {

// OpenEXR's names and type names hold at most 255 characters.
constexpr std::size_t kMaxName = 256;
// A sanity bound on attributes per header and headers per file.
constexpr int kMaxAttributes = 100000;
constexpr int kMaxParts = 100000;

bool readName(std::istream& in, std::string& name) {
    name.clear();
    for (std::size_t i = 0; i <= kMaxName; ++i) {
        const int c = in.get();
        if (c == EOF)
            return false;
        if (c == 0)
            return true;
        name.push_back(char(c));
    }
    return false;
}

} // namespace

void checkExrAttributeSizes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return; // the image library reports a file it cannot open
    unsigned char head[8];
    if (!in.read(reinterpret_cast<char*>(head), 8) || head[0] != 0x76 || head[1] != 0x2f ||
        head[2] != 0x31 || head[3] != 0x01)
        return;
    in.seekg(0, std::ios::end);
    const std::int64_t size = std::int64_t(in.tellg());
    in.seekg(8);
    const bool multipart = (head[5] & 0x10) != 0; // version flag 0x1000
    const auto corrupt = [&](const std::string& why) {
        throw InputError(path + ": a corrupt OpenEXR header (" + why +
                         "); accepted are the .exr files render --out writes");
    };
    std::string name, type;
    for (int part = 0; part < kMaxParts; ++part) {
        for (int a = 0;; ++a) {
            if (a == kMaxAttributes)
                corrupt("more than " + std::to_string(kMaxAttributes) + " attributes");
            if (!readName(in, name))
                corrupt("an attribute name that does not end within 255 bytes or the file");
            if (name.empty())
                break; // the end of this header
            if (!readName(in, type))
                corrupt("attribute '" + name + "' has no type name");
            unsigned char count[4];
            if (!in.read(reinterpret_cast<char*>(count), 4))
                corrupt("attribute '" + name + "' is cut off");
            const std::int64_t bytes = std::int64_t(
                std::int32_t(std::uint32_t(count[0]) | std::uint32_t(count[1]) << 8 |
                             std::uint32_t(count[2]) << 16 | std::uint32_t(count[3]) << 24));
            const std::int64_t left = size - std::int64_t(in.tellg());
            if (bytes < 0 || bytes > left)
                corrupt("attribute '" + name + "' of type '" + type + "' declares " +
                        std::to_string(bytes) + " bytes, and the file has " + std::to_string(left) +
                        " left");
            in.seekg(bytes, std::ios::cur);
        }
        // A multi-part file's headers end with an empty one.
        if (!multipart || in.peek() == 0 || in.peek() == EOF)
            return;
    }
    corrupt("more than " + std::to_string(kMaxParts) + " parts");
}

} // namespace morphogen
