#include "cli/knob_flags.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

#include "core/base/enum_names.hpp"
#include "core/base/errors.hpp"
#include "core/base/json_fields.hpp"
#include "core/models/diffusion_spec.hpp"
#include "core/models/initial_condition.hpp"
#include "core/session/param_map.hpp"

namespace morphogen::cli {

using nlohmann::json;

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t at = text.find(separator, start);
        parts.push_back(
            text.substr(start, at == std::string::npos ? std::string::npos : at - start));
        if (at == std::string::npos)
            return parts;
        start = at + 1;
    }
}

// A number typed on the command line, as JSON: an integer when it reads as
// one, so that the readers' integer fields ("count") take it and refuse "2.5"
// with their own message. `source` names the flag for text that is no number.
json numberJson(const std::string& source, const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(begin, &end, 10);
    if (!text.empty() && *end == '\0' && errno == 0)
        return i;
    const double d = std::strtod(begin, &end);
    if (text.empty() || *end != '\0' || !std::isfinite(d))
        throw InputError(source + ": '" + text + "' is not a number");
    return d;
}

// "X,Y" as a JSON pair of numbers.
json centreJson(const std::string& source, const std::string& text) {
    const std::vector<std::string> xy = split(text, ',');
    if (xy.size() != 2)
        throw InputError(source + ": '" + text +
                         "' is not a centre CX,CY (fractions of the image, e.g. 0.5,0.5)");
    return json::array({numberJson(source, xy[0]), numberJson(source, xy[1])});
}

// Relative image paths on the command line are from the current folder; the
// session records them absolute, since its own relative paths resolve against
// the session file's folder.
std::string imagePath(const std::string& source, const std::string& path) {
    if (path.empty())
        throw InputError(source + ": the image file is missing");
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    if (ec || !std::filesystem::is_regular_file(absolute, ec))
        throw InputError(source + ": " + path + ": image not found");
    return absolute.lexically_normal().string();
}

// The orientation field kinds --orientation accepts, as the JSON names them.
std::vector<std::string> orientationKinds() {
    using T = OrientationField::Type;
    std::vector<std::string> kinds;
    for (T t : {T::Constant, T::Radial, T::Concentric, T::Spiral, T::Vortex, T::ImageGradient})
        kinds.push_back(toString(t));
    return kinds;
}

// "--theta 45 --orientation radial": the diffusion flags given, for messages.
std::string diffusionSource(const KnobFlags& f) {
    std::string source;
    auto add = [&](const std::string& flag, const std::string& value) {
        source += (source.empty() ? "" : " ") + flag + " " + value;
    };
    if (!f.theta.empty())
        add("--theta", f.theta);
    for (const std::string& o : f.orientation)
        add("--orientation", o);
    if (!f.anisotropy.empty())
        add("--anisotropy", f.anisotropy);
    return source;
}

void makeImagesAbsolute(json& field, const std::string& source) {
    if (field.contains("image"))
        field["image"] = imagePath(source, field["image"].get<std::string>());
}

