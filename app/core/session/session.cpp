#include "core/session/session.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/base/embedded_files.hpp"
#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/json_input.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/io/output_files.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/session/gradient.hpp"
#include "core/session/watercolour_strokes.hpp"

namespace morphogen {

using nlohmann::json;

namespace {

const EnumName<Integrator> kIntegrators[] = {{Integrator::ExplicitEuler, "explicit_euler"},
                                             {Integrator::SemiImplicit, "semi_implicit"}};

const EnumAlias<Integrator> kIntegratorAliases[] = {{"euler", Integrator::ExplicitEuler},
                                                    {"explicit", Integrator::ExplicitEuler},
                                                    {"semiimplicit", Integrator::SemiImplicit},
                                                    {"imex", Integrator::SemiImplicit}};

} // namespace

std::string toString(Integrator integrator) {
    return nameOf(kIntegrators, integrator);
}

std::optional<Integrator> parseIntegrator(std::string_view name) {
    return valueNamed(kIntegrators, kIntegratorAliases, name);
}

std::string integratorNames() {
    return nameList(kIntegrators);
}

Domain Session::domain() const {
    if (atlas)
        return Domain::atlas(atlas, atlasWeights);
    if (tiles.active())
        return Domain::tiledGrid(width, height, tiles.columns, tiles.rows);
    return GridDomain(width, height, edges);
}

double Session::cellSize() const {
    if (atlas || tiles.active() || length <= 0)
        return 1.0;
    return length / width;
}

void resizeSession(Session& session, int width, int height) {
    if (session.length <= 0)
        session.length = session.width;
    session.width = width;
    session.height = height;
}

void useAtlas(Session& session, std::shared_ptr<const Atlas> atlas) {
    assert(atlas);
    session.width = atlas->width();
    session.height = atlas->height();
    session.schedule.clear();
    session.tiles = TileGrid{};
    session.atlas = std::move(atlas);
    session.atlasWeights.reset();
}

void useAtlas(Session& session, std::shared_ptr<const Atlas> atlas,
              std::shared_ptr<const AtlasWeights> weights) {
    assert(atlas);
    if (weights)
        checkAtlasWeights(*atlas, *weights);
    useAtlas(session, std::move(atlas));
    session.atlasWeights = std::move(weights);
}

const ReactionModel& Session::reactionModel() const {
    const ReactionModel* m = findModel(model);
    assert(m && "sessionFromJson rejects unknown models");
    return *m;
}

const ReactionModel& Session::outputModel() const {
    return stages.empty() ? reactionModel()
                          : stageModel(stages, stages.size() - 1, reactionModel());
}

namespace {

std::array<float, 3> colour(const FieldReader& reader, const std::string& key,
                            std::array<float, 3> fallback) {
    const json* j = reader.find(key);
    if (!j)
        return fallback;
    if (!j->is_array() || j->size() != 3)
        reader.failField(key, "must be an array of 3 numbers in [0, 1] (sRGB)");
    std::array<float, 3> rgb{};
    for (std::size_t i = 0; i < 3; ++i)
        rgb[i] = float(reader.numberValue((*j)[i], key + "[" + std::to_string(i) + "]", 0, 1));
    return rgb;
}

// A batched sweep's tiles, checked against the rest of the session.
TileGrid tilesFromJson(const json& j, const FieldReader& top, const Session& s,
                       const ReactionModel& model) {
    TileGrid tiles = tileGridFromJson(j, top.source(), model);
    if (s.width % tiles.columns != 0 || s.height % tiles.rows != 0 || s.width / tiles.columns < 4 ||
        s.height / tiles.rows < 4)
        top.failField("tiles", "grid [" + std::to_string(tiles.columns) + ", " +
                                   std::to_string(tiles.rows) + "] must split the " +
                                   std::to_string(s.width) + " x " + std::to_string(s.height) +
                                   " grid evenly into tiles of at least 4 x 4 cells");
    if (s.edges != EdgeMode::Periodic)
        top.failField("tiles", "need periodic edges (each tile wraps on its own)");
    if (!s.schedule.empty())
        top.failField("tiles", "cannot be combined with a coarse-to-fine schedule");
    if (!s.paramMaps.empty())
        top.failField("tiles", "cannot be combined with param_maps (tiles.params sets "
                               "per-tile values)");
    if (tiles.params.size() > 4)
        top.failField("tiles", "may vary at most 4 parameters per tile");
    for (const Stage& stage : s.stages) {
        if (!stage.model.empty())
            top.failField("tiles", "cannot be combined with a stage that changes the model");
        for (const auto& [name, value] : stage.params)
            if (tiles.params.count(name))
                top.failField("stages", "change '" + name + "', which tiles sets per tile");
    }
    return tiles;
}

} // namespace

namespace {

ParamValues paramsFromJson(const FieldReader& top, const ReactionModel& model) {
    ParamValues params;
    for (const ParamSpec& p : model.params())
        params[p.name] = p.defaultValue;
    const json* given = top.find("params");
    if (!given)
        return params;
    FieldReader reader(*given, top.source(), "params");
    for (auto it = given->begin(); it != given->end(); ++it) {
        const ParamSpec* spec = model.param(it.key());
        if (!spec)
            reader.fail("field 'params." + it.key() + "'",
                        "is not a parameter of model '" + model.name() +
                            "' (parameters: " + model.paramNames() + ")" +
                            didYouMean(it.key(), splitNameList(model.paramNames())));
        params[it.key()] = float(reader.numberValue(*it, it.key(), spec->min, spec->max));
    }
    return params;
}

// "size": N or [W, H].
void readSize(const FieldReader& top, Session& s) {
    const json* size = top.find("size");
    if (!size)
        return;
    if (size->is_number_integer()) {
        s.width = s.height = int(top.integer("size", 0, 1, kMaxGridSide));
    } else if (size->is_array() && size->size() == 2) {
        FieldReader dummy(json::object(), top.source(), "");
        s.width = int(dummy.numberValue((*size)[0], "size[0]", 1, kMaxGridSide));
        s.height = int(dummy.numberValue((*size)[1], "size[1]", 1, kMaxGridSide));
        if (!(*size)[0].is_number_integer() || !(*size)[1].is_number_integer())
            top.failField("size", "must hold integers");
    } else {
        top.failField("size", "must be an integer N or an array [W, H], got " + size->dump());
    }
}

std::vector<ScheduleLevel> scheduleFromJson(const FieldReader& top, const json& schedule) {
    if (!schedule.is_array() || schedule.empty())
        top.failField("schedule", "must be a non-empty array of {\"size\": N or [W, H], "
                                  "\"steps\": N}, coarsest first");
    if (schedule.size() > std::size_t(kMaxScheduleLevels))
        top.failField("schedule", "has " + std::to_string(schedule.size()) +
                                      " levels; accepted are 1 to " +
                                      std::to_string(kMaxScheduleLevels));
    std::vector<ScheduleLevel> levels;
    long long total = 0;
    for (std::size_t i = 0; i < schedule.size(); ++i) {
        FieldReader level(schedule[i], top.source(), "schedule[" + std::to_string(i) + "]");
        level.rejectUnknown({"size", "steps"});
        ScheduleLevel l;
        const json* size = level.find("size");
        if (!size)
            level.failField("size", "is missing: every level needs its \"size\": N or [W, H]");
        if (!level.find("steps"))
            level.failField("steps", "is missing: every level needs its \"steps\": N");
        if (size->is_array()) {
            if (size->size() != 2 || !(*size)[0].is_number_integer() ||
                !(*size)[1].is_number_integer())
                level.failField("size", "must be an integer N or an array [W, H] of integers");
            l.width = int(level.numberValue((*size)[0], "size[0]", 1, kMaxGridSide));
            l.height = int(level.numberValue((*size)[1], "size[1]", 1, kMaxGridSide));
        } else {
            l.width = l.height = int(level.integer("size", 0, 1, kMaxGridSide));
        }
        l.steps = int(level.integer("steps", 0, 0, kMaxSteps));
        total += l.steps;
        if (i > 0 && (l.width < levels.back().width || l.height < levels.back().height))
            level.failField("size", "is " + std::to_string(l.width) + " x " +
                                        std::to_string(l.height) + ", smaller than level " +
                                        std::to_string(i - 1) + "'s " +
                                        std::to_string(levels.back().width) + " x " +
                                        std::to_string(levels.back().height) +
                                        ": levels go from coarse to fine");
        levels.push_back(l);
    }
    if (total > kMaxSteps)
        top.failField("schedule", "levels add up to " + std::to_string(total) +
                                      " steps in all; accepted are up to " +
                                      std::to_string(kMaxSteps));
    return levels;
}

// "stages" (Turk's cascades); the session's steps become their total.
void readStages(const FieldReader& top, const json& stages, const ReactionModel& model,
                Session& s) {
    if (!s.schedule.empty())
        top.failField("stages", "cannot be combined with a coarse-to-fine schedule");
    s.stages = stagesFromJson(stages, top.source(), model);
    long long total = 0;
    bool changesModel = false;
    for (const Stage& stage : s.stages) {
        total += stage.steps;
        changesModel = changesModel || !stage.model.empty();
    }
    if (total > kMaxSteps)
        top.failField("stages", "add up to " + std::to_string(total) +
                                    " steps in all; accepted are up to " +
                                    std::to_string(kMaxSteps));
    s.steps = int(total);
    // Anisotropic and generalized diffusion name the session model's chemicals.
    if (changesModel && s.diffusion.type != DiffusionType::Isotropic)
        top.failField("stages", "change the model, which needs isotropic diffusion (field "
                                "'diffusion' has type '" +
                                    toString(s.diffusion.type) + "')");
}

void readParamMaps(const FieldReader& top, const json& maps, const ReactionModel& model,
                   Session& s) {
    if (!s.schedule.empty())
        top.failField("param_maps", "cannot be combined with a coarse-to-fine schedule");
    s.paramMaps = paramMapsFromJson(maps, top.source(), model);
    for (const Stage& stage : s.stages)
        if (!stage.model.empty())
            top.failField("param_maps", "cannot be combined with a stage that changes the "
                                        "model (they are maps of model '" +
                                            model.name() + "' parameters)");
    for (const Stage& stage : s.stages)
        for (const auto& [name, value] : stage.params)
            if (s.paramMaps.count(name))
                top.failField("stages", "change '" + name + "', which param_maps sets per cell");
}

// "colormap"; its chemical must be one of `shown`, the model of the final state.
// The map's name as written (colormap.hpp's isWatercolourMap would throw on
// a name not yet checked).
bool namesWatercolour(const std::string& name) {
    return name == "watercolour" || name == "watercolor";
}

ColorMapSpec colormapFromJson(const FieldReader& top, const json& cm, const ReactionModel& shown,
                              bool lastStageModel) {
    FieldReader reader(cm, top.source(), "colormap");
    reader.rejectUnknown({"name", "chemical", "low", "high", "levels", "colours", "colors",
                          "edge_darkening", "edge_width"});
    ColorMapSpec spec;
    const json* colours = reader.find("colours");
    if (!colours)
        colours = reader.find("colors");
    // Stops without a name are a custom map; a named map with stops is a contradiction.
    spec.name = reader.string("name", colours ? "custom" : spec.name);
    if (colours) {
        if (!isCustomColormapName(spec.name))
            reader.failField("colours",
                             "apply only to the map named \"custom\", not '" + spec.name + "'");
        if (!colours->is_array())
            reader.failField("colours", "must be an array of \"#rrggbb\" or \"#rgb\" strings");
        for (std::size_t i = 0; i < colours->size(); ++i) {
            const json& c = (*colours)[i];
            const std::optional<std::array<float, 3>> rgb =
                c.is_string() ? parseHexColour(c.get<std::string>()) : std::nullopt;
            if (!rgb)
                reader.failField("colours[" + std::to_string(i) + "]",
                                 "is " + c.dump() + ", not a \"#rrggbb\" or \"#rgb\" colour");
            spec.colours.push_back(*rgb);
        }
        if (spec.colours.size() < 2 || spec.colours.size() > std::size_t(kMaxGradientStops))
            reader.failField("colours", "has " + std::to_string(spec.colours.size()) +
                                            " colours (accepted: 2 to " +
                                            std::to_string(kMaxGradientStops) + ")");
    } else if (isCustomColormapName(spec.name)) {
        reader.failField("name", "is 'custom', which needs \"colours\": [\"#rrggbb\", ...]");
    }
    if (namesWatercolour(spec.name) && !paintsAsWatercolour(shown))
        reader.failField("name", "is 'watercolour', which paints the watercolour model's "
                                 "pigments; model '" +
                                     shown.name() + "' has none (use another map)");
    spec.chemical = reader.string("chemical", "");
    if (!spec.chemical.empty() && shown.chemicalIndex(spec.chemical) < 0)
        reader.failField("chemical",
                         "is '" + spec.chemical + "', not a chemical of model '" + shown.name() +
                             "'" + (lastStageModel ? " (the last stage's model)" : "") +
                             didYouMean(spec.chemical, splitNameList(shown.chemicalNames())));
    spec.low = colour(reader, "low", spec.low);
    spec.high = colour(reader, "high", spec.high);
    if (const json* levels = reader.find("levels")) {
        if (!levels->is_array() || levels->size() != 2)
            reader.failField("levels", "must be an array [low, high] with 0 <= low < high <= 1");
        for (std::size_t i = 0; i < 2; ++i)
            spec.levels[i] =
                float(reader.numberValue((*levels)[i], "levels[" + std::to_string(i) + "]", 0, 1));
        if (!(spec.levels[0] < spec.levels[1]))
            reader.failField("levels", "must be an array [low, high] with 0 <= low < high <= 1");
    }
    for (const char* key : {"edge_darkening", "edge_width"})
        if (!namesWatercolour(spec.name) && reader.find(key))
            reader.failField(key, "applies only to the map named \"watercolour\", not '" +
                                      spec.name + "'");
    spec.edgeDarkening = float(reader.number("edge_darkening", spec.edgeDarkening, 0, 4));
    spec.edgeWidth = float(reader.number("edge_width", spec.edgeWidth, 0.001, 0.25));
    return spec;
}

} // namespace

Session sessionFromJson(const json& root, const std::string& source) {
    FieldReader top(root, source, "");
    top.rejectUnknown({"name",           "description", "model",
                       "params",         "size",        "edges",
                       "diffusion",      "integrator",  "relaxation_passes",
                       "jacobi_sweeps",  "schedule",    "stages",
                       "param_maps",     "tiles",       "dt",
                       "steps",          "seed",        "init",
                       "colormap",       "height",      "length",
                       "coarse_to_fine", "surface",     "edits",
                       "strokes",        "gravity"});
    Session s;
    s.name = top.string("name", "");
    s.description = top.string("description", "");
    s.model = top.string("model", s.model);
    const ReactionModel* model = findModel(s.model);
    if (!model)
        top.failField("model", "is '" + s.model + "', not a known model (known: " + modelNames() +
                                   ")" + didYouMean(s.model, splitNameList(modelNames())));
    s.model = model->name();
    s.params = paramsFromJson(top, *model);
    readSize(top, s);
    s.length = top.number("length", 0.0, kMinLength, kMaxLength);
    s.coarseToFine = top.boolean("coarse_to_fine", s.coarseToFine);
    s.edges = top.choice("edges", s.edges, parseEdgeMode, edgeModeNames());

    // Like "init", a session's "diffusion" replaces the model's default whole.
    s.diffusion = model->defaultDiffusion();
    if (const json* diffusion = top.find("diffusion"))
        s.diffusion = diffusionFromJson(*diffusion, source, *model);
    if (const json* gravity = top.find("gravity"))
        s.gravity = gravityFromJson(top, *gravity);

    s.integrator = top.choice("integrator", s.integrator, parseIntegrator, integratorNames());
    s.integratorGiven = top.find("integrator") != nullptr;
    // "jacobi_sweeps" is the name sessions written before the rename use.
    s.relaxationPasses =
        int(top.integer("jacobi_sweeps", s.relaxationPasses, 1, kMaxRelaxationPasses));
    s.relaxationPasses =
        int(top.integer("relaxation_passes", s.relaxationPasses, 1, kMaxRelaxationPasses));

    s.dt = float(top.number("dt", model->defaultDt(), kMinDt, kMaxDt));
    s.steps = int(top.integer("steps", s.steps, 0, kMaxSteps));
    s.seed = std::uint64_t(top.integer("seed", 1, 0, kMaxSeed));

    if (const json* schedule = top.find("schedule"))
        applySchedule(s, scheduleFromJson(top, *schedule));
    if (const json* stages = top.find("stages"))
        readStages(top, *stages, *model, s);
    if (const json* maps = top.find("param_maps"))
        readParamMaps(top, *maps, *model, s);

    if (const json* tiles = top.find("tiles"))
        s.tiles = tilesFromJson(*tiles, top, s, *model);

    // A session's "init" replaces the model's default start whole: fields it
    // leaves out are empty, not inherited.
    s.init = model->defaultInit();
    if (const json* init = top.find("init"))
        s.init = initialConditionFromJson(*init, source, "init", *model);

    // The colours show the final state: the last stage's model's chemicals.
    if (const json* cm = top.find("colormap"))
        s.colormap = colormapFromJson(top, *cm, s.outputModel(), &s.outputModel() != model);
    if (const json* height = top.find("height"))
        s.heightMaps = heightSpecFromJson(top, *height);
    if (const json* surface = top.find("surface"))
        s.surface = surfaceSpecFromJson(top, *surface);
    if (const json* edits = top.find("edits"))
        s.edits = liveEditsFromJson(top, *edits, s);
    if (const json* strokes = top.find("strokes"))
        addWatercolourStrokes(top, *strokes, s);
    return s;
}

json sessionToJson(const Session& s) {
    json j;
    if (!s.name.empty())
        j["name"] = s.name;
    if (!s.description.empty())
        j["description"] = s.description;
    j["model"] = s.model;
    j["params"] = s.params;
    j["size"] = json::array({s.width, s.height});
    if (s.length > 0)
        j["length"] = s.length;
    if (!s.coarseToFine)
        j["coarse_to_fine"] = false;
    j["edges"] = toString(s.edges);
    j["diffusion"] = diffusionToJson(s.diffusion);
    if (s.gravity.active())
        j["gravity"] = gravityToJson(s.gravity);
    j["integrator"] = toString(s.integrator);
    if (s.integrator == Integrator::SemiImplicit)
        j["relaxation_passes"] = s.relaxationPasses;
    if (!s.stages.empty())
        j["stages"] = stagesToJson(s.stages);
    if (!s.paramMaps.empty())
        j["param_maps"] = paramMapsToJson(s.paramMaps);
    if (s.tiles.active())
        j["tiles"] = tileGridToJson(s.tiles);
    if (!s.schedule.empty()) {
        j["schedule"] = json::array();
        for (const ScheduleLevel& l : s.schedule)
            j["schedule"].push_back({{"size", {l.width, l.height}}, {"steps", l.steps}});
    }
    j["dt"] = s.dt;
    j["steps"] = s.steps;
    j["seed"] = s.seed;
    j["init"] = initialConditionToJson(s.init);
    json cm;
    cm["name"] = s.colormap.name;
    if (!s.colormap.chemical.empty())
        cm["chemical"] = s.colormap.chemical;
    cm["low"] = s.colormap.low;
    cm["high"] = s.colormap.high;
    if (isCustomColormapName(s.colormap.name)) {
        cm["colours"] = json::array();
        for (const std::array<float, 3>& c : s.colormap.colours)
            cm["colours"].push_back(hexColour(c));
    }
    if (s.colormap.levels != ColorMapSpec{}.levels)
        cm["levels"] = s.colormap.levels;
    if (namesWatercolour(s.colormap.name)) {
        cm["edge_darkening"] = s.colormap.edgeDarkening;
        cm["edge_width"] = s.colormap.edgeWidth;
    }
    j["colormap"] = cm;
    if (s.heightMaps != HeightSpec{})
        j["height"] = heightSpecToJson(s.heightMaps);
    if (s.surface.active())
        j["surface"] = surfaceSpecToJson(s.surface);
    if (!s.edits.empty())
        j["edits"] = liveEditsToJson(s.edits);
    return j;
}

Session loadSessionFile(const std::string& path) {
    const json j = parseJsonText(readInputFile(path, "session file"), path);
    Session s = sessionFromJson(j, path);
    s.baseDir = std::filesystem::path(path).parent_path().string();
    validateSession(s, path);
    return s;
}

void saveSessionFile(const Session& session, const std::string& path) {
    writeTextAtomically(path, sessionToJson(session).dump(2) + "\n");
}

std::vector<Session> allPresets() {
    std::vector<Session> presets;
    for (std::string_view path : embeddedFiles("models/presets/")) {
        const std::string source(path);
        const json j = parseJsonText(*embeddedFile(path), source);
        Session s = sessionFromJson(j, source);
        if (s.name.empty())
            s.name = std::filesystem::path(source).stem().string();
        presets.push_back(std::move(s));
    }
    return presets;
}

Session loadPreset(const std::string& name) {
    std::vector<std::string> names;
    for (Session& s : allPresets()) {
        if (sameSpelling(s.name, name))
            return s;
        names.push_back(s.name);
    }
    throw InputError("unknown preset '" + name + "' (known: " + joinNames(names) +
                     "; `morphogen presets` lists them)" + didYouMean(name, names));
}

void applyParamOverride(Session& session, const std::string& assignment) {
    const auto eq = assignment.find('=');
    const ReactionModel& model = session.reactionModel();
    if (eq == std::string::npos || eq == 0)
        throw InputError("--param '" + assignment + "': expected name=value (parameters of " +
                         model.name() + ": " + model.paramNames() + ")");
    const std::string name = assignment.substr(0, eq);
    const std::string text = assignment.substr(eq + 1);
    const ParamSpec* spec = model.param(name);
    if (!spec)
        throw InputError("--param '" + assignment + "': '" + name + "' is not a parameter of " +
                         model.name() + " (parameters: " + model.paramNames() + ")" +
                         didYouMean(name, splitNameList(model.paramNames())));
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
        throw InputError("--param '" + assignment + "': '" + text + "' is not a number");
    if (v < spec->min || v > spec->max) {
        std::ostringstream os;
        os << "--param '" << assignment << "': " << name << " must be in [" << spec->min << ", "
           << spec->max << "]";
        throw InputError(os.str());
    }
    session.params[name] = float(v);
}

void applySchedule(Session& session, std::vector<ScheduleLevel> levels) {
    assert(!levels.empty());
    long long total = 0;
    for (const ScheduleLevel& l : levels)
        total += l.steps;
    if (total > kMaxSteps)
        throw InputError("the schedule's levels have " + std::to_string(total) +
                         " steps in all; accepted are up to " + std::to_string(kMaxSteps));
    session.schedule = std::move(levels);
    session.width = session.schedule.back().width;
    session.height = session.schedule.back().height;
    session.steps = int(total);
}

void applySteps(Session& session, int steps, const std::string& flag) {
    if (!session.stages.empty())
        throw InputError(flag + " does not apply to a session with cascade \"stages\" (" +
                         std::to_string(session.stages.size()) +
                         " stages of their own steps): edit the stages' \"steps\"");
    if (!session.schedule.empty())
        throw InputError(flag + " does not apply to a session with a coarse-to-fine "
                                "\"schedule\": edit its levels or use --schedule");
    session.steps = steps;
}

namespace {

std::string numberText(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

// The checks of cascade stages against their models and each other, in one
// pass (a stage's model is the last one set up to it).
void validateStages(const Session& s, const ReactionModel& sessionModel,
                    const std::string& source) {
    if (s.stages.size() > std::size_t(kMaxStages))
        throw InputError(source + ": " + std::to_string(s.stages.size()) +
                         " cascade stages; accepted are up to " + std::to_string(kMaxStages));
    const ReactionModel* m = &sessionModel;
    bool frozen = false;
    long long total = 0;
    for (std::size_t i = 0; i < s.stages.size(); ++i) {
        const Stage& stage = s.stages[i];
        const std::string where = source + ": stages[" + std::to_string(i) + "]";
        if (!stage.model.empty()) {
            m = findModel(stage.model);
            if (!m)
                throw InputError(where + ".model '" + stage.model + "' is not a known model");
        }
        for (const auto& [name, value] : stage.params) {
            const ParamSpec* p = m->param(name);
            if (!p)
                throw InputError(where + ".params." + name + " is not a parameter of model '" +
                                 m->name() + "'" +
                                 didYouMean(name, splitNameList(m->paramNames())));
            if (!std::isfinite(value) || value < p->min || value > p->max) {
                std::ostringstream os;
                os << where << ".params." << name << " = " << value << " is outside [" << p->min
                   << ", " << p->max << "]";
                throw InputError(os.str());
            }
        }
        if (stage.steps < 0 || stage.steps > kMaxSteps)
            throw InputError(where + ".steps is " + std::to_string(stage.steps) +
                             ", accepted range is [0, " + std::to_string(kMaxSteps) + "]");
        if (stage.dt && !(*stage.dt >= float(kMinDt) && *stage.dt <= float(kMaxDt)))
            throw InputError(where + ".dt is " + numberText(*stage.dt) + ", accepted range is [" +
                             numberText(kMinDt) + ", " + numberText(kMaxDt) + "]");
        frozen = frozen || stage.freeze.has_value();
        if (!stage.reset.empty() && !frozen)
            throw InputError(where + ".reset: no stage up to this one has a \"freeze\" rule, "
                                     "so no cells are frozen to reset: add \"freeze\" to this "
                                     "stage or an earlier one");
        total += stage.steps;
    }
    if (!s.stages.empty() && total > kMaxSteps)
        throw InputError(source + ": the stages have " + std::to_string(total) +
                         " steps in all; accepted are up to " + std::to_string(kMaxSteps));
}

void validateSchedule(const Session& s, const std::string& source) {
    if (s.schedule.empty())
        return;
    if (s.schedule.size() > std::size_t(kMaxScheduleLevels))
        throw InputError(source + ": the schedule has " + std::to_string(s.schedule.size()) +
                         " levels; accepted are 1 to " + std::to_string(kMaxScheduleLevels));
    long long total = 0;
    for (std::size_t i = 0; i < s.schedule.size(); ++i) {
        const ScheduleLevel& l = s.schedule[i];
        const std::string where = source + ": schedule level " + std::to_string(i);
        if (l.width < 1 || l.height < 1 || l.width > kMaxGridSide || l.height > kMaxGridSide)
            throw InputError(where + " is " + std::to_string(l.width) + " x " +
                             std::to_string(l.height) + "; accepted are sides of 1.." +
                             std::to_string(kMaxGridSide));
        if (l.steps < 0 || l.steps > kMaxSteps)
            throw InputError(where + " has " + std::to_string(l.steps) +
                             " steps; accepted are 0.." + std::to_string(kMaxSteps));
        if (i > 0 && (l.width < s.schedule[i - 1].width || l.height < s.schedule[i - 1].height))
            throw InputError(where + " (" + std::to_string(l.width) + " x " +
                             std::to_string(l.height) +
                             ") is smaller than the level before it: "
                             "levels go from coarse to fine");
        total += l.steps;
    }
    if (total > kMaxSteps)
        throw InputError(source + ": the schedule's levels have " + std::to_string(total) +
                         " steps in all; accepted are up to " + std::to_string(kMaxSteps));
    const ScheduleLevel& last = s.schedule.back();
    if (last.width != s.width || last.height != s.height)
        throw InputError(source + ": the schedule's last level is " + std::to_string(last.width) +
                         " x " + std::to_string(last.height) + ", not the session's size " +
                         std::to_string(s.width) + " x " + std::to_string(s.height));
    if (!s.paramMaps.empty())
        throw InputError(source + ": a coarse-to-fine schedule does not combine with "
                                  "\"param_maps\"");
}

void validateTiles(const Session& s, const std::string& source) {
    if (!s.tiles.active())
        return;
    const TileGrid& t = s.tiles;
    // 64-bit: the products must not wrap before they are compared.
    const bool whole = t.columns >= 1 && t.rows >= 1 && t.columns <= kMaxTilesPerSide &&
                       t.rows <= kMaxTilesPerSide && s.width % t.columns == 0 &&
                       s.height % t.rows == 0 &&
                       static_cast<long long>(t.columns) * kMinTileCells <= s.width &&
                       static_cast<long long>(t.rows) * kMinTileCells <= s.height;
    if (!whole || s.edges != EdgeMode::Periodic)
        throw InputError(
            source + ": tiles grid [" + std::to_string(t.columns) + ", " + std::to_string(t.rows) +
            "] must split the " + std::to_string(s.width) + " x " + std::to_string(s.height) +
            " grid evenly into periodic tiles of at least " + std::to_string(kMinTileCells) +
            " x " + std::to_string(kMinTileCells) + " cells");
    if (!s.schedule.empty())
        throw InputError(source + ": \"tiles\" do not combine with a coarse-to-fine schedule");
    if (!s.paramMaps.empty())
        throw InputError(source + ": \"tiles\" do not combine with \"param_maps\" (tiles.params "
                                  "sets per-tile values)");
}

} // namespace

void validateSession(const Session& s, const std::string& source) {
    const ReactionModel* model = findModel(s.model);
    if (!model)
        throw InputError(source + ": unknown model '" + s.model + "' (known: " + modelNames() +
                         ")" + didYouMean(s.model, splitNameList(modelNames())));
    for (const ParamSpec& p : model->params()) {
        auto it = s.params.find(p.name);
        if (it == s.params.end())
            throw InputError(source + ": parameter '" + p.name + "' is missing");
        if (!std::isfinite(it->second) || it->second < p.min || it->second > p.max) {
            std::ostringstream os;
            os << source << ": parameter " << p.name << " = " << it->second << " is outside ["
               << p.min << ", " << p.max << "]";
            throw InputError(os.str());
        }
    }
    validateStages(s, *model, source);
    if (s.width < 1 || s.height < 1 || s.width > kMaxGridSide || s.height > kMaxGridSide)
        throw InputError(source + ": size " + std::to_string(s.width) + "x" +
                         std::to_string(s.height) + " is outside 1.." +
                         std::to_string(kMaxGridSide) + " per side");
    if (s.length != 0 && !(s.length >= kMinLength && s.length <= kMaxLength))
        throw InputError(source + ": the image is " + numberText(s.length) +
                         " model units wide (length, divided by --scale); accepted are " +
                         numberText(kMinLength) + " to " + numberText(kMaxLength));
    if (!(s.dt >= float(kMinDt) && s.dt <= float(kMaxDt)))
        throw InputError(source + ": dt is " + numberText(s.dt) + ", accepted range is [" +
                         numberText(kMinDt) + ", " + numberText(kMaxDt) + "]");
    if (s.steps < 0 || s.steps > kMaxSteps)
        throw InputError(source + ": steps is " + std::to_string(s.steps) +
                         ", accepted range is [0, " + std::to_string(kMaxSteps) + "]");
    if (s.seed > std::uint64_t(kMaxSeed))
        throw InputError(source + ": seed is " + std::to_string(s.seed) +
                         ", accepted range is [0, " + std::to_string(kMaxSeed) + "]");
    if (s.relaxationPasses < 1 || s.relaxationPasses > kMaxRelaxationPasses)
        throw InputError(source + ": relaxation passes is " + std::to_string(s.relaxationPasses) +
                         ", accepted range is [1, " + std::to_string(kMaxRelaxationPasses) + "]");
    if (!s.schedule.empty() && !s.stages.empty())
        throw InputError(source + ": a coarse-to-fine \"schedule\" does not combine with "
                                  "cascade \"stages\": give one of them");
    validateSchedule(s, source);
    // A size override must keep a batched sweep's tiles whole.
    validateTiles(s, source);
    checkLiveEdits(s, s.steps, source);
}

namespace {

void orientationImages(const OrientationField& field, std::vector<std::string>& images) {
    if (field.type == OrientationField::Type::ImageGradient)
        images.push_back(field.image);
    for (const OrientationField& part : field.parts)
        orientationImages(part, images);
}

} // namespace

std::vector<std::string> sessionImages(const Session& s) {
    std::vector<std::string> images;
    for (const auto& [name, map] : s.paramMaps)
        if (map.field == ParamMapSpec::Field::Image)
            images.push_back(map.image);
    if (s.diffusion.map) {
        orientationImages(s.diffusion.map->orientation, images);
        if (!s.diffusion.map->scaleImage.empty())
            images.push_back(s.diffusion.map->scaleImage);
    }
    for (std::string& image : images)
        if (!s.baseDir.empty() && !std::filesystem::path(image).is_absolute())
            image = (std::filesystem::path(s.baseDir) / image).string();
    return images;
}

} // namespace morphogen
