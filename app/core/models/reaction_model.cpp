#include "core/models/reaction_model.hpp"

#include <cassert>

#include "core/models/gray_scott.hpp"
#include "core/models/meinhardt_stripes.hpp"
#include "core/models/turing_mcgraw.hpp"
#include "core/models/turing_turk.hpp"
#include "core/models/witkin_kass.hpp"
#include "core/models/witkin_kass_multi.hpp"

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

void ReactionModel::prepareState(State&, const ParamValues&, std::uint64_t) const {}

std::vector<const ReactionModel*> allModels() {
    static const GrayScottModel grayScott;
    static const TuringTurkModel turingTurk;
    static const TuringMcGrawModel turingMcGraw;
    static const WitkinKassModel witkinKass;
    static const MeinhardtStripesModel meinhardtStripes;
    static const WitkinKassMd2 witkinKassMd2;
    static const WitkinKassMd3 witkinKassMd3;
    static const WitkinKassMd5 witkinKassMd5;
    static const WitkinKassDa2 witkinKassDa2;
    static const WitkinKassDa3 witkinKassDa3;
    static const WitkinKassDa5 witkinKassDa5;
    return {&grayScott,     &turingTurk,    &turingMcGraw,    &witkinKass,
            &witkinKassMd2, &witkinKassMd3, &witkinKassMd5,   &witkinKassDa2,
            &witkinKassDa3, &witkinKassDa5, &meinhardtStripes};
}

const ReactionModel* findModel(const std::string& name) {
    for (const ReactionModel* m : allModels())
        if (m->name() == name)
            return m;
    return nullptr;
}

} // namespace morphogen
