#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/base/state.hpp"
#include "core/models/initial_condition.hpp"

namespace morphogen {

class ReactionModel;

// Turk's cascades: a session runs as stages; each stage may change parameters,
// freeze the cells its rule picks from the previous stage's result, and reset
// chemicals at the frozen cells. Frozen cells keep their values exactly but
// still feed their neighbours' diffusion.
//
// A stage may also change the model (Turk's giraffe: Turing spots, then
// Meinhardt's stripes between them). Such a stage's parameters start from the
// new model's defaults plus its own "params", its dt from the new model's
// default dt (unless it sets "dt"), and its state from the new model's default
// start (or its own "init"). Its freeze rule reads the previous stage's result
// (so it names the previous model's chemicals); its "reset" then writes the
// new model's chemicals at the frozen cells of the new state. Cells frozen by
// earlier stages stay frozen.
struct FreezeRule {
    std::string chemical;
    float min = 0.0f; // cells with min <= value <= max are frozen
    float max = 0.0f;
};

struct Stage {
    int steps = 0;
    // Non-empty: the stage switches to this model (never the first stage).
    std::string model;
    // A model-changing stage's start; none: the new model's default start.
    std::optional<InitialCondition> init;
    // The time step from this stage on; none: the previous stage's (the new
    // model's default dt for a model-changing stage).
    std::optional<float> dt;
    // Overrides, on top of the session's and earlier stages' (on top of the
    // new model's defaults for a model-changing stage).
    std::map<std::string, float> params;
    std::optional<FreezeRule> freeze;   // reads the previous stage's result and model
    std::map<std::string, float> reset; // this stage's model's chemicals, written at frozen cells
};

// The model stage `index` runs: the last model set by stages 0..index, else
// `sessionModel`.
const ReactionModel& stageModel(const std::vector<Stage>& stages, std::size_t index,
                                const ReactionModel& sessionModel);

// Frozen cells after applying `rule` to `state`, added to `frozen` (empty:
// none frozen yet). Frozen cells stay frozen for the rest of the run.
std::vector<std::uint8_t> applyFreezeRule(const FreezeRule& rule, const State& state,
                                          const ReactionModel& model,
                                          std::vector<std::uint8_t> frozen);

// Writes `reset` values into the frozen cells.
void resetFrozenCells(State& state, const std::vector<std::uint8_t>& frozen,
                      const std::map<std::string, float>& reset, const ReactionModel& model);

// Reads "stages" for a session of `model`: each stage's params, freeze rule
// and reset are checked against the model they apply to.
std::vector<Stage> stagesFromJson(const nlohmann::json& json, const std::string& source,
                                  const ReactionModel& model);
nlohmann::json stagesToJson(const std::vector<Stage>& stages);

} // namespace morphogen
