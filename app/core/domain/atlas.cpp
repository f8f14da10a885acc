#include "core/domain/atlas.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace morphogen {

namespace {

constexpr int kMaxSide = 65536; // 16-bit texel coordinates

int index(Direction d) {
    return int(d);
}
int index(TileEdge e) {
    return int(e);
}
Direction direction(int i) {
    return Direction(((i % 4) + 4) % 4);
}
TileEdge edge(int i) {
    return TileEdge(((i % 4) + 4) % 4);
}

std::string tileEdgeName(int tile, TileEdge e) {
    return "tile " + std::to_string(tile) + " edge " + toString(e);
}

// Texel (u, v) of the tile frame at index i along edge e (class comment in atlas.hpp).
std::pair<int, int> edgeTexel(int n, TileEdge e, int i) {
    switch (e) {
    case TileEdge::PlusX:
        return {n - 1, i};
    case TileEdge::PlusY:
        return {n - 1 - i, n - 1};
    case TileEdge::MinusX:
        return {0, n - 1 - i};
    case TileEdge::MinusY:
        return {i, 0};
    }
    return {0, 0};
}

// The index along edge e of border texel (u, v).
int edgeIndex(int n, TileEdge e, int u, int v) {
    switch (e) {
    case TileEdge::PlusX:
        return v;
    case TileEdge::PlusY:
        return n - 1 - u;
    case TileEdge::MinusX:
        return n - 1 - v;
    case TileEdge::MinusY:
        return u;
    }
    return 0;
}

constexpr int kDu[4] = {1, 0, -1, 0};
constexpr int kDv[4] = {0, 1, 0, -1};

// An element of D4 acting on directions: x -> rot + x (proper) or rot - x (mirrored).
struct Frame {
    int rot = 0;
    bool mirrored = false;

    int apply(int x) const { return ((mirrored ? rot - x : rot + x) % 4 + 4) % 4; }
    // this after other: x -> this(other(x)).
    Frame after(const Frame& other) const {
        Frame f;
        f.mirrored = mirrored != other.mirrored;
        f.rot = apply(other.rot);
        return f;
    }
};

// The frame change of a step taken in direction `taken` that arrived with `s.back`.
Frame crossing(Direction taken, const AtlasStep& s) {
    Frame f;
    f.mirrored = s.mirrored;
    f.rot = s.mirrored ? index(taken) + index(s.back) + 2 : index(s.back) + 2 - index(taken);
    f.rot = ((f.rot % 4) + 4) % 4;
    return f;
}

} // namespace

Direction opposite(Direction d) {
    return direction(index(d) + 2);
}

std::string toString(Direction d) {
    static const char* names[4] = {"+x", "+y", "-x", "-y"};
    return names[index(d)];
}

std::string toString(TileEdge e) {
    return toString(Direction(index(e)));
}

Atlas::Atlas(int tileSize, int tileCount, int tilesPerRow) {
    if (tileSize < 2)
        throw std::invalid_argument("Atlas: tile size " + std::to_string(tileSize) +
                                    " is too small (at least 2 texels)");
    if (tileCount < 1)
        throw std::invalid_argument("Atlas: tile count " + std::to_string(tileCount) +
                                    " must be at least 1");
    if (tilesPerRow < 0)
        throw std::invalid_argument("Atlas: tiles per row " + std::to_string(tilesPerRow) +
                                    " must be positive (or 0 for ceil(sqrt(tile count)))");
    if (tilesPerRow == 0) {
        tilesPerRow = int(std::ceil(std::sqrt(double(tileCount))));
        while (std::int64_t(tilesPerRow) * tilesPerRow < tileCount)
            ++tilesPerRow;
        while (tilesPerRow > 1 && std::int64_t(tilesPerRow - 1) * (tilesPerRow - 1) >= tileCount)
            --tilesPerRow;
    }
    const std::int64_t rows = (std::int64_t(tileCount) + tilesPerRow - 1) / tilesPerRow;
    const std::int64_t width = std::int64_t(tilesPerRow) * tileSize;
    const std::int64_t height = rows * tileSize;
    if (width >= kMaxSide || height >= kMaxSide)
        throw std::invalid_argument("Atlas: " + std::to_string(tileCount) + " tiles of " +
                                    std::to_string(tileSize) + " texels, " +
                                    std::to_string(tilesPerRow) + " per row, make an atlas of " +
                                    std::to_string(width) + " x " + std::to_string(height) +
                                    " texels; 16-bit addresses allow at most " +
                                    std::to_string(kMaxSide - 1) + " on a side");

    m_tileSize = tileSize;
    m_tileCount = tileCount;
    m_tilesPerRow = tilesPerRow;
    m_width = int(width);
    m_height = int(height);
    m_links.assign(std::size_t(tileCount), {});

    m_neighbours.resize(cellCount());
    for (std::uint32_t c = 0; c < m_neighbours.size(); ++c)
        for (int d = 0; d < 4; ++d)
            m_neighbours[c][d] = step(c, direction(d)).cell;

    const int n = m_tileSize;
    for (std::uint32_t c = 0; c < m_neighbours.size(); ++c) {
        const TexelPos p = position(c);
        if (p.tile >= 0 && (p.u == 0 || p.v == 0 || p.u == n - 1 || p.v == n - 1))
            m_border.push_back(c);
    }
}

