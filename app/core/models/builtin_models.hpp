#pragma once

#include <typeinfo>

#include "core/models/gray_scott.hpp"
#include "core/models/meinhardt_stripes.hpp"
#include "core/models/turing_mcgraw.hpp"
#include "core/models/turing_turk.hpp"
#include "core/models/watercolour.hpp"
#include "core/models/witkin_kass.hpp"
#include "core/models/witkin_kass_multi.hpp"

namespace morphogen {

template <class... Models> struct ModelList {};

// Every built-in model, in the order allModels() lists them: the one place a
// new model is added. The registry (allModels, findModel) makes one instance
// of each, and the CPU backend instantiates its fused kernels over each one's
// Cell (cpu_kernels.cpp), both from this list.
using BuiltinModels =
    ModelList<GrayScottModel, TuringTurkModel, TuringMcGrawModel, WitkinKassModel, WitkinKassMd2,
              WitkinKassMd3, WitkinKassMd5, WitkinKassDa2, WitkinKassDa3, WitkinKassDa5,
              MeinhardtStripesModel, WatercolourModel>;

// Calls visit(model) for the built-in model of the exact type `model` has and
// returns true; false (and no call) for any other model. visit receives the
// model as its own type, so it can name Model::Cell.
template <class Visit, class... Models>
bool visitBuiltinModel(const ReactionModel& model, const Visit& visit, ModelList<Models...>) {
    // typeid, not dynamic_cast: a class derived from a built-in model may
    // change its reaction, and must not run on its base's Cell.
    return ((typeid(model) == typeid(Models) && (visit(static_cast<const Models&>(model)), true)) ||
            ...);
}

template <class Visit> bool visitBuiltinModel(const ReactionModel& model, const Visit& visit) {
    return visitBuiltinModel(model, visit, BuiltinModels());
}

} // namespace morphogen
