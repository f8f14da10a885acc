#pragma once

#include <cassert>
#include <cstddef>
#include <vector>

namespace morphogen {

// The most chemicals a model may have (both backends size their per-chemical
// arrays by it): Witkin-Kass's five-direction systems need 10. The GPU packs
// four chemicals per state texture, so 12 is three textures written at once.
constexpr int kMaxChemicals = 12;

// Chemical concentrations on a grid, one plane per chemical (structure of
// arrays: the CPU backend's row loops vectorise over planes).
class State {
public:
    State() = default;
    State(int width, int height, int channels)
        : m_width(width), m_height(height), m_channels(channels),
          m_data(std::size_t(width) * height * channels, 0.0f) {}

    int width() const { return m_width; }
    int height() const { return m_height; }
    int channels() const { return m_channels; }
    std::size_t cellCount() const { return std::size_t(m_width) * m_height; }

    float* plane(int c) {
        assert(c >= 0 && c < m_channels);
        return m_data.data() + c * cellCount();
    }
    const float* plane(int c) const {
        assert(c >= 0 && c < m_channels);
        return m_data.data() + c * cellCount();
    }
    float at(int c, int x, int y) const { return plane(c)[std::size_t(y) * m_width + x]; }
    float& at(int c, int x, int y) { return plane(c)[std::size_t(y) * m_width + x]; }

    // Interleaved RGBA floats of channels first..first+3 (missing ones are 0),
    // the layout of the GPU's state texture number first / 4.
    std::vector<float> toRgba(int first = 0) const;
    // The inverse: fills channels first..first+3 (those that exist) from rgba.
    void setRgba(const std::vector<float>& rgba, int first = 0);
    static State fromRgba(const std::vector<float>& rgba, int width, int height, int channels);

    bool operator==(const State& other) const {
        return m_width == other.m_width && m_height == other.m_height &&
               m_channels == other.m_channels && m_data == other.m_data;
    }

private:
    int m_width = 0;
    int m_height = 0;
    int m_channels = 0;
    std::vector<float> m_data;
};

} // namespace morphogen
