#include "core/session/height_spec.hpp"

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/json_fields.hpp"

namespace morphogen {

namespace {

constexpr EnumName<NormalFormat> kNormalFormatNames[] = {
    {NormalFormat::OpenGl, "opengl"},
    {NormalFormat::DirectX, "directx"},
};

} // namespace

std::string toString(NormalFormat format) {
    return nameOf(kNormalFormatNames, format);
}

std::optional<NormalFormat> parseNormalFormat(std::string_view name) {
    return valueNamed(kNormalFormatNames, name);
}

std::string normalFormatNames() {
    return nameList(kNormalFormatNames);
}

HeightSpec heightSpecFromJson(const FieldReader& top, const nlohmann::json& block) {
    FieldReader reader(block, top.source(), "height");
    reader.rejectUnknown({"range", "normal_strength", "normal_format", "mask_threshold"});
    HeightSpec spec;
    if (const nlohmann::json* range = reader.find("range")) {
        const char* expected = "must be an array [low, high] of finite numbers with low < high";
        if (!range->is_array() || range->size() != 2)
            reader.failField("range", expected);
        std::array<float, 2> r{};
        for (std::size_t i = 0; i < 2; ++i)
            r[i] = float(
                reader.numberValue((*range)[i], "range[" + std::to_string(i) + "]", -1e30, 1e30));
        if (!(r[0] < r[1]))
            reader.failField("range", expected);
        spec.range = r;
    }
    spec.normalStrength =
        float(reader.number("normal_strength", spec.normalStrength, 0.0, kMaxNormalStrength));
    spec.normalFormat =
        reader.choice("normal_format", spec.normalFormat, parseNormalFormat, normalFormatNames());
    spec.maskThreshold = float(reader.number("mask_threshold", spec.maskThreshold, 0.0, 1.0));
    return spec;
}

nlohmann::json heightSpecToJson(const HeightSpec& spec) {
    nlohmann::json j;
    if (spec.range)
        j["range"] = *spec.range;
    j["normal_strength"] = spec.normalStrength;
    j["normal_format"] = toString(spec.normalFormat);
    j["mask_threshold"] = spec.maskThreshold;
    return j;
}

} // namespace morphogen
