#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace morphogen::fuzz {

// Writes the input to `name` in a private temporary folder (made once per
// process, removed at exit) and returns its path. The readers under test take
// paths, and going through a file keeps every check they make before parsing
// (size, existence) in the fuzzed path.
std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name);
std::string writeInput(const std::string& text, const std::string& name);

// The private temporary folder itself.
const std::string& scratchDir();

// Stops the process with the input's finding on stderr: libFuzzer saves the
// input as a crash, a replay test fails.
[[noreturn]] void fail(const std::string& what);

} // namespace morphogen::fuzz
