#include "core/session/watercolour_strokes.hpp"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/base/names.hpp"
#include "core/models/reaction_model.hpp"
#include "core/session/session.hpp"

namespace morphogen {

namespace {

using nlohmann::json;

constexpr std::size_t kMaxStrokes = 100000;
constexpr std::size_t kMaxStrokePoints = 100000;
constexpr double kMaxWater = 1e3; // far past any wash: the canvas floods at ~10

// The model's pigments: "p1", "p2", ... as long as they exist.
std::vector<std::string> pigmentNames(const ReactionModel& model) {
    std::vector<std::string> names;
    for (int k = 1; model.chemicalIndex("p" + std::to_string(k)) >= 0; ++k)
        names.push_back("p" + std::to_string(k));
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

// A canvas or surface stroke's "points" and "radius".
void readPointsAndRadius(const FieldReader& reader, StrokeSpec& stroke) {
    const json* points = reader.find("points");
    const std::string expected =
        stroke.surface
            ? "must be a non-empty array of [x, y, z] points on the mesh (its coordinates)"
            : "must be a non-empty array of [x, y] points on the canvas (fractions 0..1)";
    if (!points || !points->is_array() || points->empty() || points->size() > kMaxStrokePoints)
        reader.failField("points", expected);
    for (const json& p : *points) {
        if (stroke.surface) {
            bool ok = p.is_array() && p.size() == 3;
            for (std::size_t k = 0; ok && k < 3; ++k)
                ok = p[k].is_number() && std::abs(p[k].get<double>()) <= kMaxLength;
            if (!ok)
                reader.failField("points", expected + ", got " + p.dump());
            stroke.surfacePoints.push_back(
                {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()});
            continue;
        }
        const bool ok = p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number() &&
                        p[0].get<double>() >= 0.0 && p[0].get<double>() <= 1.0 &&
                        p[1].get<double>() >= 0.0 && p[1].get<double>() <= 1.0;
        if (!ok)
            reader.failField("points", expected + ", got " + p.dump() +
                                           (p.is_array() ? " (outside the canvas)" : ""));
        stroke.points.push_back({p[0].get<double>(), p[1].get<double>()});
    }
    const double maxRadius = stroke.surface ? kMaxLength : 1.0;
    const std::string units =
        stroke.surface ? "the mesh's units" : "a fraction of the canvas width, (0, 1]";
    if (!reader.find("radius"))
        reader.failField("radius", "is missing (" + units + ")");
    stroke.radius = reader.number("radius", 0.0, 0.0, maxRadius);
    if (!(stroke.radius > 0.0))
        reader.failField("radius", "is 0: a stroke needs a radius > 0 (" + units + ")");
}

} // namespace

void addWatercolourStrokes(const FieldReader& top, const json& array, Session& session) {
    const ReactionModel& model = session.reactionModel();
    const std::vector<std::string> pigments = pigmentNames(model);
    if (model.chemicalIndex("w") < 0 || pigments.empty())
        top.failField("strokes", "are watercolour strokes: model '" + model.name() +
                                     "' has no water 'w' and pigments 'p1', ... (use \"edits\", "
                                     "or the model watercolour)");
    if (!array.is_array() || array.size() > kMaxStrokes)
        top.failField("strokes", "must be an array of strokes ({\"step\": N, \"points\": [[x, y], "
                                 "...], \"radius\": R, \"water\": W, \"pigment\": \"p1\", "
                                 "\"amount\": A})");
    std::vector<LiveEdit> added;
    for (std::size_t i = 0; i < array.size(); ++i) {
        FieldReader reader(array[i], top.source(), "strokes[" + std::to_string(i) + "]");
        reader.rejectUnknown(
            {"step", "points", "radius", "water", "pigment", "amount", "falloff", "space"});
        StrokeSpec stroke;
        stroke.mode = BrushMode::Add;
        const long long step = reader.integer("step", 0, 0, kMaxSteps);
        const std::string space = reader.string("space", "canvas");
        if (space != "canvas" && space != "surface" && space != "model")
            reader.failField("space", "is '" + space +
                                          "', accepted: canvas, surface (a model's "
                                          "surface, points in the mesh's coordinates), model "
                                          "(fractions of the model's bounding box)");
        stroke.surface = space != "canvas";
        stroke.modelBox = space == "model";
        if (stroke.modelBox)
            readModelStrokePlacement(reader, stroke);
        else
            readPointsAndRadius(reader, stroke);
        stroke.falloff = reader.number("falloff", stroke.falloff, 0.0, 1.0);
        const double water = reader.number("water", 1.0, 0.0, kMaxWater);
        const double amount = reader.number("amount", 0.5, 0.0, kMaxWater);
        const std::string pigment = reader.string("pigment", pigments.front());
        if (std::find(pigments.begin(), pigments.end(), pigment) == pigments.end())
            reader.failField("pigment", "is '" + pigment + "', not a pigment of model '" +
                                            model.name() + "' (accepted: " + joined(pigments) +
                                            ")" + didYouMean(pigment, pigments));
        LiveEdit wet;
        wet.step = step;
        wet.stroke = stroke;
        wet.stroke->chemical = "w";
        wet.stroke->value = float(water);
        added.push_back(wet);
        if (amount > 0.0) {
            LiveEdit colour = wet;
            colour.stroke->chemical = pigment;
            colour.stroke->value = float(amount);
            added.push_back(colour);
        }
    }
    // Stable: the session's own edits of a step first, then strokes in file order.
    std::vector<LiveEdit>& edits = session.edits;
    edits.insert(edits.end(), added.begin(), added.end());
    std::stable_sort(edits.begin(), edits.end(),
                     [](const LiveEdit& a, const LiveEdit& b) { return a.step < b.step; });
}

} // namespace morphogen
