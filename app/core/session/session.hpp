#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/base/limits.hpp" // kMaxGridSide and the other limits
#include "core/domain/domain.hpp"
#include "core/models/diffusion_spec.hpp"
#include "core/models/initial_condition.hpp"
#include "core/models/reaction_model.hpp"
#include "core/session/cascade.hpp"
#include "core/session/gravity.hpp"
#include "core/session/height_spec.hpp"
#include "core/session/live_edit.hpp"
#include "core/session/param_map.hpp"
#include "core/session/surface_geometry.hpp"
#include "core/session/surface_spec.hpp"
#include "core/session/tile_grid.hpp"

namespace morphogen {

enum class Integrator {
    ExplicitEuler, // c' = c + dt (f(c) + A c)                       (McGraw eq. 27)
    SemiImplicit,  // (I - dt A) c' = c + dt f(c), by relaxation passes   (McGraw eq. 28)
};
std::string toString(Integrator integrator);
// toString's spellings; std::nullopt for others. integratorNames() lists them.
std::optional<Integrator> parseIntegrator(std::string_view name);
std::string integratorNames();

// One level of a coarse-to-fine schedule (Witkin-Kass 5.2; McGraw's
// 64 -> 128 -> 256): the grid size and the steps run at it.
struct ScheduleLevel {
    int width = 0;
    int height = 0;
    int steps = 0;
};

struct ColorMapSpec {
    std::string name = "grey"; // see colormap.hpp for the list
    std::string chemical;      // empty: the model's display chemical
    // Ends of the "two-colour" blend, display (sRGB) values in [0, 1].
    std::array<float, 3> low = {0.05f, 0.05f, 0.1f};
    std::array<float, 3> high = {1.0f, 0.95f, 0.85f};
    // The "custom" map's stops, evenly spaced sRGB (core/session/gradient.hpp).
    std::vector<std::array<float, 3>> colours;
    // A window on the min-max normalised value, as an image editor's levels:
    // t -> clamp((t - levels[0]) / (levels[1] - levels[0]), 0, 1). A narrow
    // window makes a soft field a sharp-edged pattern (Witkin-Kass's cellular
    // textures are level sets of a smooth concentration).
    std::array<float, 2> levels = {0.0f, 1.0f};
    // The "watercolour" map only: the dark edge where a wash dried
    // (WatercolourEdges, core/output/watercolour_paint.hpp): its strength
    // (0: none) and the band's width as a fraction of the image's width, as
    // the strokes' radii are given.
    float edgeDarkening = 1.0f;
    float edgeWidth = 0.015f;
};

// Everything that determines a result: same session, same backend, same seed,
// the same pixels. Presets are sessions with a name and a description.
struct Session {
    std::string name;
    std::string description;
    std::string model = "gray_scott";
    ParamValues params; // complete after normalise()
    int width = 256;
    int height = 256;
    // The image's width in model length units: diffusion rates are per unit^2,
    // spot radii, lattice spacings and noise scales are in units, and width x
    // height is only the resolution, so --size keeps the pattern and adds
    // detail. 0: one unit per cell at this size (sessions written before
    // "length", read as written for their own size).
    double length = 0;
    EdgeMode edges = EdgeMode::Periodic;
    DiffusionSpec diffusion;
    // Drops running down a tilted canvas: a downhill drift of every diffusing
    // chemical (gravity.hpp). Off by default.
    Gravity gravity;
    float dt = 1.0f;
    int steps = 1000;
    Integrator integrator = Integrator::ExplicitEuler;
    // Whether the session's JSON or a flag chose the integrator: a surface
    // left to choose runs semi-implicit where explicit steps would need more
    // substeps than a semi-implicit step's passes (setUpSurface). Written
    // sessions always name it, so they replay as they ran.
    bool integratorGiven = false;
    int relaxationPasses = 8; // SemiImplicit: sweeps per step
    // Coarse-to-fine levels, coarsest first; the last must be width x height.
    // Empty: one level of `steps` at width x height.
    std::vector<ScheduleLevel> schedule;
    // Without a schedule, a size at least twice the length runs the session
    // at about one cell per unit and refines up to the size (segments.hpp);
    // false runs every step at the size.
    bool coarseToFine = true;
    // Turk's cascades: stages run in order (exclusive with a schedule); the
    // steps are their total. Empty: one stage of `steps`.
    std::vector<Stage> stages;
    // Parameters that vary over the grid, by name.
    std::map<std::string, ParamMapSpec> paramMaps;
    // A batched parameter sweep: the grid as independent tiles with per-tile
    // parameter values (a TiledGrid domain). Inactive by default.
    TileGrid tiles;
    // Cell size relative to the finest level (h); coarse levels have h > 1 and
    // their derivative kernels are scaled by 1/h^order. Set per level, not saved.
    double gridSpacing = 1.0;
    std::uint64_t seed = 1;
    InitialCondition init;
    ColorMapSpec colormap;
    // Height, normal and mask maps of a texture set ("height").
    HeightSpec heightMaps;
    // Grow the pattern on a mesh's surface instead of the flat canvas (the
    // "surface" block; inactive by default).
    SurfaceSpec surface;
    // Changes made while it ran (the designer's sliders and strokes), in step
    // order; SessionRun applies each before its step.
    std::vector<LiveEdit> edits;
    // Folder that relative paths in the session (images) resolve against; set
    // by loadSessionFile, not serialised.
    std::string baseDir;
    // A surface atlas to simulate on instead of the grid (Lo et al.): set by
    // useAtlas from engine code (the mesh pipeline), not serialised. The grid
    // is then the atlas texture (width x height) and its unused texels.
    std::shared_ptr<const Atlas> atlas;
    // Per-texel diffusion weights on that atlas (the surface's metric; null:
    // one unit per texel), set by useAtlas; not serialised either.
    std::shared_ptr<const AtlasWeights> atlasWeights;
    // Per atlas cell, the texel centre on the mesh (its coordinates), where
    // strokes on the surface land; set with the atlas from a mesh, not
    // serialised (null: none).
    std::shared_ptr<const std::vector<std::array<float, 3>>> atlasPositions;
    // The surface itself, for deformations while the session runs
    // (LiveEdit::deform); set with the atlas from a mesh, not serialised.
    std::shared_ptr<const SurfaceGeometry> surfaceGeometry;

