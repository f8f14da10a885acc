#include "cli/interrupt.hpp"

#include <cassert>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace morphogen::cli {

namespace {

std::atomic<bool> g_interrupted{false};
std::atomic<const char*> g_notice{nullptr};
bool g_guarded = false;

extern "C" void onInterrupt(int) {
    g_interrupted.store(true);
    // Only async-signal-safe calls here: write(2), not stdio.
    if (const char* notice = g_notice.load()) {
        [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, notice, std::strlen(notice));
    }
    // A second Ctrl-C ends the process the usual way.
    std::signal(SIGINT, SIG_DFL);
}

} // namespace

InterruptGuard::InterruptGuard(const char* notice) {
    assert(!g_guarded && "one InterruptGuard at a time");
    g_guarded = true;
    g_interrupted.store(false);
    g_notice.store(notice);
    m_previous = std::signal(SIGINT, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
    std::signal(SIGINT, m_previous);
    g_notice.store(nullptr);
    g_guarded = false;
}

const std::atomic<bool>* InterruptGuard::flag() const {
    return &g_interrupted;
}

} // namespace morphogen::cli
