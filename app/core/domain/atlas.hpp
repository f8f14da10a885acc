#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace morphogen {

// Directions in a tile's own frame: +x, +y, -x, -y (counter-clockwise).
enum class Direction : std::uint8_t { PlusX = 0, PlusY = 1, MinusX = 2, MinusY = 3 };

// One step from a texel: the texel reached, the direction in ITS frame that leads back, and
// whether its frame is mirrored relative to the one we came from (orientation reversed).
struct AtlasStep {
    std::uint32_t cell;
    Direction back;
    bool mirrored;
};

// A tile's edges, in the same order as Direction: stepping in direction d from a texel on the
// tile's border leaves the tile through edge d.
enum class TileEdge : std::uint8_t { PlusX, PlusY, MinusX, MinusY };

// What an edge of a tile is glued to (glued == false: a zero-flux boundary).
struct AtlasLink {
    bool glued = false;
    int tile = -1;
    TileEdge edge = TileEdge::PlusX;
    bool reversed = false;
};

Direction opposite(Direction d);
// "+x", "+y", "-x", "-y": for messages.
std::string toString(Direction d);
std::string toString(TileEdge e);

// The atlas domain (Lo et al., sections 3 and 5.1): square tiles of n x n texels laid out in
// one texture, each texel's four neighbours given by a connectivity map. A texel inside a tile
// has its neighbours at +-1 / +-width; only the tile-border ring goes through the map.
//
// Tile frame and edge numbering. Texel (u, v) of a tile, u = 0..n-1 to the right (+x),
// v = 0..n-1 upwards (+y). The tile's corners are numbered counter-clockwise from (0, 0) and
// every edge's texels are numbered 0..n-1 in the same counter-clockwise sense (the arrows):
//
//            corner 3        edge +y: i = n-1-u         corner 2
//                  +  <-----------------------------------  +
//                  |  (0,n-1)                    (n-1,n-1) ^
//       edge -x:   |                                       |   edge +x:
//       i = n-1-v  |                                       |   i = v
//                  v  (0,0)                        (n-1,0) |
//                  +  ----------------------------------->  +
//            corner 0        edge -y: i = u                 corner 1
//
// Edge e runs from corner (e+1) mod 4 to corner (e+2) mod 4 (Direction/TileEdge numbering).
//
// Gluing edge ea of tile a to edge eb of tile b:
//   proper (orientable) gluing: texel i of ea meets texel n-1-i of eb. Both tiles run round
//     their boundary counter-clockwise, so they run along a shared edge in opposite senses:
//
//         tile a   ... | i=2 | i=1 | i=0 |      (ea, a's counter-clockwise sense: <-)
//         tile b   ... |n-3  |n-2  |n-1  |      (eb, b's counter-clockwise sense: ->)
//
//   reversed (mirrored) gluing: texel i of ea meets texel i of eb (a Moebius strip's seam;
//     also a plane tile stored mirrored in the atlas).
//
// A step in direction d from a border texel at index i of edge e = d arrives at the texel of
// index j (j = n-1-i, or i when reversed) on eb; `back` is eb (stepping along eb leads back),
// `mirrored` is `reversed`. Continuing straight on means going opposite(back) in the new frame.
// The frame change is the element of the dihedral group D4 that maps a's directions to b's:
//   proper:   x -> (x + eb + 2 - ea) mod 4      (a rotation by (eb + 2 - ea) * 90 degrees)
//   reversed: x -> (ea + eb + 2 - x) mod 4      (a reflection)
// Both map ea to opposite(eb) (through the edge) and the edge's tangent consistently with the
// texel order above.
class Atlas {
public:
    // tileCount tiles of tileSize x tileSize texels, laid out row-major in a grid of tiles
    // (tilesPerRow = ceil(sqrt(tileCount)) unless given); texels outside every tile are unused.
    // Throws std::invalid_argument for tileSize < 2, tileCount < 1, tilesPerRow < 0, or an
    // atlas 65536 texels or more on a side (addresses are 16:16 on the GPU).
    Atlas(int tileSize, int tileCount, int tilesPerRow = 0);

