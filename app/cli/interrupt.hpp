#pragma once

#include <atomic>

namespace morphogen::cli {

// Signals, for the whole process: installed once by main (and by the first
// InterruptGuard). SIGINT outside a guard, SIGTERM and SIGHUP remove the
// temporaries of the files being written (core/io/output_files.hpp), so an
// interrupted write leaves neither a half-written file nor a changed one, and
// then end the process as the signal would. SIGXFSZ is ignored: a write over
// the file-size limit (ulimit -f) fails as an error, whose temporaries go.
void installSignalHandlers();

// How far apart two SIGINTs must be to count as two Ctrl-Cs. One Ctrl-C can
// arrive twice: `timeout -s INT` signals the process and then its process
// group, microseconds apart, and a shell's Ctrl-C reaches every process of a
// pipeline.
constexpr int kRepeatInterruptMs = 1000;

// Ctrl-C for the guard's lifetime: the first SIGINT sets cancelled() (and
// writes `notice` to stderr, when given), so a long command can stop at a safe
// point and still write what it finished; a SIGINT within kRepeatInterruptMs
// of it is the same Ctrl-C and ignored (also after the guard ended, while the
// command exits); a later one removes the temporaries
// and ends the process the usual way. One guard at a time; `notice` must
// outlive it (a string literal).
class InterruptGuard {
public:
    explicit InterruptGuard(const char* notice = nullptr);
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    // For RunOptions::cancel.
    const std::atomic<bool>* flag() const;
    bool cancelled() const { return flag()->load(); }
    // What a first Ctrl-C from now on prints (e.g. once the run is over and
    // only the writing is left).
    void setNotice(const char* notice);
};

} // namespace morphogen::cli
