#pragma once

#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "core/analysis/settle_detector.hpp"
#include "core/session/session.hpp"
#include "core/sim/runner.hpp"

namespace morphogen::cli {

class Progress;

// Until settled (issue: finished patterns): the default for presets, so a
// preset at any size comes out finished; a session file runs as written
// unless --until-settled is given.
struct SettleFlags {
    bool untilSettled = false;
    bool noSettle = false;
    std::string maxSteps; // cap on the last stage or level, in session steps (empty: not given)
};

void addSettleFlags(CLI::App& command, SettleFlags& flags);

// A settle check on a run: the session's last stage or level runs up to its
// cap and stops once the pattern has settled.
class SettleRun {
public:
    // Decides whether the run settles (presets do unless --steps or
    // --no-settle, or they have gravity) and, when it does, sets the cap in
    // `session`.
    SettleRun(const SettleFlags& flags, Session& session, bool preset, bool stepsGiven);

    bool active() const { return m_detector != nullptr; }
    // Wires the check into `options`; the note on `progress` says how close it is.
    void attach(RunOptions& options, Progress& progress);
    // One line for the report after the run, and whether it is a warning.
    std::string summary(const RunResult& result, bool& warning) const;

private:
    std::unique_ptr<SettleDetector> m_detector;
    int m_every = 0;
    int m_after = 0;
    int m_cap = 0;
};

} // namespace morphogen::cli