    // Glue edge ea of tile a to edge eb of tile b (see the class comment for which texels
    // meet). Throws std::invalid_argument naming the tile and edge if an edge is glued twice,
    // a tile index is out of range, or a == b && ea == eb.
    void glue(int a, TileEdge ea, int b, TileEdge eb, bool reversed = false);

    int tileSize() const { return m_tileSize; }
    int tileCount() const { return m_tileCount; }
    int tilesPerRow() const { return m_tilesPerRow; }
    int width() const { return m_width; } // the atlas texture, in texels
    int height() const { return m_height; }
    std::size_t cellCount() const { return std::size_t(m_width) * std::size_t(m_height); }
    // cell = y * width + x
    std::uint32_t cellAt(int x, int y) const { return std::uint32_t(y) * m_width + x; }

    bool used(std::uint32_t cell) const { return tileOf(cell) >= 0; } // inside some tile
    int tileOf(std::uint32_t cell) const;                             // -1 if unused
    // The cell of texel (u, v) of a tile, in the tile's own frame.
    std::uint32_t tileCell(int tile, int u, int v) const;
    // The cell of texel i (counted as in the class comment) along edge e of a tile.
    std::uint32_t edgeCell(int tile, TileEdge e, int i) const;
    // The texel of a tile at one of its corners (0..3 counter-clockwise from (0, 0)).
    std::uint32_t cornerCell(int tile, int corner) const;
    // What edge e of a tile is glued to.
    const AtlasLink& link(int tile, TileEdge e) const;

    // The four neighbours are at +-1 / +-width in the texture (no indirection needed): a used
    // cell not on its tile's border ring.
    bool interior(std::uint32_t cell) const;
    // One step. An unglued edge is a zero-flux boundary: the step returns the cell itself
    // (back = the opposite of the direction taken, mirrored = false); so does an unused cell.
    AtlasStep step(std::uint32_t cell, Direction d) const;
    // Walk a path of steps carrying the frame: each direction of `path` is taken in the
    // STARTING cell's frame, turned by the rotation/mirroring accumulated along the edges
    // crossed so far (straight on stays straight on). Steps into an unglued edge stay put and
    // keep the frame. So walk(c, {PlusX, PlusY}) is the diagonal "neighbour of neighbour in
    // the same frame".
    //
    // Where the two orders agree: wherever the 2 x 2 block of texels the two steps span lies
    // around a tile-corner vertex of valence 4, or around no tile corner at all (inside a tile
    // or across one edge), {PlusX, PlusY} and {PlusY, PlusX} reach the same texel.
    // Where they differ: only from a tile's corner texel, with both directions pointing
    // towards its corner vertex (x, y below; any of the four corners), when that vertex has
    // valence k != 4 (k tiles meet there). Going round the vertex the tiles are a (ours),
    // b (across a's edge in direction x), ..., c (across a's edge in direction y):
    //   valence 3 (a, b, c): x-then-y reaches c's corner texel, which is a's direct y
    //     neighbour; y-then-x reaches b's corner texel, a's direct x neighbour. The orders
    //     differ, and neither reaches a texel that is not already a direct neighbour.
    //   valence 5 (a, b, p, q, c): x-then-y reaches p's corner texel, y-then-x q's. The two
    //     differ, and both are corner texels at the vertex that are not direct neighbours.
    // (Checked by tests on the cube and on a 5-tile fan, for every corner texel.) On an open
    // atlas a step into an unglued edge stays put, so a diagonal there may end next to c.
    std::uint32_t walk(std::uint32_t cell, std::initializer_list<Direction> path) const;
    std::uint32_t walk(std::uint32_t cell, const std::vector<Direction>& path) const;

