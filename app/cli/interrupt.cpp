#include "cli/interrupt.hpp"

#include <cassert>
#include <csignal>
#include <cstring>
#include <ctime>
#include <unistd.h>

#include "core/io/output_files.hpp"

namespace morphogen::cli {

namespace {

std::atomic<bool> g_installed{false};
std::atomic<bool> g_guarded{false};
std::atomic<bool> g_interrupted{false};
std::atomic<long long> g_firstInterruptMs{0};
std::atomic<const char*> g_notice{nullptr};

long long monotonicMs() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t); // async-signal-safe
    return (long long)t.tv_sec * 1000 + t.tv_nsec / 1000000;
}

// Only async-signal-safe calls here: write(2), not stdio; unlink and rmdir
// (removeTemporariesForSignal); sigaction and raise.
extern "C" void onSignal(int sig) {
    // Once a Ctrl-C was taken, its repeat is ignored even after the guard
    // ended: the command is writing what it finished or exiting with 1, and
    // a second delivery of the same Ctrl-C (timeout -s INT, a pipeline)
    // there ended it with 130.
    if (sig == SIGINT && (g_guarded.load() || g_interrupted.load())) {
        const long long now = monotonicMs();
        if (!g_interrupted.load()) {
            g_firstInterruptMs.store(now);
            g_interrupted.store(true);
            if (const char* notice = g_notice.load()) {
                [[maybe_unused]] const ssize_t n =
                    write(STDERR_FILENO, notice, std::strlen(notice));
            }
            return;
        }
        if (now - g_firstInterruptMs.load() < kRepeatInterruptMs)
            return; // the same Ctrl-C, delivered once more
    }
    removeTemporariesForSignal();
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, nullptr);
    // Blocked while this handler runs: delivered, with its default action
    // (the process ends), as it returns.
    raise(sig);
}

} // namespace

void installSignalHandlers() {
    if (g_installed.exchange(true))
        return;
    struct sigaction action {};
    action.sa_handler = onSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction previous {};
        sigaction(sig, nullptr, &previous);
        // nohup's ignored SIGHUP stays ignored. SIGINT is handled even when
        // inherited as ignored (a background job of a script), as before:
        // `kill -INT` is how a script stops a run and keeps its work.
        if (sig != SIGHUP || previous.sa_handler != SIG_IGN)
            sigaction(sig, &action, nullptr);
    }
    std::signal(SIGXFSZ, SIG_IGN);
}

InterruptGuard::InterruptGuard(const char* notice) {
    installSignalHandlers();
    assert(!g_guarded.load() && "one InterruptGuard at a time");
    g_interrupted.store(false);
    g_notice.store(notice);
    g_guarded.store(true);
}

InterruptGuard::~InterruptGuard() {
    g_guarded.store(false);
    g_notice.store(nullptr);
}

const std::atomic<bool>* InterruptGuard::flag() const {
    return &g_interrupted;
}

void InterruptGuard::setNotice(const char* notice) {
    g_notice.store(notice);
}

} // namespace morphogen::cli
