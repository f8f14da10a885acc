#include "core/session/cascade.hpp"

#include <algorithm>
#include <cassert>

#include <nlohmann/json.hpp>

#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/models/reaction_model.hpp"

namespace morphogen {

using nlohmann::json;

std::vector<std::uint8_t> applyFreezeRule(const FreezeRule& rule, const State& state,
                                          const ReactionModel& model,
                                          std::vector<std::uint8_t> frozen) {
    const int c = model.chemicalIndex(rule.chemical);
    assert(c >= 0 && "stagesFromJson checks the chemical");
    if (frozen.empty())
        frozen.assign(state.cellCount(), 0);
    const float* p = state.plane(c);
    for (std::size_t i = 0; i < state.cellCount(); ++i)
        if (p[i] >= rule.min && p[i] <= rule.max)
            frozen[i] = 1;
    return frozen;
}

void resetFrozenCells(State& state, const std::vector<std::uint8_t>& frozen,
                      const std::map<std::string, float>& reset, const ReactionModel& model) {
    for (const auto& [name, value] : reset) {
        float* p = state.plane(model.chemicalIndex(name));
        for (std::size_t i = 0; i < frozen.size(); ++i)
            if (frozen[i])
                p[i] = value;
    }
}

const ReactionModel& stageModel(const std::vector<Stage>& stages, std::size_t index,
                                const ReactionModel& sessionModel) {
    for (std::size_t i = std::min(index + 1, stages.size()); i-- > 0;)
        if (!stages[i].model.empty()) {
            const ReactionModel* m = findModel(stages[i].model);
            assert(m && "stagesFromJson checks the model");
            return *m;
        }
    return sessionModel;
}

std::vector<Stage> stagesFromJson(const json& j, const std::string& source,
                                  const ReactionModel& sessionModel) {
    if (!j.is_array() || j.empty())
        throw InputError(source + ": field 'stages' must be a non-empty array of stages "
                                  "{\"steps\": N, \"model\": \"...\", \"init\": {...}, "
                                  "\"dt\": x, \"params\": {...}, \"freeze\": {...}, "
                                  "\"reset\": {...}}");
    if (j.size() > std::size_t(kMaxStages))
        throw InputError(source + ": field 'stages' has " + std::to_string(j.size()) +
                         " stages; accepted are 1 to " + std::to_string(kMaxStages));
    std::vector<Stage> stages;
    const ReactionModel* model = &sessionModel; // the model the stage runs
    bool frozen = false;                        // a stage up to this one has a freeze rule
    for (std::size_t i = 0; i < j.size(); ++i) {
        FieldReader reader(j[i], source, "stages[" + std::to_string(i) + "]");
        reader.rejectUnknown({"steps", "model", "init", "dt", "params", "freeze", "reset"});
        Stage stage;
        stage.steps = int(reader.integer("steps", 0, 0, kMaxSteps));
        const ReactionModel* previous = model; // the model of the state the freeze rule reads
        if (reader.find("model")) {
            stage.model = reader.string("model", "");
            model = findModel(stage.model);
            if (!model)
                reader.failField("model", "is '" + stage.model +
                                              "', not a known model (known: " + modelNames() + ")" +
                                              didYouMean(stage.model, splitNameList(modelNames())));
            stage.model = model->name();
            if (i == 0)
                reader.failField("model", "cannot be set on the first stage: it runs the "
                                          "session's model ('" +
                                              sessionModel.name() + "')");
        }
        if (const json* init = reader.find("init")) {
            if (stage.model.empty())
                reader.failField("init", "is only accepted on a stage that sets 'model' (it is "
                                         "the new model's start)");
            stage.init = initialConditionFromJson(*init, source, reader.path("init"), *model);
        }
        if (reader.find("dt"))
            stage.dt = float(reader.number("dt", 1.0, kMinDt, kMaxDt));
        if (const json* params = reader.find("params")) {
            FieldReader p(*params, source, reader.path("params"));
            for (auto it = params->begin(); it != params->end(); ++it) {
                const ParamSpec* spec = model->param(it.key());
                if (!spec)
                    p.failField(it.key(),
                                "is not a parameter of model '" + model->name() +
                                    "' (parameters: " + model->paramNames() + ")" +
                                    didYouMean(it.key(), splitNameList(model->paramNames())));
                stage.params[it.key()] = float(p.numberValue(*it, it.key(), spec->min, spec->max));
            }
        }
        if (const json* freeze = reader.find("freeze")) {
            FieldReader f(*freeze, source, reader.path("freeze"));
            f.rejectUnknown({"chemical", "min", "max"});
            FreezeRule rule;
            rule.chemical = f.string("chemical", "");
            if (previous->chemicalIndex(rule.chemical) < 0)
                f.failField(
                    "chemical",
                    "is '" + rule.chemical + "', not a chemical of model '" + previous->name() +
                        (previous != model ? "' (the previous stage's model, whose "
                                             "result the rule reads; chemicals: "
                                           : "' (chemicals: ") +
                        previous->chemicalNames() + ")" +
                        didYouMean(rule.chemical, splitNameList(previous->chemicalNames())));
            rule.min = float(f.number("min", -1e30, -1e30, 1e30));
            rule.max = float(f.number("max", 1e30, -1e30, 1e30));
            if (rule.min > rule.max)
                f.failField("min", "is above max");
            // The rule picks cells from the previous stage's result; before
            // the first stage there is none, so it would freeze nothing.
            if (i == 0)
                reader.failField("freeze", "cannot be on the first stage: a freeze rule picks "
                                           "cells from the previous stage's result (put it on "
                                           "the stage after the one whose result it reads)");
            stage.freeze = rule;
        }
        frozen = frozen || stage.freeze.has_value();
        if (const json* reset = reader.find("reset")) {
            // Reset writes the frozen cells only: without a freeze rule up to
            // here there are none, and the stage would silently do nothing.
            if (!frozen)
                reader.failField("reset", "needs frozen cells: add a \"freeze\" rule to this "
                                          "stage or an earlier one");
            FieldReader r(*reset, source, reader.path("reset"));
            for (auto it = reset->begin(); it != reset->end(); ++it) {
                if (model->chemicalIndex(it.key()) < 0)
                    r.failField(it.key(),
                                "is not a chemical of model '" + model->name() +
                                    "' (chemicals: " + model->chemicalNames() + ")" +
                                    didYouMean(it.key(), splitNameList(model->chemicalNames())));
                stage.reset[it.key()] = float(r.numberValue(*it, it.key(), -1e6, 1e6));
            }
        }
        stages.push_back(stage);
    }
    return stages;
}

json stagesToJson(const std::vector<Stage>& stages) {
    json j = json::array();
    for (const Stage& s : stages) {
        json stage;
        stage["steps"] = s.steps;
        if (!s.model.empty())
            stage["model"] = s.model;
        if (s.init)
            stage["init"] = initialConditionToJson(*s.init);
        if (s.dt)
            stage["dt"] = *s.dt;
        if (!s.params.empty())
            stage["params"] = s.params;
        if (s.freeze)
            stage["freeze"] = {
                {"chemical", s.freeze->chemical}, {"min", s.freeze->min}, {"max", s.freeze->max}};
        if (!s.reset.empty())
            stage["reset"] = s.reset;
        j.push_back(stage);
    }
    return j;
}

} // namespace morphogen
