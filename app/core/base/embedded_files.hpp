#pragma once
// Files from glsl/ and models/presets/, compiled into the binary (cmake/embed.cmake).

#include <optional>
#include <string_view>
#include <vector>

namespace morphogen {

// The contents of an embedded file by its path relative to the source root
// ("glsl/step.frag"), or nullopt.
std::optional<std::string_view> embeddedFile(std::string_view path);

// Paths of the embedded files that start with prefix, in a stable order.
std::vector<std::string_view> embeddedFiles(std::string_view prefix);

} // namespace morphogen
