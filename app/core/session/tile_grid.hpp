#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class ReactionModel;

// A parameter sweep batched into one session: the session's grid split into
// columns x rows equal tiles, each periodic on its own (a TiledGrid domain),
// with per-tile values of the swept parameters. Tile (column, row) behaves
// exactly as the standalone session of one tile's size with those values.
// Serialised as "tiles": {"grid": [columns, rows], "params": {"k": [...]}}.
struct TileGrid {
    int columns = 0, rows = 0; // 0 x 0: the session is not tiled
    // Per parameter, one value per tile, row-major, row 0 at the bottom as in a plot.
    std::map<std::string, std::vector<float>> params;

    bool active() const { return columns > 0 && rows > 0; }
    float value(const std::string& param, int column, int row) const {
        return params.at(param)[std::size_t(row) * std::size_t(columns) + std::size_t(column)];
    }
};

// Reads a session's "tiles"; values must lie in each parameter's range.
TileGrid tileGridFromJson(const nlohmann::json& json, const std::string& source,
                          const ReactionModel& model);
nlohmann::json tileGridToJson(const TileGrid& tiles);

} // namespace morphogen
