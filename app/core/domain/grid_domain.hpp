#pragma once

#include <cassert>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace morphogen {

enum class EdgeMode {
    Periodic, // seamless tiling: the grid wraps around
    Clamped,  // zero-flux: a neighbour outside the grid reads the edge cell
};

std::string toString(EdgeMode mode);
// toString's spellings; std::nullopt for others. edgeModeNames() lists them.
std::optional<EdgeMode> parseEdgeMode(std::string_view name);
std::string edgeModeNames();

// A W x H grid of cells with 4-connected neighbours. Both backends address it
// the same way: the CPU wraps or clamps indices, the GPU sets the sampler's
// wrap mode (GL_REPEAT / GL_CLAMP_TO_EDGE). Surface atlases will be a second
// domain with a per-texel connectivity map instead of index arithmetic.
class GridDomain {
public:
    GridDomain() = default;
    GridDomain(int width, int height, EdgeMode edges)
        : m_width(width), m_height(height), m_edges(edges) {
        assert(width > 0 && height > 0);
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    EdgeMode edges() const { return m_edges; }
    std::size_t cellCount() const { return std::size_t(m_width) * std::size_t(m_height); }

    // The neighbour coordinate of i along an axis of length n, one step away.
    static int wrapOrClamp(int i, int n, EdgeMode edges) {
        if (edges == EdgeMode::Periodic)
            return i < 0 ? i + n : (i >= n ? i - n : i);
        return i < 0 ? 0 : (i >= n ? n - 1 : i);
    }

private:
    int m_width = 1;
    int m_height = 1;
    EdgeMode m_edges = EdgeMode::Periodic;
};

} // namespace morphogen