void applyDiffusionFlags(const KnobFlags& f, Session& s, std::vector<std::string>& notes) {
    const bool theta = !f.theta.empty(), field = !f.orientation.empty(),
               ratio = !f.anisotropy.empty();
    if (!theta && !field && !ratio)
        return;
    const std::string source = diffusionSource(f);
    const ReactionModel& model = s.reactionModel();
    if (s.diffusion.type == DiffusionType::Generalized)
        throw InputError(source + ": this session's diffusion is generalized (McGraw's tensor "
                                  "sequences: no single direction to set); --theta, "
                                  "--orientation and --anisotropy apply to anisotropic or "
                                  "isotropic diffusion");

    json j = diffusionToJson(s.diffusion);
    if (s.diffusion.type == DiffusionType::Isotropic) {
        for (std::size_t i = 0; i < s.stages.size(); ++i)
            if (!s.stages[i].model.empty())
                throw InputError(source + ": stage " + std::to_string(i + 1) +
                                 " of this cascade changes the model (to '" + s.stages[i].model +
                                 "'), which needs isotropic diffusion");
        double r = kDefaultAnisotropy;
        if (ratio) {
            const json value = numberJson("--anisotropy", f.anisotropy);
            r = value.get<double>();
            if (!(r >= 1.0 && r <= 10000.0))
                throw InputError("--anisotropy " + f.anisotropy +
                                 ": accepted are 1..10000 (the rate along the orientation over "
                                 "the rate across it; for the other way round add 90 to --theta)");
        }
        // Along the orientation each chemical keeps the model's rate (so the
        // explicit time step limit stays), across it the rate is 1/r of that.
        json tensors = json::object();
        for (const ChemicalSpec& c : model.chemicals())
            tensors[c.name] = {{"theta", 0.0}, {"a1", 1.0}, {"a2", 1.0 / std::sqrt(r)}};
        j = {{"type", "anisotropic"}, {"tensors", tensors}};
        if (!ratio) {
            std::ostringstream os;
            os << source << ": this session's diffusion was isotropic; made it anisotropic, each "
               << "chemical at its rate along the orientation and " << kDefaultAnisotropy
               << "x slower across it (--anisotropy " << kDefaultAnisotropy
               << " is the default; give it to change)";
            notes.push_back(os.str());
        }
    } else if (ratio) {
        throw InputError("--anisotropy " + f.anisotropy +
                         ": this session's diffusion is already anisotropic, with its own a1, a2 "
                         "per chemical (\"diffusion.tensors\"); --anisotropy makes isotropic "
                         "diffusion anisotropic: edit the tensors in the session instead");
    }

    if (field) {
        json orientation;
        if (f.orientation.size() == 1) {
            orientation = orientationFlagJson(f.orientation[0]);
            makeImagesAbsolute(orientation, "--orientation '" + f.orientation[0] + "'");
        } else {
            orientation = {{"type", "blend"}, {"parts", json::array()}};
            for (const std::string& o : f.orientation) {
                json part = orientationFlagJson(o);
                makeImagesAbsolute(part, "--orientation '" + o + "'");
                orientation["parts"].push_back(part);
            }
        }
        if (!j.contains("map"))
            j["map"] = json::object();
        j["map"]["orientation"] = orientation;
    } else if (theta && j.contains("map")) {
        // One direction everywhere: the field goes; a map that also scales
        // the rates stays, with a constant orientation.
        const json& map = j["map"];
        const std::string kind = map["orientation"]["type"].get<std::string>();
        const bool scales = map.contains("scale_image") || map["scale"][1].get<double>() != 1.0;
        if (kind != "constant" || map["orientation"]["angle"].get<double>() != 0.0)
            notes.push_back("--theta " + f.theta + " replaces this session's '" + kind +
                            "' orientation field with one direction (with --orientation, "
                            "--theta turns the tensors relative to the field instead)");
        if (scales)
            j["map"]["orientation"] = {{"type", "constant"}, {"angle", 0.0}};
        else
            j.erase("map");
    }

    if (theta || field) {
        // The first chemical's principal direction goes to the angle (0 along
        // a field); the others keep their angle to it (the pairs of the
        // multi-direction Witkin-Kass models).
        const double target = theta ? numberJson("--theta", f.theta).get<double>() : 0.0;
        json& tensors = j["tensors"];
        const ChemicalSpec* first = nullptr;
        for (const ChemicalSpec& c : model.chemicals())
            if (!first && tensors.contains(c.name))
                first = &c;
        if (first) {
            const double from = tensors[first->name]["theta"].get<double>();
            for (auto it = tensors.begin(); it != tensors.end(); ++it) {
                const double offset = std::remainder((*it)["theta"].get<double>() - from, 360.0);
                (*it)["theta"] = it.key() == first->name ? target : target + offset;
            }
        }
    }
    s.diffusion = diffusionFromJson(j, source, model);
}

