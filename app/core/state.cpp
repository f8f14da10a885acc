#include "core/state.hpp"

namespace morphogen {

std::vector<float> State::toRgba() const {
    std::vector<float> rgba(cellCount() * 4, 0.0f);
    for (int c = 0; c < m_channels && c < 4; ++c) {
        const float* p = plane(c);
        for (std::size_t i = 0; i < cellCount(); ++i)
            rgba[i * 4 + std::size_t(c)] = p[i];
    }
    return rgba;
}

State State::fromRgba(const std::vector<float>& rgba, int width, int height, int channels) {
    State state(width, height, channels);
    assert(rgba.size() == state.cellCount() * 4);
    for (int c = 0; c < channels && c < 4; ++c) {
        float* p = state.plane(c);
        for (std::size_t i = 0; i < state.cellCount(); ++i)
            p[i] = rgba[i * 4 + std::size_t(c)];
    }
    return state;
}

} // namespace morphogen
