#include "cli/settle_flags.hpp"

#include <algorithm>
#include <climits>
#include <cstdio>

#include "cli/flag_values.hpp"
#include "cli/progress.hpp"
#include "core/base/errors.hpp"

namespace morphogen::cli {

namespace {

// The steps of the session's last stage or level (what the settle check ends).
int& lastSegmentSteps(Session& s) {
    if (!s.stages.empty())
        return s.stages.back().steps;
    if (!s.schedule.empty())
        return s.schedule.back().steps;
    return s.steps;
}

long long sessionStepsTotal(const Session& s) {
    long long total = 0;
    for (const Stage& stage : s.stages)
        total += stage.steps;
    for (const ScheduleLevel& level : s.schedule)
        total += level.steps;
    return s.stages.empty() && s.schedule.empty() ? s.steps : total;
}

void recountSteps(Session& s) {
    if (s.stages.empty() && s.schedule.empty())
        return;
    long long total = 0;
    for (const Stage& stage : s.stages)
        total += stage.steps;
    for (const ScheduleLevel& level : s.schedule)
        total += level.steps;
    s.steps = int(std::min<long long>(total, INT_MAX));
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g%%", 100.0 * fraction);
    return text;
}

} // namespace

void addSettleFlags(CLI::App& command, SettleFlags& flags) {
    command.add_flag("--until-settled", flags.untilSettled,
                     "run the last stage until the pattern settles (feature count and change "
                     "both stable), at most --max-steps; the default for presets");
    command.add_flag("--no-settle", flags.noSettle,
                     "run a preset's steps as written instead of until settled");
    command
        .add_option("--max-steps", flags.maxSteps,
                    "until settled: cap on the last stage's steps, 1.." +
                        std::to_string(kMaxSteps) + " (default 3x its steps)")
        ->type_name("N");
}

SettleRun::SettleRun(const SettleFlags& flags, Session& session, bool preset, bool stepsGiven) {
    if (flags.untilSettled && flags.noSettle)
        throw InputError("--until-settled and --no-settle are exclusive: give one");
    const long long maxSteps =
        flags.maxSteps.empty() ? -1 : integerFlag("--max-steps", flags.maxSteps, 1, kMaxSteps);
    // Drops running under gravity move by nature, and their deposits change
    // slowly while they run: a preset with gravity runs its steps as written.
    const bool on = flags.untilSettled ||
                    (preset && !stepsGiven && !flags.noSettle && !session.gravity.active());
    if (!on) {
        if (maxSteps != -1)
            throw InputError("--max-steps applies to a run until settled: add --until-settled");
        return;
    }
    if (session.tiles.active())
        throw InputError("--until-settled does not apply to a batched sweep session");
    int& steps = lastSegmentSteps(session);
    const int nominal = std::max(1, steps);
    // The session's steps in all stay within kMaxSteps, so the session written
    // after the run reads back.
    const long long others = std::max(0LL, sessionStepsTotal(session) - steps);
    const long long room = std::max(1LL, kMaxSteps - others);
    if (maxSteps > room)
        throw InputError("--max-steps " + flags.maxSteps + ": with the " + std::to_string(others) +
                         " steps before the last stage, accepted are 1.." + std::to_string(room) +
                         " (" + std::to_string(kMaxSteps) + " steps in all)");
    m_cap = maxSteps != -1 ? int(maxSteps) : int(std::min(3LL * nominal, room));
    // Checks every 1/40 of the nominal steps; never before half of them, so a
    // slow start (noise decaying before a Turing pattern grows) is not taken
    // for a settled one.
    m_every = std::max(1, nominal / 40);
    m_after = std::min(m_cap, nominal / 2);
    steps = m_cap;
    recountSteps(session);
    const ReactionModel& model = session.outputModel();
    const int chemical = session.colormap.chemical.empty()
                             ? model.displayChemical()
                             : std::max(0, model.chemicalIndex(session.colormap.chemical));
    m_detector = std::make_unique<SettleDetector>(chemical, session.edges == EdgeMode::Periodic);
}

void SettleRun::attach(RunOptions& options, Progress& progress) {
    if (!active())
        return;
    options.settleEvery = m_every;
    options.settleAfter = m_after;
    SettleDetector* detector = m_detector.get();
    options.settled = [detector, &progress](const State& state) {
        const bool settled = detector->check(state);
        progress.setNote("settling: change " + percent(detector->change()) + " (target " +
                         percent(detector->changeTolerance()) + "), " +
                         std::to_string(detector->features()) + " features, stable " +
                         std::to_string(detector->stableChecks()) + "/" +
                         std::to_string(detector->window()));
        return settled;
    };
}

std::string SettleRun::summary(const RunResult& result, bool& warning) const {
    warning = false;
    if (!active() || result.cancelled)
        return {};
    if (result.settled)
        return "settled after " + std::to_string(result.completed.steps) +
               " steps (feature count and change stable over " +
               std::to_string(m_detector->window()) + " checks, last change " +
               percent(m_detector->change()) + " of the range); the session records them";
    warning = true;
    return "did not settle within its cap of " + std::to_string(m_cap) +
           " steps on the last stage (still changing by " + percent(m_detector->change()) +
           " of its range per check, target " + percent(m_detector->changeTolerance()) +
           "): a pattern that moves by nature (waves, chaos, dividing spots) never settles; "
           "otherwise raise --max-steps";
}

} // namespace morphogen::cli
