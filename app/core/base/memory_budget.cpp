#include "core/base/memory_budget.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <sstream>

#include <sys/resource.h>

#include "core/base/errors.hpp"

namespace morphogen {

namespace {

// A "Key:  1234 kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> procKilobytes(const char* file, const std::string& key) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind(key + ":", 0) == 0) {
            std::istringstream fields(line.substr(key.size() + 1));
            std::uint64_t kb = 0;
            if (fields >> kb)
                return kb * 1024;
        }
    return std::nullopt;
}

std::optional<std::uint64_t> limitLeft(int resource, std::optional<std::uint64_t> used) {
    rlimit limit{};
    if (::getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY || !used)
        return std::nullopt;
    const std::uint64_t cap = std::uint64_t(limit.rlim_cur);
    return cap > *used ? cap - *used : 0;
}

std::mutex g_workloadMutex;
std::string g_workload;

} // namespace

std::optional<std::uint64_t> allocatableBytes() {
    std::optional<std::uint64_t> least;
    const auto consider = [&](std::optional<std::uint64_t> v) {
        if (v)
            least = least ? std::min(*least, *v) : *v;
    };
    consider(limitLeft(RLIMIT_AS, procKilobytes("/proc/self/status", "VmSize")));
    consider(limitLeft(RLIMIT_DATA, procKilobytes("/proc/self/status", "VmData")));
    const auto available = procKilobytes("/proc/meminfo", "MemAvailable");
    const auto swap = procKilobytes("/proc/meminfo", "SwapFree");
    if (available)
        consider(*available + swap.value_or(0));
    return least;
}

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
    double v = double(bytes);
    int unit = 0;
    while (v >= 1024 && unit < 4) {
        v /= 1024;
        ++unit;
    }
    char text[32];
    std::snprintf(text, sizeof text, unit == 0 || v >= 100 ? "%.0f %s" : "%.1f %s", v, units[unit]);
    return text;
}

void requireMemory(std::uint64_t bytes, const std::string& what) {
    const std::optional<std::uint64_t> left = allocatableBytes();
    if (!left || bytes <= *left)
        return;
    throw InputError(what + " needs at least " + formatBytes(bytes) + ", more than the " +
                     formatBytes(*left) +
                     " this process may still allocate (the smallest of ulimit -v, ulimit -d "
                     "and the memory available); use a smaller size or free memory");
}

void setCurrentWorkload(const std::string& description) {
    const std::lock_guard<std::mutex> lock(g_workloadMutex);
    g_workload = description;
}

std::string currentWorkload() {
    const std::lock_guard<std::mutex> lock(g_workloadMutex);
    return g_workload;
}

} // namespace morphogen
