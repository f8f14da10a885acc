#pragma once

#include <atomic>

namespace morphogen::cli {

// Ctrl-C for the guard's lifetime: the first SIGINT sets cancelled() (and
// writes `notice` to stderr, when given), so a long command can stop at a safe
// point and still write what it finished; a second SIGINT ends the process the
// usual way. The previous handler is restored on destruction. One guard at a
// time; `notice` must outlive it (a string literal).
class InterruptGuard {
public:
    explicit InterruptGuard(const char* notice = nullptr);
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // For RunOptions::cancel.
    const std::atomic<bool>* flag() const;
    bool cancelled() const { return flag()->load(); }

private:
    void (*m_previous)(int);
};

} // namespace morphogen::cli