    // The CPU's index array: per cell its 4 neighbours (Direction order); unused cells point
    // at themselves.
    const std::vector<std::array<std::uint32_t, 4>>& neighbours() const { return m_neighbours; }
    // Border cells only (used cells where interior() is false), in increasing order: the few
    // the step must look up.
    const std::vector<std::uint32_t>& borderCells() const { return m_border; }
    // The GPU's connectivity map: 4 uint32 per texel (RGBA32UI), neighbour d packed
    // x | (y << 16); unused texels point at themselves.
    std::vector<std::uint32_t> connectivityMap() const;

    // How many tile corners meet at this tile corner (a tile-corner vertex of the glued
    // surface): e.g. 3 on every cube corner, 4 on a flat grid of tiles. On the boundary of an
    // open atlas it counts the tiles in the fan around the vertex (a lone tile: 1).
    // corner 0..3 counter-clockwise from (0, 0), as in the class comment.
    int cornerValence(int tile, int corner) const;

    // Throws std::invalid_argument naming the tile and edge if the atlas is not closed
    // (requireClosed: every edge glued) or otherwise inconsistent (a link that does not point
    // back, a step whose `back` does not return).
    void validate(bool requireClosed) const;

    // Tiles from quads: quads[t] lists the vertex ids of tile t's corners 0..3 (counter-
    // clockwise in the tile frame). Edges with the same two vertices are glued: properly when
    // the quads run along them in opposite senses, reversed when in the same sense. Throws
    // std::invalid_argument for an edge shared by more than two quads or a degenerate edge.
    static Atlas fromQuads(int tileSize, const std::vector<std::array<int, 4>>& quads,
                           int tilesPerRow = 0);

    // Six tiles glued as the faces of a cube (closed, orientable, 8 corners of valence 3).
    // Cube vertex v sits at (v & 1, (v >> 1) & 1, (v >> 2) & 1); tile t is face t with its
    // corners 0..3 at these vertices (counter-clockwise seen from outside, so the frames are
    // right-handed with the outward normal):
    //   0: +x {1,3,7,5}  1: -x {0,4,6,2}  2: +y {2,6,7,3}
    //   3: -y {0,1,5,4}  4: +z {4,5,7,6}  5: -z {0,2,3,1}
    static Atlas cube(int tileSize);
    // A 3 x 3 periodic plane of tiles (a torus, every corner valence 4), tile t = (t mod 3,
    // t / 3) of the plane stored in the atlas turned by an element e of D4: rotated by
    // (e mod 4) * 90 degrees counter-clockwise, after a mirror u -> n-1-u when e >= 4, with
    // e = t for tiles 0..7 and e = 2 for tile 8. Its gluings have every relative rotation (0,
    // 90, 180, 270 degrees) in both orientations (plain and mirrored). Simulations on it equal
    // those on a periodic grid of 3n x 3n cells, texel for texel through
    // rotatedTilesPlaneCells.
    static Atlas rotatedTiles(int tileSize);
    // For each cell of rotatedTiles(tileSize), the cell (y * 3n + x) of the 3n x 3n periodic
    // grid it stands for (UINT32_MAX for unused cells; rotatedTiles has none).
    static std::vector<std::uint32_t> rotatedTilesPlaneCells(int tileSize);
    // An N x M grid of tiles glued as a periodic plane (every corner valence 4), laid out with
    // tilesPerRow = N: the same cells and neighbours as a periodic grid of (N n) x (M n) cells.
    static Atlas periodicPlane(int tileSize, int tilesX, int tilesY);

private:
    struct TexelPos {
        int tile;
        int u;
        int v;
    };
    TexelPos position(std::uint32_t cell) const;
    void checkTile(int tile, const char* what) const;
    void refreshEdge(int tile, TileEdge e);

    int m_tileSize = 2;
    int m_tileCount = 1;
    int m_tilesPerRow = 1;
    int m_width = 2;
    int m_height = 2;
    std::vector<std::array<AtlasLink, 4>> m_links;
    std::vector<std::array<std::uint32_t, 4>> m_neighbours;
    std::vector<std::uint32_t> m_border;
};

} // namespace morphogen
