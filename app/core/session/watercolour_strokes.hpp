#pragma once

#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/session/live_edit.hpp"

namespace morphogen {

class FieldReader;
struct Session;

// A session's "strokes": watercolour brush strokes, sugar for live edits.
//   {"step": N, "points": [[x, y], ...], "radius": R, "water": W,
//    "pigment": "p1", "amount": A, "falloff": F}
// becomes, before session step N, an "add" stroke of W to the water "w" and
// (when A > 0) one of A to the pigment, along the same path (canvas
// fractions 0..1, radius a fraction of the width, as edits take them). More
// water makes a wider, longer-lived wash, so it bleeds further. Any model
// with a "w" chemical and pigment chemicals "p1", "p2", ... accepts them.
// With "space": "surface" a stroke is on the session's model: points [x, y, z]
// in the mesh's coordinates and the radius in its units (as surface edits).
// Bad strokes are InputErrors naming "strokes[i].<field>": points outside
// the canvas, a radius of 0, negative water or amount, an unknown pigment.
// The expanded edits are merged into `session.edits` in step order (a
// stroke's pair after the session's own edits of the same step), so the
// session written back holds them as edits and reproduces the painting.
void addWatercolourStrokes(const FieldReader& top, const nlohmann::json& array, Session& session);

} // namespace morphogen
