#include "core/mesh/edge_table.hpp"

#include <algorithm>
#include <deque>
#include <numeric>
#include <utility>

namespace morphogen {

EdgeTable::EdgeTable(const TriangleMesh& mesh) {
    const std::size_t n = mesh.triangles.size();
    m_uses.reserve(3 * n);
    for (std::size_t t = 0; t < n; ++t) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t a = mesh.triangles[t][c];
            const std::uint32_t b = mesh.triangles[t][(c + 1) % 3];
            const std::uint64_t lo = std::min(a, b), hi = std::max(a, b);
            m_uses.push_back({lo << 32 | hi, std::uint32_t(t), std::uint8_t(c), a < b});
        }
    }
    std::sort(m_uses.begin(), m_uses.end(), [](const Use& x, const Use& y) {
        return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
    });
    m_edgeOfCorner.assign(3 * n, 0);
    m_start.clear();
    for (std::size_t i = 0; i < m_uses.size(); ++i) {
        if (i == 0 || m_uses[i].key != m_uses[i - 1].key)
            m_start.push_back(std::uint32_t(i));
        m_edgeOfCorner[3 * std::size_t(m_uses[i].triangle) + m_uses[i].corner] =
            std::uint32_t(m_start.size() - 1);
    }
    m_start.push_back(std::uint32_t(m_uses.size()));
}

PieceOrientation orientPieces(const TriangleMesh& mesh, const EdgeTable& edges) {
    const std::size_t n = mesh.triangles.size();
    constexpr std::uint32_t kUnreached = ~0u;
    PieceOrientation o;
    o.flip.assign(n, 0);
    o.piece.assign(n, kUnreached);
    std::vector<std::uint32_t> members;
    std::deque<std::uint32_t> queue;
    for (std::size_t seed = 0; seed < n; ++seed) {
        if (o.piece[seed] != kUnreached)
            continue;
        const std::uint32_t id = std::uint32_t(o.orientable.size());
        o.orientable.push_back(1);
        members.clear();
        o.piece[seed] = id;
        queue.push_back(std::uint32_t(seed));
        while (!queue.empty()) {
            const std::uint32_t t = queue.front();
            queue.pop_front();
            members.push_back(t);
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t e = edges.edgeOf(t, c);
                if (edges.useCount(e) != 2)
                    continue; // boundary or non-manifold: no one neighbour to agree with
                const EdgeTable::Use* a = edges.begin(e);
                const EdgeTable::Use* b = a + 1;
                if (a->triangle != t)
                    std::swap(a, b);
                // Agreeing neighbours run along their shared edge in opposite directions.
                const std::uint8_t wanted = o.flip[t] ^ std::uint8_t(a->forward == b->forward);
                if (o.piece[b->triangle] == kUnreached) {
                    o.piece[b->triangle] = id;
                    o.flip[b->triangle] = wanted;
                    queue.push_back(b->triangle);
                } else if (o.flip[b->triangle] != wanted) {
                    o.orientable[id] = 0;
                }
            }
        }
        std::size_t flipped = 0;
        for (std::uint32_t t : members)
            flipped += o.flip[t];
        if (2 * flipped > members.size()) {
            for (std::uint32_t t : members)
                o.flip[t] ^= 1;
            flipped = members.size() - flipped;
        }
        o.flipped += flipped;
    }
    return o;
}

UnionFind::UnionFind(std::size_t n) : m_parent(n), m_size(n, 1) {
    std::iota(m_parent.begin(), m_parent.end(), 0u);
}

std::uint32_t UnionFind::find(std::uint32_t i) {
    while (m_parent[i] != i) {
        m_parent[i] = m_parent[m_parent[i]];
        i = m_parent[i];
    }
    return i;
}

void UnionFind::unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b)
        return;
    if (m_size[a] < m_size[b])
        std::swap(a, b);
    m_parent[b] = a;
    m_size[a] += m_size[b];
}

} // namespace morphogen
