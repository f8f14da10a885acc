#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class ReactionModel;

// A model parameter that varies over the grid (Turk's "Varying Parameters";
// the parameter maps of Pearson's and McGraw's F-k plots): its value at each
// cell is min + (max - min) * t, with t in [0, 1] from a field.
struct ParamMapSpec {
    enum class Field {
        LinearX, // t = x / (W - 1): left to right
        LinearY, // t = y / (H - 1) with y up: bottom to top, as a plot's axis
        Radial,  // t = distance from the centre / the half-diagonal
        Noise,   // smooth value noise with features `scale` cells across
        Image,   // t = an image's luminance
    };
    Field field = Field::LinearX;
    float min = 0.0f;
    float max = 1.0f;
    float scale = 16.0f;                  // Noise: feature size in model units
    float centreX = 0.5f, centreY = 0.5f; // Radial
    std::string image;                    // Image (relative to the session's folder)
};
std::string toString(ParamMapSpec::Field field);

// Per-cell values (row 0 at the top), a pure function of its inputs.
// cellSize: model units per cell (0: one).
std::vector<float> evaluateParamMap(const ParamMapSpec& spec, int width, int height,
                                    std::uint64_t seed, const std::string& baseDir,
                                    double cellSize = 0);

// The same on a surface (a session on a mesh): per atlas cell, the field at
// the texel's point `positions[i]` (mesh coordinates; `used[i]` false: an
// unused texel, given spec.min). linear_x and linear_y run across the used
// points' bounding box along the model's x and y, radial from the box's point
// at (centre x, centre y, middle z) over half its diagonal, noise is a 3D value
// noise `scale` model units across (unitsPerMesh model units per mesh unit).
// An image field has no place on a surface: InputError naming `param`.
std::vector<float> evaluateSurfaceParamMap(const ParamMapSpec& spec, const std::string& param,
                                           const std::vector<std::array<float, 3>>& positions,
                                           const std::vector<bool>& used, double unitsPerMesh,
                                           std::uint64_t seed);

// Reads "param_maps" of a session: {"F": {"field": "linear_x", "range": [0.01, 0.1]}, ...};
// values must lie in each parameter's accepted range.
std::map<std::string, ParamMapSpec> paramMapsFromJson(const nlohmann::json& json,
                                                      const std::string& source,
                                                      const ReactionModel& model);
nlohmann::json paramMapsToJson(const std::map<std::string, ParamMapSpec>& maps);

} // namespace morphogen
