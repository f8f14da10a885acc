#include "core/session/live_edit.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/base/names.hpp"
#include "core/models/reaction_model.hpp"
#include "core/session/session.hpp"

namespace morphogen {

namespace {

using nlohmann::json;

// Strokes longer than this are a designer bug or a hostile file: a drag
// records a few points per frame.
constexpr std::size_t kMaxStrokePoints = 100000;
constexpr std::size_t kMaxLiveEdits = 1000000;
// Brush amounts: chemical values are clamped to the model's range anyway.
constexpr double kMaxBrushValue = 1e6;

// The models whose names an edit may use: the session's and every model its
// stages switch to (an edit's step decides which one runs, and the run
// refuses a name the model in force lacks).
std::vector<const ReactionModel*> sessionModels(const Session& s) {
    std::vector<const ReactionModel*> models{&s.reactionModel()};
    for (const Stage& stage : s.stages)
        if (!stage.model.empty())
            if (const ReactionModel* m = findModel(stage.model))
                models.push_back(m);
    return models;
}

std::string acceptedNames(const std::vector<const ReactionModel*>& models, bool chemicals) {
    std::set<std::string> names;
    for (const ReactionModel* m : models)
        for (const std::string& n : splitNameList(chemicals ? m->chemicalNames() : m->paramNames()))
            names.insert(n);
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

const ParamSpec* findParam(const std::vector<const ReactionModel*>& models,
                           const std::string& name) {
    for (const ReactionModel* m : models)
        if (const ParamSpec* p = m->param(name))
            return p;
    return nullptr;
}

StrokeSpec strokeFromJson(const FieldReader& edit, const json& block,
                          const std::vector<const ReactionModel*>& models) {
    FieldReader reader(block, edit.source(), edit.path("stroke"));
    reader.rejectUnknown({"mode", "chemical", "param", "value", "seed", "points", "radius",
                          "falloff", "continues", "space", "localized"});
    StrokeSpec s;
    if (!reader.find("mode"))
        reader.failField("mode", "is missing (accepted: " + brushModeNames() + ")");
    s.mode = reader.choice("mode", s.mode, parseBrushMode, brushModeNames());
    s.value = float(reader.number("value", 0.0, -kMaxBrushValue, kMaxBrushValue));
    s.seed = std::uint64_t(reader.integer("seed", 0, 0, kMaxSeed));
    s.falloff = reader.number("falloff", s.falloff, 0.0, 1.0);
    s.continues = reader.boolean("continues", false);
    if (writesChemical(s.mode)) {
        s.chemical = reader.string("chemical", "");
        const std::string accepted = acceptedNames(models, true);
        if (s.chemical.empty())
            reader.failField("chemical", "is missing: mode '" + toString(s.mode) +
                                             "' writes a chemical (accepted: " + accepted + ")");
        if (std::find_if(models.begin(), models.end(), [&](const ReactionModel* m) {
                return m->chemicalIndex(s.chemical) >= 0;
            }) == models.end())
            reader.failField("chemical", "is '" + s.chemical + "', not a chemical of the model " +
                                             "(accepted: " + accepted + ")" +
                                             didYouMean(s.chemical, splitNameList(accepted)));
    } else if (reader.find("chemical")) {
        reader.failField("chemical", "is not used by mode '" + toString(s.mode) + "'");
    }
    if (s.mode == BrushMode::Paint) {
        s.param = reader.string("param", "");
        const std::string accepted = acceptedNames(models, false);
        const ParamSpec* p = findParam(models, s.param);
        if (!p)
            reader.failField("param", "is '" + s.param + "', not a parameter of the model " +
                                          "(accepted: " + accepted + ")" +
                                          didYouMean(s.param, splitNameList(accepted)));
        s.value = float(reader.number("value", 0.0, p->min, p->max));
    } else if (reader.find("param")) {
        reader.failField("param", "is only used by mode 'paint'");
    }
    const std::string space = reader.string("space", "canvas");
    if (space != "canvas" && space != "surface" && space != "model")
        reader.failField("space", "is '" + space + "', accepted: canvas, surface, model");
    s.surface = space != "canvas";
    s.localized = reader.boolean("localized", false);
    if (s.localized && !s.surface)
        reader.failField("localized", "needs \"space\": \"surface\" or \"model\": localized "
                                      "re-growth runs on a mesh's tiles, not on the canvas");
    if (space == "model") {
        readModelStrokePlacement(reader, s);
        return s;
    }
    const json* points = reader.find("points");
    const std::string expected =
        s.surface ? "must be a non-empty array of [x, y, z] points on the mesh (its coordinates)"
                  : "must be a non-empty array of [x, y] canvas fractions (0..1; -1..2 wraps on "
                    "periodic edges)";
    if (!points || !points->is_array() || points->empty() || points->size() > kMaxStrokePoints)
        reader.failField("points", expected);
    const std::size_t dims = s.surface ? 3 : 2;
    for (const json& p : *points) {
        bool ok = p.is_array() && p.size() == dims;
        for (std::size_t k = 0; ok && k < dims; ++k) {
            ok = p[k].is_number();
            const double v = ok ? p[k].get<double>() : 0.0;
            ok = ok && (s.surface ? std::abs(v) <= kMaxLength : v >= -1.0 && v <= 2.0);
        }
        if (!ok)
            reader.failField("points", expected + ", got " + p.dump());
        if (s.surface)
            s.surfacePoints.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
        else
            s.points.push_back({p[0].get<double>(), p[1].get<double>()});
    }
    // On a surface the radius is in the mesh's units.
    s.radius = reader.number("radius", s.radius, 1e-9, s.surface ? kMaxLength : 1.0);
    return s;
}

} // namespace

void readModelStrokePlacement(const FieldReader& reader, StrokeSpec& stroke) {
    stroke.surface = true;
    stroke.modelBox = true;
    const json* points = reader.find("points");
    const std::string expected = "must be a non-empty array of [x, y, z] fractions of the model's "
                                 "bounding box (each 0..1; [0.5, 1, 0.5] is the middle of its top)";
    if (!points || !points->is_array() || points->empty() || points->size() > kMaxStrokePoints)
        reader.failField("points", expected);
    for (const json& p : *points) {
        bool ok = p.is_array() && p.size() == 3;
        for (std::size_t k = 0; ok && k < 3; ++k)
            ok = p[k].is_number() && p[k].get<double>() >= 0.0 && p[k].get<double>() <= 1.0;
        if (!ok)
            reader.failField("points", expected + ", got " + p.dump());
        stroke.boxPoints.push_back({p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
    }
    if (!reader.find("radius"))
        reader.failField("radius", "is missing (a fraction of the model's bounding-box diagonal, "
                                   "(0, 1])");
    stroke.boxRadius = reader.number("radius", 0.0, 0.0, 1.0);
    if (!(stroke.boxRadius > 0.0))
        reader.failField("radius", "is 0: a stroke needs a radius > 0 (a fraction of the model's "
                                   "bounding-box diagonal, (0, 1])");
    // Placed on the mesh when the surface is set up; until then nothing to paint.
    stroke.radius = 0;
}

namespace {

std::array<double, 3> vectorField(const FieldReader& reader, const char* name,
                                  const std::string& expected) {
    const json* v = reader.find(name);
    bool ok = v && v->is_array() && v->size() == 3;
    for (std::size_t k = 0; ok && k < 3; ++k)
        ok = (*v)[k].is_number() && std::abs((*v)[k].get<double>()) <= kMaxLength;
    if (!ok)
        reader.failField(name, expected + (v ? ", got " + v->dump() : std::string()));
    return {(*v)[0].get<double>(), (*v)[1].get<double>(), (*v)[2].get<double>()};
}

DeformSpec deformFromJson(const FieldReader& edit, const json& block) {
    FieldReader reader(block, edit.source(), edit.path("deform"));
    reader.rejectUnknown({"centre", "direction", "radius", "factor", "reach"});
    DeformSpec d;
    d.centre = vectorField(reader, "centre", "must be [x, y, z] on the mesh (its coordinates)");
    d.direction = vectorField(reader, "direction", "must be a non-zero [x, y, z] direction");
    if (d.direction == std::array<double, 3>{0, 0, 0})
        reader.failField("direction", "must not be zero");
    if (!reader.find("radius"))
        reader.failField("radius", "is missing (the slab's half width, mesh units)");
    d.radius = reader.number("radius", d.radius, 1e-9, kMaxLength);
    d.factor = reader.number("factor", d.factor, kMinDeformFactor, kMaxDeformFactor);
    d.reach = reader.number("reach", d.reach, 0.0, kMaxLength);
    return d;
}

json strokeToJson(const StrokeSpec& s) {
    json j;
    j["mode"] = toString(s.mode);
    if (writesChemical(s.mode))
        j["chemical"] = s.chemical;
    if (s.mode == BrushMode::Paint)
        j["param"] = s.param;
    if (s.mode != BrushMode::Hold && s.mode != BrushMode::Release)
        j["value"] = s.value;
    if (s.mode == BrushMode::Randomise)
        j["seed"] = s.seed;
    j["radius"] = s.radius;
    j["falloff"] = s.falloff;
    if (s.continues)
        j["continues"] = true;
    if (s.localized)
        j["localized"] = true;
    j["points"] = json::array();
    if (s.modelBox) {
        j["space"] = "model";
        j["radius"] = s.boxRadius;
        for (const auto& p : s.boxPoints)
            j["points"].push_back({p[0], p[1], p[2]});
    } else if (s.surface) {
        j["space"] = "surface";
        for (const auto& p : s.surfacePoints)
            j["points"].push_back({p[0], p[1], p[2]});
    } else {
        for (const auto& p : s.points)
            j["points"].push_back({p[0], p[1]});
    }
    return j;
}

} // namespace

bool StrokeSpec::operator==(const StrokeSpec& o) const {
    return mode == o.mode && chemical == o.chemical && param == o.param && value == o.value &&
           seed == o.seed && points == o.points && radius == o.radius && falloff == o.falloff &&
           continues == o.continues && surface == o.surface && surfacePoints == o.surfacePoints &&
           localized == o.localized && modelBox == o.modelBox && boxPoints == o.boxPoints &&
           boxRadius == o.boxRadius;
}

bool LiveEdit::operator==(const LiveEdit& o) const {
    return step == o.step && params == o.params && dt == o.dt && stroke == o.stroke &&
           deform == o.deform;
}

std::vector<LiveEdit> liveEditsFromJson(const FieldReader& top, const json& array,
                                        const Session& session) {
    if (!array.is_array() || array.size() > kMaxLiveEdits)
        top.failField("edits", "must be an array of edits ({\"step\": N, \"params\": {...}, "
                               "\"dt\": X, \"stroke\": {...}})");
    const std::vector<const ReactionModel*> models = sessionModels(session);
    std::vector<LiveEdit> edits;
    for (std::size_t i = 0; i < array.size(); ++i) {
        FieldReader reader(array[i], top.source(), "edits[" + std::to_string(i) + "]");
        reader.rejectUnknown({"step", "params", "dt", "stroke", "deform"});
        LiveEdit e;
        if (!reader.find("step"))
            reader.failField("step", "is missing (the session step before which it applies)");
        e.step = reader.integer("step", 0, 0, kMaxSteps);
        if (!edits.empty() && e.step < edits.back().step)
            reader.failField("step", "is " + std::to_string(e.step) + ", before the edit ahead " +
                                         "of it (step " + std::to_string(edits.back().step) +
                                         "): edits are in step order");
        if (const json* params = reader.find("params")) {
            FieldReader p(*params, top.source(), reader.path("params"));
            for (auto it = params->begin(); it != params->end(); ++it) {
                const ParamSpec* spec = findParam(models, it.key());
                if (!spec) {
                    const std::string accepted = acceptedNames(models, false);
                    p.failField(it.key(), "is not a parameter of the model (accepted: " + accepted +
                                              ")" + didYouMean(it.key(), splitNameList(accepted)));
                }
                e.params[it.key()] = float(p.numberValue(*it, it.key(), spec->min, spec->max));
            }
        }
        if (reader.find("dt"))
            e.dt = float(reader.number("dt", 1.0, kMinDt, kMaxDt));
        if (const json* stroke = reader.find("stroke"))
            e.stroke = strokeFromJson(reader, *stroke, models);
        if (const json* deform = reader.find("deform"))
            e.deform = deformFromJson(reader, *deform);
        edits.push_back(std::move(e));
    }
    return edits;
}

json liveEditsToJson(const std::vector<LiveEdit>& edits) {
    json array = json::array();
    for (const LiveEdit& e : edits) {
        json j;
        j["step"] = e.step;
        if (!e.params.empty())
            j["params"] = e.params;
        if (e.dt)
            j["dt"] = *e.dt;
        if (e.stroke)
            j["stroke"] = strokeToJson(*e.stroke);
        if (e.deform) {
            j["deform"] = {{"centre", e.deform->centre},
                           {"direction", e.deform->direction},
                           {"radius", e.deform->radius},
                           {"factor", e.deform->factor}};
            if (e.deform->reach > 0)
                j["deform"]["reach"] = e.deform->reach;
        }
        array.push_back(std::move(j));
    }
    return array;
}

void checkLiveEdits(const Session& s, long long totalSteps, const std::string& source) {
    if (s.edits.empty())
        return;
    if (s.edits.back().step > totalSteps)
        throw InputError(source + ": edit at step " + std::to_string(s.edits.back().step) +
                         " comes after the session's last step (" + std::to_string(totalSteps) +
                         "): edits apply before a step the session runs, or at its end");
    for (const LiveEdit& e : s.edits) {
        if (e.deform && !s.surface.active())
            throw InputError(source + ": edit at step " + std::to_string(e.step) +
                             ": a deformation in a session without a mesh (no \"surface\" "
                             "block)");
        if (!e.stroke)
            continue;
        if (!e.stroke->surface && s.surface.active())
            throw InputError(source + ": edit at step " + std::to_string(e.step) +
                             ": a stroke on the canvas in a session on a mesh (\"surface\"); "
                             "its strokes give \"space\": \"surface\" and points on the mesh");
        if (e.stroke->surface && !s.surface.active())
            throw InputError(source + ": edit at step " + std::to_string(e.step) +
                             ": a stroke on a surface in a session without a mesh (no "
                             "\"surface\" block)");
    }
    if (!s.edits.empty() && s.tiles.active())
        throw InputError(source + ": \"edits\" do not combine with \"tiles\" (a batched sweep "
                                  "sets its parameters per tile)");
}

bool editsNeedTheModel(const std::vector<LiveEdit>& edits) {
    for (const LiveEdit& e : edits)
        if (e.deform || (e.stroke && e.stroke->surface))
            return true;
    return false;
}

} // namespace morphogen
