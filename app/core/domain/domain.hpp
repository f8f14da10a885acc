#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <string>

#include "core/domain/grid_domain.hpp"

namespace morphogen {

class Atlas;
struct AtlasWeights;

// Where the cells are and who their neighbours are, read by both backends.
// A feature never asks "is this a sweep?": it asks the domain's kind, and an
// operator or statistic a kind cannot support is refused by name.
//
//   Grid       W x H cells, periodic or clamped (GridDomain). The CPU wraps
//              or clamps indices; the GPU uses textureOffset and the sampler's
//              wrap mode. This is the fast path and stays exactly as it was.
//   TiledGrid  W x H cells split into columns x rows equal tiles, each
//              periodic on its own: tiles exchange nothing (a parameter sweep
//              batched into one simulation). The CPU advances each tile a
//              chunk of explicit steps on its own, tiles in parallel
//              (cpu_tile_runs.cpp), and otherwise walks each row as one column
//              segment per tile, interior columns unit-stride; the GPU wraps
//              inside the tile (TILES variant of glsl/step.frag).
//   Atlas      square tiles in one texture (Lo et al.); every texel's four
//              neighbours come from a connectivity map (core/domain/atlas.hpp).
//              Interior texels use +-1 / +-width, border texels the map;
//              texels outside every tile are unused and never change.
//              With per-texel weights (atlas_weights.hpp, from the surface's
//              metric) every used texel's Laplacian is the weighted 5-point
//              one, sum_d c_d (u_d - u): interior texels too.
//
// Operators on an atlas (decided here, enforced in StepConstants::fromSession):
//   5-point Laplacian  defined everywhere (four neighbours are all the map has).
//                      With weights: the weighted 5-point Laplacian.
//   9-point Laplacian  diagonals = neighbour of neighbour in the same frame,
//                      the mean of both orders (x then y, y then x); the grid's
//                      stencil away from irregular corners, and mass-conserving
//                      at valence 3 and 5 (core/domain/atlas_diagonals.hpp).
//                      With weights: the weighted 5-point runs instead (the
//                      weights have no diagonals), and the plan says so.
//   Witkin-Kass 3x3 tensors, McGraw's 5x5 kernels, tensor maps: refused with an
//                      InputError naming the operator and the domain: their
//                      cross terms and distance-2 taps need a frame that
//                      rotates across tile edges and is undefined at an
//                      irregular corner (for the metric correction a 4-neighbour
//                      form of the anisotropic term is the likely way).
//   The semi-implicit integrator (its weight comes from a grid's Fourier
//   symbol) and param maps (fields in grid x and y) are refused likewise.
enum class DomainKind { Grid, TiledGrid, Atlas };
std::string toString(DomainKind kind);

class Domain;
// For features defined on a grid's x and y axes or its Fourier modes (FFT
// pattern statistics, the Fourier-symbol stability analysis, orientation
// fields, param-map fields in x and y): throws InputError naming `feature`
// and the domain when the domain is an atlas. A tiled grid is accepted: each
// tile is a periodic grid (statistics are measured per tile).
void requireGridAxes(const Domain& domain, const std::string& feature);

class Domain {
public:
    Domain() = default;
    // A grid is a domain; most code still builds one from (W, H, edges).
    Domain(const GridDomain& grid) : m_grid(grid) {} // NOLINT: implicit on purpose

    static Domain tiledGrid(int width, int height, int columns, int rows);
    static Domain atlas(std::shared_ptr<const Atlas> atlas);
    // An atlas with per-texel diffusion weights (atlas_weights.hpp): every
    // used texel's Laplacian is the weighted 5-point one. Null weights: the
    // plain atlas. Throws InputError for weights of the wrong size (useAtlas
    // checks their values too).
    static Domain atlas(std::shared_ptr<const Atlas> atlas,
                        std::shared_ptr<const AtlasWeights> weights);

    DomainKind kind() const { return m_kind; }
    std::string name() const { return toString(m_kind); }
    int width() const { return m_grid.width(); }
    int height() const { return m_grid.height(); }
    // Grid: the session's; a tiled grid wraps (inside each tile); an atlas
    // glues its tiles through the map and is zero-flux at unglued edges.
    EdgeMode edges() const { return m_grid.edges(); }
    std::size_t cellCount() const { return m_grid.cellCount(); }
    const GridDomain& grid() const { return m_grid; }

    // TiledGrid: tiles across and down and cells per tile; 1 x 1 tiles of the
    // whole grid otherwise.
    int columns() const { return m_columns; }
    int rows() const { return m_rows; }
    int tileWidth() const { return width() / m_columns; }
    int tileHeight() const { return height() / m_rows; }

    // Atlas only (null otherwise).
    const Atlas* atlasMap() const { return m_atlas.get(); }
    const std::shared_ptr<const Atlas>& sharedAtlas() const { return m_atlas; }
    // Weighted atlas only (null otherwise).
    const AtlasWeights* atlasWeights() const { return m_weights.get(); }
    const std::shared_ptr<const AtlasWeights>& sharedAtlasWeights() const { return m_weights; }

    // The row dy rows from y (|dy| < tile height), wrapped or clamped by the
    // grid's edges or wrapped inside y's tile. An atlas answers as a clamped
    // grid: right for interior texels, and its border texels are redone
    // through the connectivity map.
    int neighbourRow(int y, int dy) const {
        if (m_kind != DomainKind::TiledGrid)
            return GridDomain::wrapOrClamp(y + dy, height(), edges());
        const int th = tileHeight(), top = y - y % th;
        return top + GridDomain::wrapOrClamp(y - top + dy, th, EdgeMode::Periodic);
    }
    // Likewise for columns.
    int neighbourColumn(int x, int dx) const {
        if (m_kind != DomainKind::TiledGrid)
            return GridDomain::wrapOrClamp(x + dx, width(), edges());
        const int tw = tileWidth(), left = x - x % tw;
        return left + GridDomain::wrapOrClamp(x - left + dx, tw, EdgeMode::Periodic);
    }

private:
    DomainKind m_kind = DomainKind::Grid;
    GridDomain m_grid;
    int m_columns = 1, m_rows = 1;
    std::shared_ptr<const Atlas> m_atlas;
    std::shared_ptr<const AtlasWeights> m_weights;
};

} // namespace morphogen
