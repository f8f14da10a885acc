#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/session/brush_mode.hpp"
#include "core/session/surface_geometry.hpp"

namespace morphogen {

class FieldReader;
class ReactionModel;
struct Session;
using ParamValues = std::map<std::string, float>;

// A brush stroke as a session records it. Positions and radius are fractions
// of the canvas, so a stroke lands on the same part of the pattern at any
// --size (the canvas holds the same pattern at every resolution).
struct StrokeSpec {
    BrushMode mode = BrushMode::Add;
    std::string chemical;   // add, remove, set, randomise
    std::string param;      // paint
    float value = 0.0f;     // amount (add, remove, randomise) or target (set, paint)
    std::uint64_t seed = 0; // randomise
    // The path: x across the width, y down the rows as the state stores them,
    // 0..1 over the canvas (periodic edges wrap points outside it). One point
    // is a dab; consecutive points are joined by a swept disc.
    std::vector<std::array<double, 2>> points;
    // A stroke on a session's surface (a mesh): the path in the mesh's own
    // coordinates and the radius in its units; the texels within the radius
    // of the path (straight-line distance from their centres) are the cells.
    bool surface = false;
    std::vector<std::array<double, 3>> surfacePoints;
    // A stroke placed by the model's bounding box ("space": "model", also a
    // surface stroke): boxPoints are fractions 0..1 of the box along x, y and
    // z, boxRadius a fraction of its diagonal. Setting up the surface puts
    // surfacePoints at the mesh's points nearest to them and radius in mesh
    // units (placeModelStrokes), so the session's strokes fit any model; the
    // session keeps the fractions.
    bool modelBox = false;
    std::vector<std::array<double, 3>> boxPoints;
    double boxRadius = 0;
    double radius = 0.02; // fraction of the canvas width
    double falloff = 0.5; // outer fraction of the radius that ramps down to 0
    // The stroke goes on from the previous stroke edit (a drag recorded piece
    // by piece as the cursor moves): a cell's chemical changes by at most the
    // full amount over the whole stroke, however often the path crosses it,
    // as an opacity brush in a paint program (a new stroke builds up on the last).
    bool continues = false;
    // On a surface: after the stroke only the tiles it can have reached step,
    // growing ring by ring until the pattern there has settled again (Lo's
    // localized reaction-diffusion, core/sim/local_regrowth.hpp); the rest
    // of the surface holds its values meanwhile. For strokes on a settled
    // pattern: a fast re-growth. A session replays it step for step.
    bool localized = false;

    bool operator==(const StrokeSpec& o) const;
};

// The stretch factors a deformation accepts (below 1 compresses).
constexpr double kMinDeformFactor = 0.5;
constexpr double kMaxDeformFactor = 4.0;

// Reads a "space": "model" stroke's "points" (fractions of the model's
// bounding box, each 0..1) and "radius" (a fraction of its diagonal, (0, 1])
// into `stroke`, which becomes a surface stroke placed by the box. Fails the
// field (InputError naming it and what is accepted) otherwise.
void readModelStrokePlacement(const FieldReader& reader, StrokeSpec& stroke);

// A change made while the session ran (the designer's sliders and brushes),
// recorded so that the session reproduces the run: before session step
// `step` (counted over the whole session, cascade stages included), set the
// parameters and dt it holds and apply its stroke, in that order.
struct LiveEdit {
    long long step = 0;
    ParamValues params;      // the parameters it changes; the others keep their values
    std::optional<float> dt; // a new session time step
    std::optional<StrokeSpec> stroke;
    // On a surface: the mesh deformed there (Lo 5.5); the metric is
    // recomputed and the pattern re-grows there with localized re-growth.
    // Applied first, before the parameters, dt and stroke.
    std::optional<DeformSpec> deform;

    bool operator==(const LiveEdit& o) const;
};

// The "edits" array of a session. Errors name `top`'s source and the field.
// Checked here: the fields and their ranges, steps that do not decrease,
// parameter and chemical names of the session's model (or of any model its
// stages switch to). The step bound and the domain are validateSession's.
std::vector<LiveEdit> liveEditsFromJson(const FieldReader& top, const nlohmann::json& array,
                                        const Session& session);
nlohmann::json liveEditsToJson(const std::vector<LiveEdit>& edits);

// Whether any edit is on the session's model (a stroke in the mesh's
// coordinates, a deformation): such a session cannot run flat, without its
// surface (the gallery's flat pictures).
bool editsNeedTheModel(const std::vector<LiveEdit>& edits);

// validateSession's part: edits after the session's last step, and strokes on
// a domain they cannot address (a surface, a batched sweep), are refused.
void checkLiveEdits(const Session& session, long long totalSteps, const std::string& source);

} // namespace morphogen