void Atlas::checkTile(int tile, const char* what) const {
    if (tile < 0 || tile >= m_tileCount)
        throw std::invalid_argument(std::string("Atlas::") + what + ": tile " +
                                    std::to_string(tile) + " is out of range (0.." +
                                    std::to_string(m_tileCount - 1) + ")");
}

void Atlas::glue(int a, TileEdge ea, int b, TileEdge eb, bool reversed) {
    checkTile(a, "glue");
    checkTile(b, "glue");
    if (index(ea) < 0 || index(ea) > 3 || index(eb) < 0 || index(eb) > 3)
        throw std::invalid_argument("Atlas::glue: edge out of range (+x, +y, -x, -y)");
    if (a == b && ea == eb)
        throw std::invalid_argument("Atlas::glue: " + tileEdgeName(a, ea) +
                                    " cannot be glued to itself");
    for (const auto& [t, e] : {std::pair{a, ea}, std::pair{b, eb}}) {
        const AtlasLink& l = m_links[t][index(e)];
        if (l.glued)
            throw std::invalid_argument("Atlas::glue: " + tileEdgeName(t, e) +
                                        " is already glued (to " + tileEdgeName(l.tile, l.edge) +
                                        ")");
    }
    m_links[a][index(ea)] = AtlasLink{true, b, eb, reversed};
    m_links[b][index(eb)] = AtlasLink{true, a, ea, reversed};
    refreshEdge(a, ea);
    refreshEdge(b, eb);
}

void Atlas::refreshEdge(int tile, TileEdge e) {
    for (int i = 0; i < m_tileSize; ++i) {
        const std::uint32_t c = edgeCell(tile, e, i);
        m_neighbours[c][index(e)] = step(c, Direction(index(e))).cell;
    }
}

Atlas::TexelPos Atlas::position(std::uint32_t cell) const {
    if (cell >= cellCount())
        return {-1, 0, 0};
    const int x = int(cell % std::uint32_t(m_width));
    const int y = int(cell / std::uint32_t(m_width));
    const int tile = (y / m_tileSize) * m_tilesPerRow + x / m_tileSize;
    if (tile >= m_tileCount)
        return {-1, 0, 0};
    return {tile, x % m_tileSize, y % m_tileSize};
}

int Atlas::tileOf(std::uint32_t cell) const {
    return position(cell).tile;
}

std::uint32_t Atlas::tileCell(int tile, int u, int v) const {
    const int x = (tile % m_tilesPerRow) * m_tileSize + u;
    const int y = (tile / m_tilesPerRow) * m_tileSize + v;
    return cellAt(x, y);
}

std::uint32_t Atlas::edgeCell(int tile, TileEdge e, int i) const {
    const auto [u, v] = edgeTexel(m_tileSize, e, i);
    return tileCell(tile, u, v);
}

std::uint32_t Atlas::cornerCell(int tile, int corner) const {
    checkTile(tile, "cornerCell");
    if (corner < 0 || corner > 3)
        throw std::invalid_argument("Atlas::cornerCell: corner " + std::to_string(corner) +
                                    " is out of range (0..3)");
    const int n = m_tileSize - 1;
    const int u[4] = {0, n, n, 0}, v[4] = {0, 0, n, n};
    return tileCell(tile, u[corner], v[corner]);
}

