#include "core/domain/tile_sets.hpp"

#include <algorithm>
#include <numeric>

#include "core/domain/atlas.hpp"

namespace morphogen {

namespace {

int find(std::vector<int>& parent, int i) {
    while (parent[std::size_t(i)] != i) {
        parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
        i = parent[std::size_t(i)];
    }
    return i;
}

void unite(std::vector<int>& parent, int a, int b) {
    a = find(parent, a);
    b = find(parent, b);
    if (a != b)
        parent[std::size_t(std::max(a, b))] = std::min(a, b);
}

} // namespace

TileNeighbourhoods::TileNeighbourhoods(const Atlas& atlas) {
    const int tiles = atlas.tileCount();
    std::vector<int> parent(std::size_t(4 * tiles));
    std::iota(parent.begin(), parent.end(), 0);
    const auto slot = [](int tile, int corner) { return 4 * tile + (corner % 4); };
    for (int a = 0; a < tiles; ++a)
        for (int ea = 0; ea < 4; ++ea) {
            const AtlasLink& l = atlas.link(a, TileEdge(ea));
            if (!l.glued)
                continue;
            const int eb = int(l.edge);
            const int aStart = slot(a, ea + 1), aEnd = slot(a, ea + 2);
            const int bStart = slot(l.tile, eb + 1), bEnd = slot(l.tile, eb + 2);
            unite(parent, aStart, l.reversed ? bStart : bEnd);
            unite(parent, aEnd, l.reversed ? bEnd : bStart);
        }
    m_vertex.resize(parent.size());
    std::vector<int> id(parent.size(), -1);
    for (std::size_t i = 0; i < parent.size(); ++i) {
        const int root = find(parent, int(i));
        if (id[std::size_t(root)] < 0)
            id[std::size_t(root)] = m_vertexCount++;
        m_vertex[i] = id[std::size_t(root)];
    }
    std::vector<std::vector<int>> tilesAt(static_cast<std::size_t>(m_vertexCount));
    for (int t = 0; t < tiles; ++t)
        for (int c = 0; c < 4; ++c)
            tilesAt[std::size_t(vertex(t, c))].push_back(t);
    m_neighbours.resize(std::size_t(tiles));
    for (int t = 0; t < tiles; ++t) {
        std::vector<int>& n = m_neighbours[std::size_t(t)];
        for (int c = 0; c < 4; ++c) {
            const std::vector<int>& at = tilesAt[std::size_t(vertex(t, c))];
            n.insert(n.end(), at.begin(), at.end());
        }
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
    }
}

std::vector<int> TileNeighbourhoods::grow(const std::vector<int>& tiles) const {
    std::vector<char> in(m_neighbours.size(), 0);
    for (int t : tiles)
        if (t >= 0 && t < tileCount())
            for (int n : of(t))
                in[std::size_t(n)] = 1;
    std::vector<int> out;
    for (std::size_t t = 0; t < in.size(); ++t)
        if (in[t])
            out.push_back(int(t));
    return out;
}

} // namespace morphogen
