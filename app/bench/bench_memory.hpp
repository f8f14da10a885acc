#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// What the memory rows of `morphogen bench` render.
struct MemoryBench {
    std::vector<int> sizes;            // grid sides, one row per size and backend
    std::string preset;                // not a cascade (its stages set their own steps)
    std::vector<std::string> backends; // "cpu", "gpu"
    std::string context;               // passed on to the renders (--context), may be empty
    std::string gpuDevice;             // --gpu-device, may be empty
};

// Steps of each measured render: memory, not the pattern, is the point.
constexpr int kMemoryBenchSteps = 10;

// The memory rows, printed and returned as JSON: the peak resident memory of
// a `morphogen render --out x.png` of the preset at each size, each run in a
// child process of this executable, against the state it simulates (cells x
// chemicals x 4 bytes). The child reports its own peak (VmHWM, see
// cli/peak_memory.hpp): wait4's ru_maxrss would be at least the bench's
// own peak, which Linux carries into a child at exec. The same render at 16x16
// gives the process's fixed cost (libraries, the GL driver), so a row reports
// both its peak over the state and its growth above that baseline over the
// state (the render's own memory; the goal is about 3 or less).
nlohmann::json benchMemory(const MemoryBench& bench);

} // namespace morphogen::bench