const AtlasLink& Atlas::link(int tile, TileEdge e) const {
    checkTile(tile, "link");
    return m_links[tile][index(e)];
}

bool Atlas::interior(std::uint32_t cell) const {
    const TexelPos p = position(cell);
    const int n = m_tileSize;
    return p.tile >= 0 && p.u > 0 && p.v > 0 && p.u < n - 1 && p.v < n - 1;
}

AtlasStep Atlas::step(std::uint32_t cell, Direction d) const {
    const AtlasStep stay{cell, opposite(d), false};
    const TexelPos p = position(cell);
    if (p.tile < 0)
        return stay;
    const int n = m_tileSize;
    const int u = p.u + kDu[index(d)];
    const int v = p.v + kDv[index(d)];
    if (u >= 0 && v >= 0 && u < n && v < n)
        return {tileCell(p.tile, u, v), opposite(d), false};

    const TileEdge out = TileEdge(index(d));
    const AtlasLink& l = m_links[p.tile][index(out)];
    if (!l.glued)
        return stay;
    const int i = edgeIndex(n, out, p.u, p.v);
    const int j = l.reversed ? i : n - 1 - i;
    return {edgeCell(l.tile, l.edge, j), Direction(index(l.edge)), l.reversed};
}

std::uint32_t Atlas::walk(std::uint32_t cell, std::initializer_list<Direction> path) const {
    return walk(cell, std::vector<Direction>(path));
}

std::uint32_t Atlas::walk(std::uint32_t cell, const std::vector<Direction>& path) const {
    Frame frame; // maps the starting frame's directions to the current cell's
    for (Direction d : path) {
        const Direction taken = direction(frame.apply(index(d)));
        const AtlasStep s = step(cell, taken);
        frame = crossing(taken, s).after(frame);
        cell = s.cell;
    }
    return cell;
}

std::vector<std::uint32_t> Atlas::connectivityMap() const {
    std::vector<std::uint32_t> map(cellCount() * 4);
    const auto w = std::uint32_t(m_width);
    for (std::size_t c = 0; c < m_neighbours.size(); ++c)
        for (int d = 0; d < 4; ++d) {
            const std::uint32_t nb = m_neighbours[c][d];
            map[c * 4 + d] = (nb % w) | ((nb / w) << 16);
        }
    return map;
}

int Atlas::cornerValence(int tile, int corner) const {
    checkTile(tile, "cornerValence");
    if (corner < 0 || corner > 3)
        throw std::invalid_argument("Atlas::cornerValence: corner " + std::to_string(corner) +
                                    " is out of range (0..3)");
    // Corner c is where edge c+2 ends and edge c+3 starts. Go round the vertex through one of
    // the two edges at the corner, then through the other edge of the corner reached, until
    // we are back or hit an unglued edge.
    const auto goRound = [&](bool throughStartingEdge, bool& closed) {
        int t = tile, c = corner, count = 0;
        bool viaStart = throughStartingEdge;
        closed = false;
        for (int guard = 0; guard <= 4 * m_tileCount; ++guard) {
            const TileEdge e = edge(viaStart ? c + 3 : c + 2);
            const AtlasLink& l = m_links[t][index(e)];
            if (!l.glued)
                return count;
            // The start of e meets the end of l.edge in a proper gluing, its start when
            // reversed; and the other way round for the end of e.
            const bool arriveAtStart = l.reversed == viaStart;
            t = l.tile;
            c = arriveAtStart ? index(l.edge) + 1 : index(l.edge) + 2;
            c %= 4;
            // Leave the corner through its other edge: l.edge starts at c => leave via the
            // edge ending at c, and vice versa.
            viaStart = !arriveAtStart;
            if (t == tile && c == corner) {
                closed = true;
                return count + 1;
            }
            ++count;
        }
        throw std::logic_error("Atlas::cornerValence: no way round the corner vertex of tile " +
                               std::to_string(tile));
    };
    bool closed = false;
    const int forward = goRound(true, closed);
    if (closed)
        return forward;
    bool unused = false;
    const int backward = goRound(false, unused);
    return 1 + forward + backward;
}

