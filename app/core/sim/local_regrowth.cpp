#include "core/sim/local_regrowth.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/domain/atlas.hpp"

namespace morphogen {

namespace {

// The schedule's own (step-counted) growth is not used: checks grow the set.
constexpr int kNeverOnItsOwn = 1 << 30;

} // namespace

float maxChangePerStep(const State& now, const State& before, int steps) {
    assert(now.channels() == before.channels() && now.cellCount() == before.cellCount());
    float worst = 0;
    for (int c = 0; c < now.channels(); ++c) {
        const float* a = now.plane(c);
        const float* b = before.plane(c);
        for (std::size_t i = 0; i < now.cellCount(); ++i)
            worst = std::max(worst, std::fabs(a[i] - b[i]));
    }
    return worst / float(std::max(1, steps));
}

float maxChangePerStep(const State& now, const State& before, int steps, const Atlas& atlas,
                       const std::vector<int>& tiles) {
    assert(now.channels() == before.channels() && now.cellCount() == before.cellCount());
    float worst = 0;
    for (int c = 0; c < now.channels(); ++c) {
        const float* a = now.plane(c);
        const float* b = before.plane(c);
        for (int t : tiles)
            for (int v = 0; v < atlas.tileSize(); ++v)
                for (int u = 0; u < atlas.tileSize(); ++u) {
                    const std::uint32_t i = atlas.tileCell(t, u, v);
                    worst = std::max(worst, std::fabs(a[i] - b[i]));
                }
    }
    return worst / float(std::max(1, steps));
}

LocalRegrowth::LocalRegrowth(std::shared_ptr<const TileNeighbourhoods> neighbourhoods,
                             std::shared_ptr<const Atlas> atlas, const std::vector<int>& touched,
                             const LocalRegrowthOptions& options)
    : m_neighbourhoods(std::move(neighbourhoods)), m_options(options), m_atlas(std::move(atlas)),
      m_schedule(*m_neighbourhoods, touched, kNeverOnItsOwn, options.globalFraction) {
    assert(!touched.empty() && options.checkEvery >= 1 && m_atlas);
    m_over = m_schedule.global();
}

void LocalRegrowth::touch(const std::vector<int>& touched) {
    if (m_over) {
        m_schedule = ActiveTileSchedule(*m_neighbourhoods, touched, kNeverOnItsOwn,
                                        m_options.globalFraction);
        m_phase = 1;
    } else
        m_schedule.add(touched);
    m_over = m_schedule.global();
    m_settled = false;
    m_sinceCheck = 0;
    m_previous.reset();
}

int LocalRegrowth::stepsBeforeChange() const {
    return m_over ? kNeverOnItsOwn : std::max(1, m_options.checkEvery - m_sinceCheck);
}

bool LocalRegrowth::stepped(int steps, const std::function<State()>& readState) {
    if (m_over)
        return false;
    assert(steps >= 1 && steps <= stepsBeforeChange());
    m_sinceCheck += steps;
    if (m_sinceCheck < m_options.checkEvery)
        return false;
    State now = readState();
    bool changed = false;
    // The first check after a change only takes the reference.
    if (m_previous) {
        const std::vector<int>& set = m_schedule.tiles();
        if (maxChangePerStep(now, *m_previous, m_sinceCheck) < m_options.settledBelow) {
            m_over = m_settled = true;
            changed = true;
        } else {
            std::vector<int> ring;
            for (int t : set) {
                const std::vector<int>& around = m_neighbourhoods->of(t);
                if (std::any_of(around.begin(), around.end(), [&](int n) {
                        return !std::binary_search(set.begin(), set.end(), n);
                    }))
                    ring.push_back(t);
            }
            if (maxChangePerStep(now, *m_previous, m_sinceCheck, *m_atlas, ring) >
                m_options.spreadAbove) {
                m_schedule.add(set); // N(A_k)
                ++m_phase;
                m_over = m_schedule.global();
                changed = true;
            }
        }
    }
    m_previous = std::move(now);
    m_sinceCheck = 0;
    return changed;
}

} // namespace morphogen
