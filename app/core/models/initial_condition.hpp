#pragma once

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "core/base/state.hpp"

namespace morphogen {

class ReactionModel;

// How the chemicals start. Every cell gets base[c] + U(-noise[c], noise[c]);
// then, by type, a centred square (McGraw's Gray-Scott start), random seed
// spots or discs on a jittered diamond lattice (Witkin-Kass's giraffe start)
// get `inside[c]` (plus the same noise). Chemicals not named default to 0.
struct InitialCondition {
    enum class Type { Noise, CentreSquare, SeedSpots, JitteredGrid };
    Type type = Type::Noise;
    std::map<std::string, float> base;
    std::map<std::string, float> noise;
    std::map<std::string, float> inside;
    float squareFraction = 0.1f; // CentreSquare: side as a fraction of the grid's
    int spotCount = 10;          // SeedSpots
    float spotRadius = 3.0f;     // SeedSpots and JitteredGrid, in model units
    float spacing = 16.0f;       // JitteredGrid: lattice spacing in model units
    float jitter = 0.25f;        // JitteredGrid: displacement, as a fraction of the spacing
};

std::string toString(InitialCondition::Type type);

// Reads an "init" object found at `path` ("init", "stages[1].init") of
// `source` for `model`: unknown fields and chemicals are InputErrors. Fields
// it leaves out are empty, not inherited from the model's default start.
InitialCondition initialConditionFromJson(const nlohmann::json& json, const std::string& source,
                                          const std::string& path, const ReactionModel& model);
nlohmann::json initialConditionToJson(const InitialCondition& init);

// The initial state, a pure function of (condition, model, params, size,
// seed, cell size). cellSize: model units per cell; the noise is a field in
// model units (core/base/noise_field.hpp) and radii and spacings are in
// units. 0: one unit per cell with a value drawn per cell (a session
// without a length).
State makeInitialState(const InitialCondition& init, const ReactionModel& model,
                       const std::map<std::string, float>& params, int width, int height,
                       std::uint64_t seed, double cellSize = 0);

} // namespace morphogen
