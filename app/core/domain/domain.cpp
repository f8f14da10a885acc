#include "core/domain/domain.hpp"

#include "core/base/errors.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"

namespace morphogen {

std::string toString(DomainKind kind) {
    switch (kind) {
    case DomainKind::Grid:
        return "grid";
    case DomainKind::TiledGrid:
        return "tiled grid";
    case DomainKind::Atlas:
        return "atlas";
    }
    return "grid";
}

void requireGridAxes(const Domain& domain, const std::string& feature) {
    if (domain.kind() == DomainKind::Atlas)
        throw InputError(feature + " needs a grid's x and y axes and cannot run on an atlas "
                                   "domain (accepted: grid, tiled grid)");
}

Domain Domain::tiledGrid(int width, int height, int columns, int rows) {
    assert(columns >= 1 && rows >= 1 && width % columns == 0 && height % rows == 0);
    Domain d(GridDomain(width, height, EdgeMode::Periodic));
    d.m_kind = DomainKind::TiledGrid;
    d.m_columns = columns;
    d.m_rows = rows;
    return d;
}

Domain Domain::atlas(std::shared_ptr<const Atlas> atlas) {
    assert(atlas);
    // Edges mean nothing here: every step goes through the atlas, and an
    // unglued tile edge is zero-flux.
    Domain d(GridDomain(atlas->width(), atlas->height(), EdgeMode::Clamped));
    d.m_kind = DomainKind::Atlas;
    d.m_atlas = std::move(atlas);
    return d;
}

Domain Domain::atlas(std::shared_ptr<const Atlas> atlas,
                     std::shared_ptr<const AtlasWeights> weights) {
    // Sizes only: a session's domain is made often, and useAtlas checked the values.
    if (weights)
        checkAtlasWeightSizes(*atlas, *weights);
    Domain d = Domain::atlas(std::move(atlas));
    d.m_weights = std::move(weights);
    return d;
}

} // namespace morphogen
