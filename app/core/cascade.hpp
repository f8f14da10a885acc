#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/state.hpp"

namespace morphogen {

class ReactionModel;

// Turk's cascades: a session runs as stages; each stage may change parameters,
// freeze the cells its rule picks from the previous stage's result, and reset
// chemicals at the frozen cells. Frozen cells keep their values exactly but
// still feed their neighbours' diffusion.
struct FreezeRule {
    std::string chemical;
    float min = 0.0f; // cells with min <= value <= max are frozen
    float max = 0.0f;
};

struct Stage {
    int steps = 0;
    std::map<std::string, float> params; // overrides, on top of the session's and earlier stages'
    std::optional<FreezeRule> freeze;
    std::map<std::string, float> reset; // chemical values written at frozen cells
};

// Frozen cells after applying `rule` to `state`, added to `frozen` (empty:
// none frozen yet). Frozen cells stay frozen for the rest of the run.
std::vector<std::uint8_t> applyFreezeRule(const FreezeRule& rule, const State& state,
                                          const ReactionModel& model,
                                          std::vector<std::uint8_t> frozen);

// Writes `reset` values into the frozen cells.
void resetFrozenCells(State& state, const std::vector<std::uint8_t>& frozen,
                      const std::map<std::string, float>& reset, const ReactionModel& model);

std::vector<Stage> stagesFromJson(const nlohmann::json& json, const std::string& source,
                                  const ReactionModel& model);
nlohmann::json stagesToJson(const std::vector<Stage>& stages);

} // namespace morphogen