void applyParamMapFlags(const std::vector<std::string>& texts, Session& s) {
    const ReactionModel& model = s.reactionModel();
    std::set<std::string> seen;
    for (const std::string& text : texts) {
        const std::string source = "--param-map '" + text + "'";
        auto [name, spec] = paramMapFlagJson(text);
        if (!seen.insert(name).second)
            throw InputError(source + ": '" + name + "' is mapped twice; give one --param-map " +
                             name + "=...");
        if (spec.is_null()) {
            if (s.paramMaps.erase(name) == 0)
                throw InputError(source + ": this session has no map of '" + name + "' to remove");
            continue;
        }
        if (spec["field"] == "image")
            spec["image"] = imagePath(source, spec["image"].get<std::string>());
        // The reader checks the name against the model and the values against its range.
        const std::map<std::string, ParamMapSpec> maps =
            paramMapsFromJson(json{{name, spec}}, source, model);
        // The session reader's checks of "param_maps" against the rest of the session.
        if (!s.schedule.empty())
            throw InputError(source + ": parameter maps do not combine with a coarse-to-fine "
                                      "schedule (\"schedule\", --schedule)");
        if (s.tiles.active())
            throw InputError(source + ": parameter maps do not combine with a batched sweep's "
                                      "\"tiles\" (tiles.params sets per-tile values)");
        for (std::size_t i = 0; i < s.stages.size(); ++i) {
            if (!s.stages[i].model.empty())
                throw InputError(source + ": stage " + std::to_string(i + 1) +
                                 " of this cascade changes the model (to '" + s.stages[i].model +
                                 "'); parameter maps are maps of model '" + model.name() +
                                 "' parameters");
            if (s.stages[i].params.count(name))
                throw InputError(source + ": stage " + std::to_string(i + 1) +
                                 " of this cascade sets '" + name +
                                 "', which a map would set per cell");
        }
        s.paramMaps[name] = maps.at(name);
    }
}

// "u=0.5,v=0.25" merged into the JSON object `values`.
void mergeChemicalValues(const std::string& source, const std::string& text, json& values) {
    if (!values.is_object())
        values = json::object();
    for (const std::string& item : split(text, ',')) {
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(source + ": '" + item + "' is not CHEMICAL=VALUE (e.g. u=0.5,v=0.25)");
        values[item.substr(0, eq)] = numberJson(source, item.substr(eq + 1));
    }
}

void applyInitFlags(const KnobFlags& f, Session& s) {
    using T = InitialCondition::Type;
    const ReactionModel& model = s.reactionModel();
    auto reread = [&](const json& j, const std::string& source) {
        s.init = initialConditionFromJson(j, source, "init", model);
    };
    if (!f.init.empty()) {
        json j = initialConditionToJson(s.init);
        j["type"] = f.init;
        reread(j, "--init " + f.init);
    }
    const std::pair<const std::vector<std::string>*, const char*> values[] = {
        {&f.initBase, "base"}, {&f.initNoise, "noise"}, {&f.initInside, "inside"}};
    for (const auto& [texts, key] : values)
        for (const std::string& text : *texts) {
            const std::string source = std::string("--init-") + key + " '" + text + "'";
            json j = initialConditionToJson(s.init);
            mergeChemicalValues(source, text, j[key]);
            reread(j, source);
        }

    struct Knob {
        const std::string& text;
        const char* flag;
        const char* key;
        std::vector<T> types;
    };
    const Knob knobs[] = {
        {f.spots, "--spots", "count", {T::SeedSpots}},
        {f.spotRadius, "--spot-radius", "radius", {T::SeedSpots, T::JitteredGrid}},
        {f.spacing, "--spacing", "spacing", {T::JitteredGrid}},
        {f.jitter, "--jitter", "jitter", {T::JitteredGrid}},
        {f.square, "--square", "fraction", {T::CentreSquare}}};
    for (const Knob& k : knobs) {
        if (k.text.empty())
            continue;
        const std::string source = std::string(k.flag) + " " + k.text;
        bool applies = false;
        std::string types;
        for (T t : k.types) {
            applies = applies || s.init.type == t;
            types += (types.empty() ? "" : " or ") + toString(t);
        }
        if (!applies)
            throw InputError(source + ": applies to --init " + types +
                             "; this session starts from " + toString(s.init.type) +
                             " (add --init " + toString(k.types[0]) + ")");
        json j = initialConditionToJson(s.init);
        j[k.key] = numberJson(source, k.text);
        reread(j, source);
    }

    // Spots, grid discs and the square are where the `inside` values go: without
    // any they would start like the rest of the grid.
    if (!f.init.empty() && s.init.type != T::Noise && s.init.inside.empty())
        throw InputError("--init " + toString(s.init.type) +
                         ": the marked cells take \"inside\" values and this session has none, "
                         "so they would start like the rest: add --init-inside CHEMICAL=VALUE,... "
                         "(chemicals of " +
                         model.name() + ": " + model.chemicalNames() + ")");
}

} // namespace

