#include "cli/exploration.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/base/names.hpp"

namespace morphogen::cli {

SweepAxis parseAxis(const std::string& flag, const std::string& text, const ReactionModel& model) {
    std::stringstream in(text);
    std::string name, lo, hi;
    std::getline(in, name, ':');
    std::getline(in, lo, ':');
    std::getline(in, hi, ':');
    char* end1 = nullptr;
    char* end2 = nullptr;
    SweepAxis axis{name, std::strtof(lo.c_str(), &end1), std::strtof(hi.c_str(), &end2)};
    if (name.empty() || lo.empty() || hi.empty() || *end1 || *end2 || !in.eof())
        throw InputError(flag + " '" + text + "': expected PARAM:MIN:MAX, e.g. F:0.01:0.1");
    const ParamSpec* spec = model.param(name);
    if (!spec)
        throw InputError(flag + " '" + text + "': '" + name + "' is not a parameter of " +
                         model.name() + " (parameters: " + model.paramNames() + ")" +
                         didYouMean(name, splitNameList(model.paramNames())));
    if (axis.min < spec->min || axis.max > spec->max || !(axis.min < axis.max))
        throw InputError(flag + " '" + text + "': need MIN < MAX within " + name + "'s range [" +
                         std::to_string(spec->min) + ", " + std::to_string(spec->max) + "]");
    return axis;
}

Session explorationBase(const std::string& modelName, const std::string& preset,
                        const std::string& name) {
    if (modelName.empty() == preset.empty())
        throw InputError("give one of --model NAME or --preset NAME");
    if (!preset.empty()) {
        Session s = loadPreset(preset);
        // Maps and sweeps vary one model's parameters over one run.
        if (&s.outputModel() != &s.reactionModel())
            throw InputError("--preset " + preset + " switches from model '" + s.model + "' to '" +
                             s.outputModel().name() + "' in its stages; " + name +
                             " needs a single-model preset or --model");
        return s;
    }
    const ReactionModel* model = findModel(modelName);
    if (!model)
        throw InputError("--model '" + modelName + "' is unknown (known: " + modelNames() + ")" +
                         didYouMean(modelName, splitNameList(modelNames())));
    Session s;
    s.name = name;
    s.model = model->name();
    for (const ParamSpec& p : model->params())
        s.params[p.name] = p.defaultValue;
    s.dt = model->defaultDt();
    s.init = model->defaultInit();
    s.diffusion = model->defaultDiffusion();
    s.steps = 10000;
    s.colormap.name = "viridis";
    return s;
}

void keepSeedSpotDensity(Session& s, int side, bool fromPreset) {
    if (fromPreset || s.init.type != InitialCondition::Type::SeedSpots)
        return;
    const Session defaults; // the grid a model's default start is made for
    s.init.spotCount = std::max(1, int(double(s.init.spotCount) * side * side /
                                       (double(defaults.width) * defaults.height)));
}

ExplorationStart parseStartFlag(const std::string& text) {
    if (const std::optional<ExplorationStart> start = parseExplorationStart(text))
        return *start;
    throw InputError("--start '" + text + "' is unknown (accepted: " + explorationStartNames() +
                     ")" + didYouMean(text, splitNameList(explorationStartNames())));
}

void useStart(Session& s, ExplorationStart start, int side, bool fromPreset) {
    if (start == ExplorationStart::Noise)
        s.init = noiseStart(s.init, s.reactionModel());
    else
        keepSeedSpotDensity(s, side, fromPreset);
}

std::string startDescription(ExplorationStart start) {
    return start == ExplorationStart::Noise
               ? "noise start (perturbations over the whole area: the pattern each point "
                 "settles to)"
               : "preset start (the preset's or model's own start: growth fronts from its seeds)";
}

void checkPickSize(int size) {
    if (size < 16 || size > kMaxGridSide)
        throw InputError("--pick-size " + std::to_string(size) + ": accepted are 16.." +
                         std::to_string(kMaxGridSide) + " cells");
}

void writePick(const Session& picked, const std::string& path, const std::string& what,
               const SweepAxis& x, const SweepAxis& y) {
    saveSessionFile(picked, path);
    std::printf("picked %s: %s = %g, %s = %g\n", what.c_str(), x.param.c_str(),
                double(picked.params.at(x.param)), y.param.c_str(),
                double(picked.params.at(y.param)));
    std::printf("%s\n", path.c_str());
    std::fprintf(stderr,
                 "morphogen: wrote %s (%d x %d cells, %d steps); render it with: morphogen render "
                 "--session %s --out picked.png\n",
                 path.c_str(), picked.width, picked.height, picked.steps, path.c_str());
}

} // namespace morphogen::cli
