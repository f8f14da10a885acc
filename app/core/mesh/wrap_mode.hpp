#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace morphogen {

// When a mesh is replaced by its alpha wrap (mesh_wrap.hpp).
enum class WrapMode {
    Automatic, // when the welded or the repaired mesh looks like a soup (looksLikeSoup)
    Always,
    Never,
};
std::optional<WrapMode> parseWrapMode(std::string_view text); // "auto", "always", "never"
std::string toString(WrapMode mode);
std::string wrapModeNames(); // "auto, always, never"

} // namespace morphogen