json orientationFlagJson(const std::string& text) {
    const std::string source = "--orientation '" + text + "'";
    const std::size_t colon = text.find(':');
    const std::string kindText = text.substr(0, colon);
    const std::string rest = colon == std::string::npos ? "" : text.substr(colon + 1);
    const std::vector<std::string> kinds = orientationKinds();
    std::string kind;
    for (const std::string& k : kinds)
        if (sameSpelling(kindText, k))
            kind = k;
    if (sameSpelling(kindText, "image"))
        kind = toString(OrientationField::Type::ImageGradient);
    if (sameSpelling(kindText, "blend"))
        throw InputError(source + ": give --orientation once per field to blend them (each "
                                  "with its centre, e.g. --orientation radial:0.3,0.5 "
                                  "--orientation concentric:0.7,0.5)");
    if (kind.empty())
        throw InputError(source + ": '" + kindText + "' is not an orientation field (accepted: " +
                         joinNames(kinds) + ", image)" + didYouMean(kindText, kinds));

    json field = {{"type", kind}};
    if (kind == toString(OrientationField::Type::ImageGradient)) {
        if (rest.empty())
            throw InputError(source + ": needs the image, e.g. image:lines.png");
        field["image"] = rest;
        return field;
    }
    // The parts after the kind: a centre "CX,CY" and an angle, in either order.
    const bool angled = kind == "constant" || kind == "spiral" || kind == "vortex";
    bool hasAngle = false, hasCentre = false;
    if (!rest.empty())
        for (const std::string& part : split(rest, ':')) {
            if (part.find(',') != std::string::npos) {
                if (hasCentre)
                    throw InputError(source + ": gives the centre twice");
                field["centre"] = centreJson(source, part);
                hasCentre = true;
            } else {
                if (!angled)
                    throw InputError(source + ": '" + part + "': " + kind +
                                     " takes only a centre CX,CY (e.g. " + kind + ":0.5,0.5)");
                if (hasAngle)
                    throw InputError(source + ": gives the angle twice");
                field["angle"] = numberJson(source, part);
                hasAngle = true;
            }
        }
    if (angled && !hasAngle)
        throw InputError(source + ": " + kind + " needs " +
                         (kind == "constant" ? "its angle in degrees, e.g. constant:45"
                                             : "its twist in degrees, e.g. " + kind + ":45 or " +
                                                   kind + ":45:0.5,0.5"));
    return field;
}

