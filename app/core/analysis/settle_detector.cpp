#include "core/analysis/settle_detector.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdlib>

#include "core/analysis/pattern_stats.hpp"

namespace morphogen {

SettleDetector::SettleDetector(int chemical, bool periodic, Rule rule)
    : m_chemical(chemical), m_periodic(periodic), m_rule(rule) {
    assert(rule.window >= 1);
}

bool SettleDetector::check(const State& state) {
    const float* plane = state.plane(m_chemical);
    const std::size_t n = state.cellCount();
    const int features = featureCount(state, m_chemical, m_periodic);
    bool stable = false;
    if (m_previous.size() == n) {
        const auto [lo, hi] = std::minmax_element(plane, plane + n);
        double sum = 0;
        for (std::size_t i = 0; i < n; ++i)
            sum += std::abs(double(plane[i]) - m_previous[i]);
        const double range = double(*hi) - double(*lo);
        // A flat plane (range ~ 0) has nothing left to change shape.
        m_change = range > 1e-6 ? sum / double(n) / range : 0.0;
        const int drift = std::abs(features - m_features);
        const bool sameFeatures =
            drift <= 2 || drift <= m_rule.featureTolerance * std::max(features, m_features);
        stable = std::isfinite(m_change) && m_change <= m_rule.changeTolerance && sameFeatures;
    }
    m_stable = stable ? m_stable + 1 : 0;
    m_features = features;
    m_previous.assign(plane, plane + n);
    ++m_checks;
    return m_stable >= m_rule.window;
}

} // namespace morphogen
