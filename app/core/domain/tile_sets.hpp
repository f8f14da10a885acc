#pragma once

#include <vector>

namespace morphogen {

class Atlas;

// Tile neighbourhoods of an atlas for localized reaction-diffusion (Lo et al.
// section 4): two tiles are neighbours when they share a vertex of the glued
// surface (a corner, not only an edge), and N(S) is S with every neighbour of
// a tile of S.
//
// The vertices come from the gluing: gluing edge ea of tile a to edge eb of
// tile b identifies the corners at their ends (edge e runs from corner e+1 to
// corner e+2, atlas.hpp): a proper gluing meets ea's start with eb's end and
// ea's end with eb's start, a reversed one start with start and end with end.
// The classes of corners under these identifications are the vertices; going
// round one class is the corner valence walk of Atlas::cornerValence, and a
// class has cornerValence(tile, corner) corners.
class TileNeighbourhoods {
public:
    explicit TileNeighbourhoods(const Atlas& atlas);

    int tileCount() const { return int(m_neighbours.size()); }
    int vertexCount() const { return m_vertexCount; }
    // The vertex (0..vertexCount()-1) at corner 0..3 of a tile.
    int vertex(int tile, int corner) const { return m_vertex[std::size_t(4 * tile + corner)]; }
    // The tiles sharing a vertex with `tile`, itself included, ascending.
    const std::vector<int>& of(int tile) const { return m_neighbours[std::size_t(tile)]; }
    // N(S): ascending, S included. Tiles out of range are ignored.
    std::vector<int> grow(const std::vector<int>& tiles) const;

private:
    std::vector<int> m_vertex;
    int m_vertexCount = 0;
    std::vector<std::vector<int>> m_neighbours;
};

} // namespace morphogen
