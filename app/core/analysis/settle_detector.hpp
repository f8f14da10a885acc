#pragma once

#include <vector>

#include "core/base/state.hpp"

namespace morphogen {

// Whether a pattern has settled (issue: finished patterns): the bench's
// convergence test generalised. At each check it counts the features of one
// chemical (featureCount) and measures how much the chemical changed since
// the previous check: the mean absolute change over the plane's range
// (max - min). Settled: both stable over `window` consecutive checks.
class SettleDetector {
public:
    struct Rule {
        int window = 3;
        // Relative; a drift of two features always passes (labyrinth walls
        // join and split by one or two as they straighten).
        double featureTolerance = 0.03;
        // Mean |change| per check over the plane's range. Measured on the
        // presets (checks 1/40 of their steps apart): chaos and waves change
        // 5-13% per check for ever; growing fronts 1-4%; a labyrinth that
        // has filled its grid creeps by 0.2-0.3%, Turing spots fade below
        // 0.4% once their count is fixed.
        double changeTolerance = 0.005;
    };

    SettleDetector(int chemical, bool periodic, Rule rule);
    SettleDetector(int chemical, bool periodic) : SettleDetector(chemical, periodic, Rule{}) {}

    // Takes the state at the next check; true once settled.
    bool check(const State& state);

    int checks() const { return m_checks; }
    int stableChecks() const { return m_stable; }
    int window() const { return m_rule.window; }
    int features() const { return m_features; }
    // The last check's relative change (0 before the second check).
    double change() const { return m_change; }
    double changeTolerance() const { return m_rule.changeTolerance; }

private:
    int m_chemical;
    bool m_periodic;
    Rule m_rule;
    std::vector<float> m_previous;
    int m_checks = 0;
    int m_stable = 0;
    int m_features = -1;
    double m_change = 0;
};

} // namespace morphogen
