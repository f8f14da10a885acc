#include "cli/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace morphogen::cli {

Progress::Progress(std::string label, int total)
    : m_label(std::move(label)), m_total(total), m_tty(isatty(STDERR_FILENO) != 0),
      m_start(std::chrono::steady_clock::now()), m_lastDraw(m_start) {}

void Progress::update(int done) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const double rate = elapsed > 0 ? done / elapsed : 0.0;
    const double eta = rate > 0 ? (m_total - done) / rate : 0.0;
    const int percent = m_total > 0 ? int(100.0 * done / m_total) : 100;
    if (m_tty) {
        if (done < m_total && now - m_lastDraw < std::chrono::milliseconds(100))
            return;
        m_lastDraw = now;
        std::fprintf(stderr, "\r%s %3d%% %d/%d steps, %.0f steps/s, ETA %.0fs%s%s   ",
                     m_label.c_str(), percent, done, m_total, rate, eta, m_note.empty() ? "" : ", ",
                     m_note.c_str());
        std::fflush(stderr);
        return;
    }
    const int decile = percent / 10;
    if (decile == m_lastDecile)
        return;
    m_lastDecile = decile;
    std::fprintf(stderr, "%s %3d%% %d/%d steps, %.0f steps/s%s%s\n", m_label.c_str(), percent, done,
                 m_total, rate, m_note.empty() ? "" : ", ", m_note.c_str());
}

void Progress::finish(const std::string& summary) {
    if (m_tty)
        std::fprintf(stderr, "\n");
    std::fprintf(stderr, "%s %s\n", m_label.c_str(), summary.c_str());
}

} // namespace morphogen::cli
