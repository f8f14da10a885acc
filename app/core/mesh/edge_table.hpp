#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/triangle_mesh.hpp"

namespace morphogen {

// The mesh's undirected edges and, for each, the triangle corners that use it
// (corner c of triangle t uses the edge from its vertex c to vertex c + 1).
// Built by sorting, so edge ids are ordered by (smaller vertex, larger vertex).
class EdgeTable {
public:
    explicit EdgeTable(const TriangleMesh& mesh);

    struct Use {
        std::uint64_t key; // smaller vertex << 32 | larger vertex
        std::uint32_t triangle;
        std::uint8_t corner;
        bool forward; // runs from the smaller vertex to the larger
    };

    std::size_t edgeCount() const { return m_start.size() - 1; }
    // The uses of edge e: [begin, end).
    const Use* begin(std::size_t e) const { return m_uses.data() + m_start[e]; }
    const Use* end(std::size_t e) const { return m_uses.data() + m_start[e + 1]; }
    std::size_t useCount(std::size_t e) const { return m_start[e + 1] - m_start[e]; }
    std::uint32_t lowVertex(std::size_t e) const { return std::uint32_t(begin(e)->key >> 32); }
    std::uint32_t highVertex(std::size_t e) const { return std::uint32_t(begin(e)->key); }
    // The edge that corner c of triangle t uses.
    std::uint32_t edgeOf(std::size_t t, int c) const { return m_edgeOfCorner[3 * t + c]; }

private:
    std::vector<Use> m_uses;
    std::vector<std::uint32_t> m_start;
    std::vector<std::uint32_t> m_edgeOfCorner;
};

// A consistent winding for each piece of triangles joined by edges with exactly
// two triangles (a breadth-first walk from each piece's first triangle; the
// piece is flipped whole when that changes fewer triangles).
struct PieceOrientation {
    std::vector<std::uint8_t> flip;       // per triangle: 1 to reverse it
    std::vector<std::uint32_t> piece;     // per triangle: its piece
    std::vector<std::uint8_t> orientable; // per piece: 0 if some edge could not agree (Moebius)
    std::size_t flipped = 0;              // triangles with flip == 1
};
PieceOrientation orientPieces(const TriangleMesh& mesh, const EdgeTable& edges);

// Disjoint sets with path halving and union by size.
class UnionFind {
public:
    explicit UnionFind(std::size_t n);
    std::uint32_t find(std::uint32_t i);
    void unite(std::uint32_t a, std::uint32_t b);

private:
    std::vector<std::uint32_t> m_parent;
    std::vector<std::uint32_t> m_size;
};

} // namespace morphogen
