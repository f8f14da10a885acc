#pragma once
// Memory a run needs, checked before it starts: a run that cannot fit is
// refused at once with the figures (InputError, exit 2) instead of failing
// with a bare std::bad_alloc after seconds of work.

#include <cstdint>
#include <optional>
#include <string>

namespace morphogen {

// Bytes this process may still allocate: the smallest of its address-space
// and data limits (ulimit -v, ulimit -d) less what it already uses, and the
// machine's available memory and swap (/proc/meminfo). nullopt: unknown.
std::optional<std::uint64_t> allocatableBytes();

// Throws InputError when `bytes`, the least that `what` needs (e.g. "a
// 8192x8192 grid of 2 chemicals"), is more than allocatableBytes().
void requireMemory(std::uint64_t bytes, const std::string& what);

// "1.5 GiB", "600 MiB", "12 KiB".
std::string formatBytes(std::uint64_t bytes);

// What the process is running, for an out-of-memory message that cannot
// otherwise say (main's handler of std::bad_alloc): set by each run as it
// starts; "" when nothing is.
void setCurrentWorkload(const std::string& description);
std::string currentWorkload();

} // namespace morphogen
