#include "core/base/state.hpp"

namespace morphogen {

std::vector<float> State::toRgba(int first) const {
    std::vector<float> rgba(cellCount() * 4, 0.0f);
    for (int k = 0; k < 4 && first + k < m_channels; ++k) {
        const float* p = plane(first + k);
        for (std::size_t i = 0; i < cellCount(); ++i)
            rgba[i * 4 + std::size_t(k)] = p[i];
    }
    return rgba;
}

void State::setRgba(const std::vector<float>& rgba, int first) {
    assert(rgba.size() == cellCount() * 4);
    for (int k = 0; k < 4 && first + k < m_channels; ++k) {
        float* p = plane(first + k);
        for (std::size_t i = 0; i < cellCount(); ++i)
            p[i] = rgba[i * 4 + std::size_t(k)];
    }
}

State State::fromRgba(const std::vector<float>& rgba, int width, int height, int channels) {
    State state(width, height, channels);
    state.setRgba(rgba, 0);
    return state;
}

} // namespace morphogen