    // The grid, the tiled grid of a batched sweep, or the atlas.
    Domain domain() const;
    // Model units per cell at width x height (h). A batched sweep's tiles and
    // an atlas run at one unit per cell.
    double cellSize() const;
    // cellSize() for what is laid out in model units (start noise, spot
    // radii, noise maps); 0 for a session without a length, whose start draws
    // per cell as it always did.
    double layoutCellSize() const { return length > 0 ? cellSize() : 0.0; }
    const ReactionModel& reactionModel() const; // asserts a known model
    // The model whose chemicals the final state holds: the last stage's that
    // changes model (a cascade such as Turk's giraffe), else reactionModel().
    const ReactionModel& outputModel() const;
};

// Changes the resolution, keeping the pattern: a session without a length
// first takes its current width as its length.
void resizeSession(Session& session, int width, int height);

// Runs the session on `atlas`: its size becomes the atlas texture's.
void useAtlas(Session& session, std::shared_ptr<const Atlas> atlas);
// The same with per-texel diffusion weights (null: none). Throws InputError
// for weights that do not fit the atlas (checkAtlasWeights).
void useAtlas(Session& session, std::shared_ptr<const Atlas> atlas,
              std::shared_ptr<const AtlasWeights> weights);

// Parses a session; `source` names the file (or preset) in error messages.
// Unknown fields, wrong types and out-of-range values throw InputError.
Session sessionFromJson(const nlohmann::json& json, const std::string& source);
nlohmann::json sessionToJson(const Session& session);

Session loadSessionFile(const std::string& path);
// Writes atomically (temporary file, then rename).
void saveSessionFile(const Session& session, const std::string& path);

// Built-in presets (models/presets/*.json, embedded).
std::vector<Session> allPresets();
Session loadPreset(const std::string& name);

// Applies "name=value" to session.params; throws InputError naming the
// parameter and the accepted names/range.
void applyParamOverride(Session& session, const std::string& assignment);

// Sets a coarse-to-fine schedule: the grid becomes the last level's and the
// steps the levels' total.
void applySchedule(Session& session, std::vector<ScheduleLevel> levels);

// Sets the number of steps of a one-level session; a session with cascade
// stages or a schedule counts its steps per stage or level, so `flag` (e.g.
// "--steps") is refused with an InputError saying so.
void applySteps(Session& session, int steps, const std::string& flag);

// Checks params against the model's ranges and the grid against limits.
void validateSession(const Session& session, const std::string& source);

// The image files a run of the session reads (parameter maps, orientation
// and scale images), resolved against its baseDir as the run resolves them.
std::vector<std::string> sessionImages(const Session& session);

} // namespace morphogen
