#include "core/models/reaction_model.hpp"

#include <tuple>

#include "core/base/names.hpp"
#include "core/models/builtin_models.hpp"

namespace morphogen {

int ReactionModel::chemicalIndex(const std::string& name) const {
    for (std::size_t i = 0; i < m_chemicals.size(); ++i)
        if (m_chemicals[i].name == name)
            return int(i);
    return -1;
}

const ParamSpec* ReactionModel::param(const std::string& name) const {
    for (const ParamSpec& p : m_params)
        if (p.name == name)
            return &p;
    return nullptr;
}

namespace {
template <class Range, class Name> std::string joinNames(const Range& range, const Name& name) {
    std::string names;
    for (const auto& item : range)
        names += (names.empty() ? "" : ", ") + name(item);
    return names;
}
} // namespace

std::string ReactionModel::chemicalNames() const {
    return joinNames(m_chemicals, [](const ChemicalSpec& c) { return c.name; });
}

std::string ReactionModel::paramNames() const {
    return joinNames(m_params, [](const ParamSpec& p) { return p.name; });
}

std::string modelNames() {
    return joinNames(allModels(), [](const ReactionModel* m) { return m->name(); });
}

std::vector<float> ReactionModel::packParams(const ParamValues& values) const {
    std::vector<float> packed;
    packed.reserve(m_params.size());
    for (const ParamSpec& p : m_params) {
        auto it = values.find(p.name);
        packed.push_back(it == values.end() ? p.defaultValue : it->second);
    }
    return packed;
}

void ReactionModel::prepareState(State&, const ParamValues&, const NoiseField&) const {}

namespace {
template <class... Models> std::vector<const ReactionModel*> instances(ModelList<Models...>) {
    static const std::tuple<Models...> models;
    return {&std::get<Models>(models)...};
}
} // namespace

std::vector<const ReactionModel*> allModels() {
    return instances(BuiltinModels());
}

const ReactionModel* findModel(const std::string& name) {
    for (const ReactionModel* m : allModels())
        if (sameSpelling(m->name(), name))
            return m;
    return nullptr;
}

} // namespace morphogen
