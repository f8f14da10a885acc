#include "core/session/tile_grid.hpp"

#include <nlohmann/json.hpp>

#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/models/reaction_model.hpp"

namespace morphogen {

using nlohmann::json;

TileGrid tileGridFromJson(const json& j, const std::string& source, const ReactionModel& model) {
    FieldReader reader(j, source, "tiles");
    reader.rejectUnknown({"grid", "params"});
    TileGrid tiles;
    const json* grid = reader.find("grid");
    if (!grid || !grid->is_array() || grid->size() != 2)
        reader.failField("grid", "must be [columns, rows]");
    tiles.columns = int(reader.numberValue((*grid)[0], "grid[0]", 1, kMaxTilesPerSide));
    tiles.rows = int(reader.numberValue((*grid)[1], "grid[1]", 1, kMaxTilesPerSide));
    if (!(*grid)[0].is_number_integer() || !(*grid)[1].is_number_integer())
        reader.failField("grid", "must hold integers");
    const json* params = reader.find("params");
    if (!params)
        return tiles;
    FieldReader values(*params, source, reader.path("params"));
    const std::size_t count = std::size_t(tiles.columns) * std::size_t(tiles.rows);
    for (auto it = params->begin(); it != params->end(); ++it) {
        const ParamSpec* param = model.param(it.key());
        if (!param)
            values.failField(it.key(), "is not a parameter of model '" + model.name() +
                                           "' (parameters: " + model.paramNames() + ")");
        if (!it->is_array() || it->size() != count)
            values.failField(it.key(), "must hold columns x rows = " + std::to_string(count) +
                                           " values, bottom row first");
        std::vector<float>& v = tiles.params[it.key()];
        for (std::size_t i = 0; i < count; ++i)
            v.push_back(float(values.numberValue((*it)[i], it.key() + "[" + std::to_string(i) + "]",
                                                 param->min, param->max)));
    }
    return tiles;
}

json tileGridToJson(const TileGrid& tiles) {
    json j;
    j["grid"] = {tiles.columns, tiles.rows};
    j["params"] = json::object();
    for (const auto& [name, values] : tiles.params)
        j["params"][name] = values;
    return j;
}

} // namespace morphogen
