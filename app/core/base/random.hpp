#pragma once

#include <cstdint>

namespace morphogen {

// Counter-based random numbers: the value for (seed, stream, index) does not
// depend on evaluation order, so threaded initialisation is reproducible.
inline std::uint64_t mixBits(std::uint64_t x) {
    // splitmix64 finaliser
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Uniform in [0, 1).
inline double uniform01(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
    std::uint64_t h = mixBits(seed ^ mixBits(stream * 0x632be59bd9b4e019ull ^ mixBits(index)));
    return double(h >> 11) * (1.0 / 9007199254740992.0);
}

// Uniform in [-1, 1).
inline double uniformSigned(std::uint64_t seed, std::uint64_t stream, std::uint64_t index) {
    return 2.0 * uniform01(seed, stream, index) - 1.0;
}

} // namespace morphogen