std::pair<std::string, json> paramMapFlagJson(const std::string& text) {
    const std::string source = "--param-map '" + text + "'";
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(source + ": expected NAME=FIELD:LOW:HIGH (e.g. k=linear_x:0.05:0.07)");
    const std::string name = text.substr(0, eq);
    const std::string value = text.substr(eq + 1);
    if (sameSpelling(value, "none"))
        return {name, nullptr};
    const std::size_t colon = value.find(':');
    const std::string fieldText = value.substr(0, colon);
    std::vector<std::string> parts = colon == std::string::npos
                                         ? std::vector<std::string>{}
                                         : split(value.substr(colon + 1), ':');

    const std::vector<std::string> fields = {"linear_x", "linear_y", "radial", "noise", "image"};
    std::string field;
    for (const std::string& f : fields)
        if (sameSpelling(fieldText, f))
            field = f;
    if (field.empty())
        throw InputError(source + ": '" + fieldText + "' is not a map field (accepted: " +
                         joinNames(fields) + ")" + didYouMean(fieldText, fields));

    json spec = {{"field", field}};
    if (field == "image") {
        // The file may hold ':'; the range is the last two parts.
        if (parts.size() < 3)
            throw InputError(source + ": expected " + name + "=image:FILE:LOW:HIGH");
        std::string file = parts[0];
        for (std::size_t i = 1; i + 2 < parts.size(); ++i)
            file += ":" + parts[i];
        spec["image"] = file;
        parts.erase(parts.begin(), parts.end() - 2);
    }
    const char* usage = field == "radial"  ? "radial:LOW:HIGH[:CX,CY]"
                        : field == "noise" ? "noise:LOW:HIGH[:SCALE]"
                        : field == "image" ? "image:FILE:LOW:HIGH"
                                           : nullptr;
    const std::string expected =
        source + ": expected " + name + "=" + (usage ? usage : field + ":LOW:HIGH");
    const bool extra = parts.size() == 3 && (field == "radial" || field == "noise");
    if (parts.size() != 2 && !extra)
        throw InputError(expected);
    spec["range"] = json::array({numberJson(source, parts[0]), numberJson(source, parts[1])});
    if (extra && field == "radial")
        spec["centre"] = centreJson(source, parts[2]);
    if (extra && field == "noise")
        spec["scale"] = numberJson(source, parts[2]);
    return {name, spec};
}

json gravityFlagJson(const std::string& text) {
    if (text == "off")
        return {{"angle", Gravity{}.angle}, {"strength", 0}};
    const std::vector<std::string> parts = split(text, ':');
    if (parts.size() != 2)
        throw InputError("--gravity: '" + text +
                         "' is not ANGLE:STRENGTH (degrees counter-clockwise from +x, 270 down "
                         "the page; model units per unit time, e.g. 270:0.5) or off");
    return {{"angle", numberJson("--gravity", parts[0])},
            {"strength", numberJson("--gravity", parts[1])}};
}

std::vector<std::string> applyKnobFlags(const KnobFlags& flags, Session& session) {
    std::vector<std::string> notes;
    applyDiffusionFlags(flags, session, notes);
    applyParamMapFlags(flags.paramMaps, session);
    applyInitFlags(flags, session);
    if (!flags.gravity.empty())
        session.gravity = gravityFromJson(FieldReader(json::object(), "--gravity", ""),
                                          gravityFlagJson(flags.gravity));
    if (!flags.gravityDirection.empty()) {
        const std::vector<std::string> parts = split(flags.gravityDirection, ',');
        if (parts.size() != 3)
            throw InputError("--gravity-direction: '" + flags.gravityDirection +
                             "' is not X,Y,Z (gravity in the mesh's object space, e.g. 0,-1,0)");
        json block = gravityToJson(session.gravity);
        block["direction"] = json::array();
        for (const std::string& p : parts)
            block["direction"].push_back(numberJson("--gravity-direction", p));
        session.gravity =
            gravityFromJson(FieldReader(json::object(), "--gravity-direction", ""), block);
    }
    return notes;
}

