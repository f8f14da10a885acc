#include "core/models/diffusion_spec.hpp"

#include <nlohmann/json.hpp>

#include "core/base/enum_names.hpp"
#include "core/base/json_fields.hpp"
#include "core/base/limits.hpp"
#include "core/models/reaction_model.hpp"
#include "core/numerics/tensor_sequence.hpp"

namespace morphogen {

using nlohmann::json;

namespace {

const EnumName<Stencil> kStencils[] = {{Stencil::FivePoint, "5-point"},
                                       {Stencil::NinePoint, "9-point"}};

const EnumName<DiffusionType> kDiffusionTypes[] = {{DiffusionType::Isotropic, "isotropic"},
                                                   {DiffusionType::Anisotropic, "anisotropic"},
                                                   {DiffusionType::Generalized, "generalized"}};

const EnumAlias<Stencil> kStencilAliases[] = {{"five-point", Stencil::FivePoint},
                                              {"nine-point", Stencil::NinePoint}};

const EnumAlias<DiffusionType> kDiffusionTypeAliases[] = {
    {"generalised", DiffusionType::Generalized}};

const EnumName<OrientationField::Type> kFieldTypes[] = {
    {OrientationField::Type::Constant, "constant"},
    {OrientationField::Type::Radial, "radial"},
    {OrientationField::Type::Concentric, "concentric"},
    {OrientationField::Type::Spiral, "spiral"},
    {OrientationField::Type::Vortex, "vortex"},
    {OrientationField::Type::Blend, "blend"},
    {OrientationField::Type::ImageGradient, "image_gradient"}};

std::optional<DiffusionType> parseDiffusionType(std::string_view name) {
    return valueNamed(kDiffusionTypes, kDiffusionTypeAliases, name);
}

std::optional<OrientationField::Type> parseFieldType(std::string_view name) {
    return valueNamed(kFieldTypes, name);
}

void checkChemical(const FieldReader& reader, const std::string& key, const ReactionModel& model) {
    if (model.chemicalIndex(key) < 0)
        reader.failField(key, "is not a chemical of model '" + model.name() +
                                  "' (chemicals: " + model.chemicalNames() + ")" +
                                  didYouMean(key, splitNameList(model.chemicalNames())));
}

// `fields` counts the fields read so far in this orientation (a blend's parts
// through nested blends); `depth` is the number of blends around this one.
OrientationField fieldFromJson(const json& j, const std::string& source, const std::string& path,
                               int depth, int& fields) {
    FieldReader reader(j, source, path);
    if (++fields > kMaxOrientationFields)
        reader.fail("field '" + path + "'",
                    "is one field too many: an orientation may hold up to " +
                        std::to_string(kMaxOrientationFields) +
                        " fields, counting a blend's parts");
    reader.rejectUnknown({"type", "angle", "centre", "parts", "image"});
    OrientationField field;
    field.type = reader.choice("type", field.type, parseFieldType, nameList(kFieldTypes));
    field.angle = float(reader.number("angle", 0.0, -3600.0, 3600.0));
    if (const json* centre = reader.find("centre")) {
        if (!centre->is_array() || centre->size() != 2)
            reader.failField("centre", "must be [x, y], fractions of the grid");
        field.centreX = float(reader.numberValue((*centre)[0], "centre[0]", -10, 10));
        field.centreY = float(reader.numberValue((*centre)[1], "centre[1]", -10, 10));
    }
    if (field.type == OrientationField::Type::Blend) {
        const json* parts = reader.find("parts");
        if (!parts || !parts->is_array() || parts->empty())
            reader.failField("parts", "must be a non-empty array of fields, each with a centre");
        if (depth >= kMaxBlendDepth)
            reader.failField("parts", "nest a blend " + std::to_string(depth + 1) +
                                          " deep; accepted are blends nested up to " +
                                          std::to_string(kMaxBlendDepth) + " deep");
        for (std::size_t i = 0; i < parts->size(); ++i)
            field.parts.push_back(fieldFromJson((*parts)[i], source,
                                                reader.path("parts[" + std::to_string(i) + "]"),
                                                depth + 1, fields));
    }
    field.image = reader.string("image", "");
    if (field.type == OrientationField::Type::ImageGradient && field.image.empty())
        reader.failField("image", "is required for an image_gradient field");
    return field;
}

json fieldToJson(const OrientationField& f) {
    json j;
    j["type"] = toString(f.type);
    j["angle"] = f.angle;
    j["centre"] = {f.centreX, f.centreY};
    if (!f.parts.empty()) {
        j["parts"] = json::array();
        for (const OrientationField& p : f.parts)
            j["parts"].push_back(fieldToJson(p));
    }
    if (!f.image.empty())
        j["image"] = f.image;
    return j;
}

} // namespace

std::string toString(Stencil stencil) {
    return nameOf(kStencils, stencil);
}

std::optional<Stencil> parseStencil(std::string_view name) {
    return valueNamed(kStencils, kStencilAliases, name);
}

std::string stencilNames() {
    return nameList(kStencils);
}

std::string toString(DiffusionType type) {
    return nameOf(kDiffusionTypes, type);
}

std::string toString(OrientationField::Type type) {
    return nameOf(kFieldTypes, type);
}

DiffusionSpec diffusionFromJson(const json& j, const std::string& source,
                                const ReactionModel& model) {
    FieldReader reader(j, source, "diffusion");
    reader.rejectUnknown({"type", "stencil", "tensors", "map", "savitzky_golay", "stabilize"});
    DiffusionSpec spec;
    spec.type = reader.choice("type", spec.type, parseDiffusionType, nameList(kDiffusionTypes));
    spec.stencil = reader.choice("stencil", spec.stencil, parseStencil, stencilNames());

    if (const json* tensors = reader.find("tensors")) {
        FieldReader t(*tensors, source, reader.path("tensors"));
        for (auto it = tensors->begin(); it != tensors->end(); ++it) {
            checkChemical(t, it.key(), model);
            if (spec.type == DiffusionType::Anisotropic) {
                FieldReader one(*it, source, t.path(it.key()));
                one.rejectUnknown({"theta", "a1", "a2"});
                AnisotropicTensor a;
                a.theta = float(one.number("theta", 0.0, -3600.0, 3600.0));
                a.a1 = float(one.number("a1", 1.0, 0.0, 100.0));
                a.a2 = float(one.number("a2", 1.0, 0.0, 100.0));
                spec.anisotropic[it.key()] = a;
            } else if (spec.type == DiffusionType::Generalized) {
                if (!it->is_string())
                    t.failField(it.key(), "must be a tensor set a..f or components like "
                                          "\"xx=1,yy=1,xxxx=-1\"");
                spec.generalized[it.key()] = it->get<std::string>();
                try {
                    parseTensorSequence(spec.generalized[it.key()]); // refused here, not at the run
                } catch (const InputError& e) {
                    t.failField(it.key(), std::string("is not accepted: ") + e.what());
                }
            } else {
                reader.failField("tensors", "needs type anisotropic or generalized");
            }
        }
    }
    if (spec.type != DiffusionType::Isotropic && !reader.find("tensors"))
        reader.failField("tensors", "is required for " + toString(spec.type) + " diffusion");

    if (const json* sg = reader.find("savitzky_golay")) {
        FieldReader s(*sg, source, reader.path("savitzky_golay"));
        s.rejectUnknown({"window", "degree", "central_second_order"});
        spec.savitzkyGolay.window = int(s.integer("window", 5, 3, 5));
        // The filter is centred: an even window has no centre cell (4 would run as 5).
        if (spec.savitzkyGolay.window % 2 == 0)
            s.failField("window", "is " + std::to_string(spec.savitzkyGolay.window) +
                                      ", accepted are 3 (3x3) and 5 (5x5)");
        spec.savitzkyGolay.degree = int(s.integer("degree", 4, 2, 6));
        if (const json* c = s.find("central_second_order")) {
            if (!c->is_boolean())
                s.failField("central_second_order", "must be true or false");
            spec.savitzkyGolay.centralSecondOrder = c->get<bool>();
        }
    }
    if (const json* st = reader.find("stabilize")) {
        if (!st->is_boolean())
            reader.failField("stabilize", "must be true or false");
        spec.stabilize = st->get<bool>();
    }

    if (const json* map = reader.find("map")) {
        if (spec.type != DiffusionType::Anisotropic)
            reader.failField("map", "needs type anisotropic (diffusion maps vary its tensor)");
        FieldReader m(*map, source, reader.path("map"));
        m.rejectUnknown({"orientation", "scale_image", "scale"});
        DiffusionMapSpec mapSpec;
        if (const json* o = m.find("orientation")) {
            int fields = 0;
            mapSpec.orientation = fieldFromJson(*o, source, m.path("orientation"), 0, fields);
        }
        mapSpec.scaleImage = m.string("scale_image", "");
        if (const json* scale = m.find("scale")) {
            if (!scale->is_array() || scale->size() != 2)
                m.failField("scale", "must be [min, max]");
            mapSpec.scaleMin = float(m.numberValue((*scale)[0], "scale[0]", 0, 100));
            mapSpec.scaleMax = float(m.numberValue((*scale)[1], "scale[1]", 0, 100));
        }
        spec.map = mapSpec;
    }
    return spec;
}

json diffusionToJson(const DiffusionSpec& spec) {
    json j;
    j["type"] = toString(spec.type);
    if (spec.type == DiffusionType::Isotropic)
        j["stencil"] = toString(spec.stencil);
    if (spec.type == DiffusionType::Anisotropic) {
        json tensors = json::object();
        for (const auto& [name, a] : spec.anisotropic)
            tensors[name] = {{"theta", a.theta}, {"a1", a.a1}, {"a2", a.a2}};
        j["tensors"] = tensors;
    }
    if (spec.type == DiffusionType::Generalized) {
        j["tensors"] = spec.generalized;
        j["savitzky_golay"] = {{"window", spec.savitzkyGolay.window},
                               {"degree", spec.savitzkyGolay.degree},
                               {"central_second_order", spec.savitzkyGolay.centralSecondOrder}};
        j["stabilize"] = spec.stabilize;
    }
    if (spec.map) {
        json m;
        m["orientation"] = fieldToJson(spec.map->orientation);
        if (!spec.map->scaleImage.empty())
            m["scale_image"] = spec.map->scaleImage;
        m["scale"] = {spec.map->scaleMin, spec.map->scaleMax};
        j["map"] = m;
    }
    return j;
}

} // namespace morphogen
