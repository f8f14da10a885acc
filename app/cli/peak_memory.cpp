#include "cli/peak_memory.hpp"

#include <cstdlib>
#include <fstream>
#include <string>

namespace morphogen::cli {

namespace {

// This process's peak resident memory in kB (the high-water mark of its
// address space since exec), or -1 where /proc is not there.
long long peakResidentKb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0)
            return std::atoll(line.c_str() + 6);
    return -1;
}

void writePeak() {
    if (const char* path = std::getenv(kPeakMemoryEnv)) {
        std::ofstream out(path);
        out << peakResidentKb() << "\n";
    }
}

} // namespace

void writePeakMemoryAtExit() {
    if (std::getenv(kPeakMemoryEnv))
        std::atexit(writePeak);
}

} // namespace morphogen::cli