void Atlas::validate(bool requireClosed) const {
    if (m_width >= kMaxSide || m_height >= kMaxSide)
        throw std::invalid_argument("Atlas: " + std::to_string(m_width) + " x " +
                                    std::to_string(m_height) +
                                    " texels do not fit 16-bit addresses");
    for (int t = 0; t < m_tileCount; ++t)
        for (int e = 0; e < 4; ++e) {
            const AtlasLink& l = m_links[t][e];
            if (!l.glued) {
                if (requireClosed)
                    throw std::invalid_argument("Atlas is not closed: " + tileEdgeName(t, edge(e)) +
                                                " is not glued");
                continue;
            }
            if (l.tile < 0 || l.tile >= m_tileCount)
                throw std::invalid_argument("Atlas: " + tileEdgeName(t, edge(e)) +
                                            " is glued to tile " + std::to_string(l.tile) +
                                            ", out of range");
            const AtlasLink& back = m_links[l.tile][index(l.edge)];
            if (!back.glued || back.tile != t || index(back.edge) != e ||
                back.reversed != l.reversed)
                throw std::invalid_argument("Atlas: " + tileEdgeName(t, edge(e)) + " is glued to " +
                                            tileEdgeName(l.tile, l.edge) +
                                            ", which is not glued back the same way");
        }
    for (std::uint32_t c : m_border) {
        const TexelPos p = position(c);
        for (int d = 0; d < 4; ++d) {
            const AtlasStep s = step(c, direction(d));
            if (m_neighbours[c][d] != s.cell)
                throw std::invalid_argument("Atlas: the index array disagrees with the gluing "
                                            "at texel (" +
                                            std::to_string(p.u) + ", " + std::to_string(p.v) +
                                            ") of tile " + std::to_string(p.tile) + ", " +
                                            toString(direction(d)));
            const bool outward = (d == 0 && p.u == m_tileSize - 1) ||
                                 (d == 1 && p.v == m_tileSize - 1) || (d == 2 && p.u == 0) ||
                                 (d == 3 && p.v == 0);
            if (outward && !m_links[p.tile][d].glued)
                continue; // zero flux: the step stays put
            const AtlasStep r = step(s.cell, s.back);
            if (r.cell != c || index(r.back) != d || r.mirrored != s.mirrored)
                throw std::invalid_argument("Atlas: stepping " + toString(direction(d)) +
                                            " from texel (" + std::to_string(p.u) + ", " +
                                            std::to_string(p.v) + ") of tile " +
                                            std::to_string(p.tile) + " does not lead back (edge " +
                                            tileEdgeName(p.tile, edge(d)) + ")");
        }
    }
}

Atlas Atlas::fromQuads(int tileSize, const std::vector<std::array<int, 4>>& quads,
                       int tilesPerRow) {
    Atlas atlas(tileSize, int(quads.size()), tilesPerRow);
    struct Side {
        int tile;
        TileEdge edge;
        int from;
    };
    std::map<std::pair<int, int>, std::vector<Side>> sides;
    for (int t = 0; t < int(quads.size()); ++t)
        for (int e = 0; e < 4; ++e) {
            const int from = quads[t][(e + 1) % 4];
            const int to = quads[t][(e + 2) % 4];
            if (from == to)
                throw std::invalid_argument("Atlas::fromQuads: " + tileEdgeName(t, edge(e)) +
                                            " joins vertex " + std::to_string(from) + " to itself");
            auto& list = sides[{std::min(from, to), std::max(from, to)}];
            list.push_back({t, edge(e), from});
            if (list.size() > 2)
                throw std::invalid_argument("Atlas::fromQuads: the edge between vertices " +
                                            std::to_string(from) + " and " + std::to_string(to) +
                                            " is shared by more than two quads (" +
                                            tileEdgeName(list[0].tile, list[0].edge) + ", " +
                                            tileEdgeName(list[1].tile, list[1].edge) + ", " +
                                            tileEdgeName(t, edge(e)) + ")");
        }
    for (const auto& [key, list] : sides)
        if (list.size() == 2)
            atlas.glue(list[0].tile, list[0].edge, list[1].tile, list[1].edge,
                       list[0].from == list[1].from);
    return atlas;
}

