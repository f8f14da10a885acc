#include "core/domain/domain.hpp"

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

Domain Domain::tiledGrid(int width, int height, int columns, int rows) {
    assert(columns >= 1 && rows >= 1 && width % columns == 0 && height % rows == 0);
    Domain d(GridDomain(width, height, EdgeMode::Periodic));
    d.m_kind = DomainKind::TiledGrid;
    d.m_columns = columns;
    d.m_rows = rows;
    return d;
}

} // namespace morphogen