void addKnobFlags(CLI::App& cmd, KnobFlags& f) {
    const std::string orientation = "Orientation (anisotropic diffusion; JSON \"diffusion\")";
    cmd.add_option("--theta", f.theta,
                   "one direction for the whole image, degrees counter-clockwise from +x: stripes "
                   "run along it (replaces an orientation field; with --orientation, turns the "
                   "tensors relative to the field)")
        ->type_name("DEG")
        ->group(orientation);
    cmd.add_option("--orientation", f.orientation,
                   "an orientation field: constant:DEG, radial[:CX,CY], concentric[:CX,CY], "
                   "spiral:TWIST[:CX,CY], vortex:TWIST[:CX,CY] or image:FILE (along its "
                   "isolines); centres are fractions of the image; repeat to blend fields by "
                   "distance to their centres")
        ->type_name("KIND[:ARGS]")
        ->group(orientation);
    std::ostringstream ratio;
    ratio << "makes isotropic diffusion anisotropic: each chemical keeps its rate along the "
             "orientation and diffuses RATIO times slower across it (default "
          << kDefaultAnisotropy << " when --theta or --orientation needs it)";
    cmd.add_option("--anisotropy", f.anisotropy, ratio.str())
        ->type_name("RATIO")
        ->group(orientation);

    cmd.add_option("--param-map", f.paramMaps,
                   "vary a parameter over the image: NAME=linear_x:LOW:HIGH, "
                   "NAME=linear_y:LOW:HIGH (bottom to top), NAME=radial:LOW:HIGH[:CX,CY], "
                   "NAME=noise:LOW:HIGH[:SCALE], NAME=image:FILE:LOW:HIGH (luminance), "
                   "NAME=none (remove a session's map); repeatable")
        ->type_name("NAME=FIELD:...")
        ->group("Parameter maps (JSON \"param_maps\")");

    const std::string init = "Initial condition (JSON \"init\")";
    cmd.add_option("--init", f.init,
                   "how the chemicals start: noise, centre_square, seed_spots or jittered_grid")
        ->type_name("TYPE")
        ->group(init);
    cmd.add_option("--spots", f.spots, "seed_spots: number of spots")->type_name("N")->group(init);
    cmd.add_option("--spot-radius", f.spotRadius, "seed_spots, jittered_grid: spot radius")
        ->type_name("R")
        ->group(init);
    cmd.add_option("--spacing", f.spacing, "jittered_grid: lattice spacing")
        ->type_name("S")
        ->group(init);
    cmd.add_option("--jitter", f.jitter,
                   "jittered_grid: displacement as a fraction of the spacing, 0..1")
        ->type_name("J")
        ->group(init);
    cmd.add_option("--square", f.square, "centre_square: side as a fraction of the image, 0..1")
        ->type_name("FRACTION")
        ->group(init);
    cmd.add_option("--init-base", f.initBase,
                   "start values CHEMICAL=VALUE,... everywhere (merged into the session's)")
        ->type_name("CHEM=V,...")
        ->group(init);
    cmd.add_option("--init-noise", f.initNoise,
                   "uniform noise amplitude CHEMICAL=VALUE,... added everywhere")
        ->type_name("CHEM=V,...")
        ->group(init);
    cmd.add_option("--init-inside", f.initInside,
                   "values CHEMICAL=VALUE,... in the spots, grid discs or square")
        ->type_name("CHEM=V,...")
        ->group(init);

    cmd.add_option("--gravity", f.gravity,
                   "tilt the canvas: every diffusing chemical drifts downhill at STRENGTH model "
                   "units per unit time towards ANGLE (degrees counter-clockwise from +x; 270 "
                   "runs down the page), e.g. 270:0.5 for drops; off removes a session's")
        ->type_name("ANGLE:STRENGTH")
        ->group("Gravity (JSON \"gravity\")");
    cmd.add_option("--gravity-direction", f.gravityDirection,
                   "on a model (--mesh): gravity's direction in the mesh's object space (default "
                   "0,-1,0: down the model); drops run along its projection on the surface at "
                   "--gravity's STRENGTH")
        ->type_name("X,Y,Z")
        ->group("Gravity (JSON \"gravity\")");
}

} // namespace morphogen::cli
