#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class FieldReader;

// Which way a normal map's green channel points: OpenGL's +Y is up the image,
// DirectX's +Y is down it (the same map with green inverted).
enum class NormalFormat { OpenGl, DirectX };
std::string toString(NormalFormat format);
// toString's spellings; std::nullopt for others. normalFormatNames() lists them.
std::optional<NormalFormat> parseNormalFormat(std::string_view name);
std::string normalFormatNames();

// How a texture set (core/output/texture_set.hpp) turns the final state into
// height, normal and mask maps: the session's "height" block, so a written
// session reproduces the set.
struct HeightSpec {
    // Chemical values mapped to height 0 and 1, fixed so that a series of
    // renders shares its levels. Unset: the model's display range of the
    // colour map's chemical.
    std::optional<std::array<float, 2>> range;
    // Displacement, in texels, of a height step from 0 to 1 (the whole range).
    float normalStrength = 1.0f;
    NormalFormat normalFormat = NormalFormat::OpenGl;
    // The mask is 255 where the height (0..1 over the range) is above this.
    float maskThreshold = 0.5f;

    bool operator==(const HeightSpec& o) const {
        return range == o.range && normalStrength == o.normalStrength &&
               normalFormat == o.normalFormat && maskThreshold == o.maskThreshold;
    }
    bool operator!=(const HeightSpec& o) const { return !(*this == o); }
};

// Most displacement --normal-strength / "normal_strength" accepts (texels per
// height range); far beyond it every slope is a wall.
constexpr float kMaxNormalStrength = 1000.0f;

// The "height" block of a session; errors name `top`'s source and the field.
HeightSpec heightSpecFromJson(const FieldReader& top, const nlohmann::json& block);
nlohmann::json heightSpecToJson(const HeightSpec& spec);

} // namespace morphogen