Atlas Atlas::cube(int tileSize) {
    return fromQuads(tileSize, {{{1, 3, 7, 5}},
                                {{0, 4, 6, 2}},
                                {{2, 6, 7, 3}},
                                {{0, 1, 5, 4}},
                                {{4, 5, 7, 6}},
                                {{0, 2, 3, 1}}});
}

namespace {

// The D4 element rotatedTiles stores tile t with: e mod 4 quarter turns, mirrored when e >= 4.
// Tiles 0..7 take the eight elements; tile 8 is turned like tile 2, which puts two tiles
// turned the same way next to each other (tiles 2 and 8 are neighbours across the wrap) so
// that a plain, unrotated gluing occurs too.
constexpr int kRotatedTileElement[9] = {0, 1, 2, 3, 4, 5, 6, 7, 2};

// That element acting on a point of the tile square [0, s]^2 (s = n for corners, s = n-1 for
// texel indices): mirror x -> s-x first when e >= 4, then quarter turns counter-clockwise.
std::pair<int, int> rotatedTileTransform(int t, int s, int x, int y) {
    const int e = kRotatedTileElement[t];
    if (e >= 4)
        x = s - x;
    for (int k = 0; k < e % 4; ++k) {
        const int nx = s - y;
        y = x;
        x = nx;
    }
    return {x, y};
}

constexpr int kPlaneTiles = 3;

} // namespace

Atlas Atlas::rotatedTiles(int tileSize) {
    const int n = tileSize;
    const int m = kPlaneTiles;
    std::vector<std::array<int, 4>> quads;
    const int cornerX[4] = {0, n, n, 0};
    const int cornerY[4] = {0, 0, n, n};
    for (int t = 0; t < m * m; ++t) {
        const int tx = t % m, ty = t / m;
        std::array<int, 4> q{};
        for (int k = 0; k < 4; ++k) {
            const auto [x, y] = rotatedTileTransform(t, n, cornerX[k], cornerY[k]);
            const int vx = (tx + x / n) % m, vy = (ty + y / n) % m;
            q[k] = vy * m + vx;
        }
        quads.push_back(q);
    }
    return fromQuads(tileSize, quads, m);
}

std::vector<std::uint32_t> Atlas::rotatedTilesPlaneCells(int tileSize) {
    const Atlas atlas(tileSize, kPlaneTiles * kPlaneTiles, kPlaneTiles);
    const int n = tileSize;
    const int side = kPlaneTiles * n;
    std::vector<std::uint32_t> cells(atlas.cellCount(), std::numeric_limits<std::uint32_t>::max());
    for (int t = 0; t < atlas.tileCount(); ++t)
        for (int v = 0; v < n; ++v)
            for (int u = 0; u < n; ++u) {
                const auto [x, y] = rotatedTileTransform(t, n - 1, u, v);
                const int gx = (t % kPlaneTiles) * n + x, gy = (t / kPlaneTiles) * n + y;
                cells[atlas.tileCell(t, u, v)] = std::uint32_t(gy * side + gx);
            }
    return cells;
}

Atlas Atlas::periodicPlane(int tileSize, int tilesX, int tilesY) {
    if (tilesX < 1 || tilesY < 1)
        throw std::invalid_argument("Atlas::periodicPlane: " + std::to_string(tilesX) + " x " +
                                    std::to_string(tilesY) + " tiles; need at least 1 x 1");
    if (std::int64_t(tilesX) * tilesY > std::numeric_limits<int>::max())
        throw std::invalid_argument("Atlas::periodicPlane: too many tiles");
    Atlas atlas(tileSize, tilesX * tilesY, tilesX);
    for (int y = 0; y < tilesY; ++y)
        for (int x = 0; x < tilesX; ++x) {
            const int t = y * tilesX + x;
            atlas.glue(t, TileEdge::PlusX, y * tilesX + (x + 1) % tilesX, TileEdge::MinusX);
            atlas.glue(t, TileEdge::PlusY, ((y + 1) % tilesY) * tilesX + x, TileEdge::MinusY);
        }
    return atlas;
}

} // namespace morphogen
