#pragma once

#include <chrono>
#include <string>

namespace morphogen::cli {

// A progress line on stderr. On a terminal it redraws one line in place (at
// most ten times a second); otherwise it prints a line every 10%, so logs stay
// readable.
class Progress {
public:
    Progress(std::string label, int total);
    void update(int done);
    // Text shown after the counts from the next update on (e.g. how close a
    // pattern is to settled).
    void setNote(std::string note) { m_note = std::move(note); }
    // Ends the line (terminal) and prints a summary.
    void finish(const std::string& summary);

private:
    std::string m_label;
    std::string m_note;
    int m_total;
    bool m_tty;
    int m_lastDecile = -1;
    std::chrono::steady_clock::time_point m_start;
    std::chrono::steady_clock::time_point m_lastDraw;
};

} // namespace morphogen::cli
