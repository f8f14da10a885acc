// The designer's left panel: model, operator, integrator, grid, parameters
// with their ranges, the stability report, the brush and the display.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/base/names.hpp"
#include "core/models/builtin_models.hpp"
#include "core/numerics/propagator.hpp"
#include "core/numerics/tensor_sequence.hpp"
#include "core/output/colormap.hpp"
#include "core/output/watercolour_paint.hpp"
#include "core/sim/stability_check.hpp"
#include "ui/designer_app.hpp"
#include "ui/layout_window.hpp"

namespace morphogen::ui {

namespace {

using nlohmann::json;

// The session with `edit` applied to its JSON, read back through the
// session reader: every change the panel makes is validated as a file would be.
Session edited(const Session& base, const std::function<void(json&)>& edit) {
    json j = sessionToJson(base);
    edit(j);
    Session s = sessionFromJson(j, "the designer's session");
    s.baseDir = base.baseDir;
    validateSession(s, "the designer's session");
    return s;
}

const char* kOperatorLabels[] = {"isotropic, 5-point", "isotropic, 9-point", "anisotropic",
                                 "generalized (McGraw)"};

int operatorIndex(const DiffusionSpec& d) {
    switch (d.type) {
    case DiffusionType::Isotropic:
        return d.stencil == Stencil::FivePoint ? 0 : 1;
    case DiffusionType::Anisotropic:
        return 2;
    case DiffusionType::Generalized:
        return 3;
    }
    return 0;
}

// McGraw's propagator of a tensor set as a polar curve: its lobes are the
// directions the pattern prefers (Fig. 3 of the paper).
void drawPropagator(const std::string& set) {
    try {
        const Propagator p(set.size() == 1 ? tableTwoSet(set[0]) : parseTensorSequence(set));
        const float size = 120;
        const ImVec2 origin = ImGui::GetCursorScreenPos();
        const ImVec2 centre(origin.x + size / 2, origin.y + size / 2);
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddRectFilled(origin, ImVec2(origin.x + size, origin.y + size),
                            IM_COL32(25, 25, 30, 255));
        std::vector<double> values(180);
        double top = 0;
        for (int i = 0; i < 180; ++i) {
            values[std::size_t(i)] = std::max(0.0, p.atAngle(i * 2.0, 1.5 * p.width()));
            top = std::max(top, values[std::size_t(i)]);
        }
        std::vector<ImVec2> points;
        for (int i = 0; i < 180; ++i) {
            const double r = top > 0 ? values[std::size_t(i)] / top * (size / 2 - 6) : 0;
            const double a = i * 2.0 * M_PI / 180.0;
            // Counter-clockwise from +x, y up on screen, as the texture shows it.
            points.push_back(
                ImVec2(centre.x + float(r * std::cos(a)), centre.y - float(r * std::sin(a))));
        }
        draw->AddPolyline(points.data(), int(points.size()), IM_COL32(120, 200, 255, 255),
                          ImDrawFlags_Closed, 1.5f);
        ImGui::Dummy(ImVec2(size, size));
    } catch (const std::exception& e) {
        ImGui::TextWrapped("no propagator: %s", e.what());
    }
}

// The typed field right of a slider: the value entered (with Enter) where it
// differs from `value`.
std::optional<float> typedField(float value, float width) {
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(width);
    float typed = value;
    if (ImGui::InputFloat("##typed", &typed, 0, 0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) &&
        typed != value)
        return typed;
    return std::nullopt;
}

} // namespace

void Designer::drawControls(float x, float y, float w, float h) {
    beginPanel("Controls", x, y, w, h);
    // Resizing the panel moves the canvas' edge.
    if (ImGui::GetWindowSize().x != w)
        m_controlsWidth = ImGui::GetWindowSize().x;
    if (!m_doc.isOpen()) {
        ImGui::End();
        return;
    }
    // Transport.
    if (ImGui::Button(m_playing ? "Pause" : "Play", ImVec2(70, 0)))
        m_playing = !m_playing;
    ImGui::SameLine();
    if (ImGui::Button("Step"))
        stepOnce();
    ImGui::SameLine();
    if (ImGui::Button("Reset"))
        reset();
    ImGui::SameLine();
    if (ImGui::Button("Reseed"))
        reseed();
    bool autoSteps = m_stepsPerFrame == 0;
    if (ImGui::Checkbox("auto", &autoSteps))
        m_stepsPerFrame = autoSteps ? 0 : m_autoSteps;
    ImGui::SameLine();
    int steps = m_stepsPerFrame > 0 ? m_stepsPerFrame : m_autoSteps;
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##steps", &steps, 1, 2000, "%d steps/frame",
                         ImGuiSliderFlags_Logarithmic))
        m_stepsPerFrame = std::max(1, steps);
    if (m_doc.run().position().segments > 1) {
        const RunPosition p = m_doc.run().position();
        ImGui::Text("%s %d of %d, step %d", p.stages ? "stage" : "level", p.segment + 1, p.segments,
                    p.segmentStep / std::max(1, m_doc.run().substeps()));
    }
    ImGui::Separator();
    if (ImGui::CollapsingHeader("Model and operator", ImGuiTreeNodeFlags_DefaultOpen))
        drawModelSection();
    if (ImGui::CollapsingHeader("Parameters", ImGuiTreeNodeFlags_DefaultOpen))
        drawParamsSection();
    if (ImGui::CollapsingHeader("Cascade", m_doc.session().stages.empty()
                                               ? ImGuiTreeNodeFlags_None
                                               : ImGuiTreeNodeFlags_DefaultOpen))
        drawCascadeSection();
    if (ImGui::CollapsingHeader("Brush", ImGuiTreeNodeFlags_DefaultOpen))
        drawBrushSection();
    if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen))
        drawDisplaySection();
    ImGui::End();
}

void Designer::drawModelSection() {
    // A copy: a change below replaces the document's session mid-loop.
    const Session base = m_doc.session();
    const ReactionModel& model = base.reactionModel();
    ImGui::TextWrapped("%s", base.name.empty() ? "(unnamed session)" : base.name.c_str());
    if (!base.description.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("%s", base.description.c_str());
        ImGui::PopStyleColor();
    }

    if (ImGui::BeginCombo("model", model.name().c_str())) {
        for (const std::string& name : splitNameList(modelNames())) {
            if (ImGui::Selectable(name.c_str(), name == model.name()) && name != model.name())
                guarded("model", [&] {
                    // A fresh session of the model at this size: its defaults.
                    json j = {{"model", name},
                              {"size", {base.width, base.height}},
                              {"seed", base.seed},
                              {"colormap", {{"name", base.colormap.name}}}};
                    if (base.length > 0)
                        j["length"] = base.length;
                    Session s = sessionFromJson(j, "the designer's session");
                    s.name = name;
                    m_doc.replace(std::move(s), "model " + name);
                    m_displayChemical = -1;
                });
        }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s", model.description().c_str());
    // A cascade's later stage may run another model: the parameters below are its.
    const ReactionModel& running = m_doc.live().reactionModel();
    if (running.name() != model.name()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.95f, 0.75f, 0.35f, 1.0f));
        ImGui::TextWrapped("now running %s (stage %d; its parameters below)",
                           running.name().c_str(), m_doc.run().position().segment + 1);
        ImGui::PopStyleColor();
    }

    int op = operatorIndex(base.diffusion);
    if (ImGui::Combo("operator", &op, kOperatorLabels, IM_ARRAYSIZE(kOperatorLabels)) &&
        op != operatorIndex(base.diffusion)) {
        guarded("operator", [&] {
            Session s = edited(base, [&](json& j) {
                json d;
                if (op <= 1) {
                    d = {{"type", "isotropic"}, {"stencil", op == 0 ? "5-point" : "9-point"}};
                } else if (op == 2) {
                    d = {{"type", "anisotropic"}, {"tensors", json::object()}};
                    for (const ChemicalSpec& c : model.chemicals())
                        if (!c.diffusionParam.empty())
                            d["tensors"][c.name] = {{"theta", 0}, {"a1", 2}, {"a2", 1}};
                } else {
                    d = {{"type", "generalized"}, {"tensors", json::object()}};
                    for (const ChemicalSpec& c : model.chemicals())
                        if (!c.diffusionParam.empty())
                            d["tensors"][c.name] = "c";
                }
                j["diffusion"] = d;
            });
            m_doc.replace(std::move(s), std::string("operator ") + kOperatorLabels[op]);
        });
    }
    // The operator's own settings: a change restarts the run (a saved
    // session reproduces a run only from its start).
    if (base.diffusion.type == DiffusionType::Anisotropic) {
        for (const auto& entry : base.diffusion.anisotropic) {
            const std::string& chemical = entry.first;
            const AnisotropicTensor& tensor = entry.second;
            float values[3] = {float(tensor.theta), float(tensor.a1), float(tensor.a2)};
            ImGui::PushID(chemical.c_str());
            ImGui::Text("%s: angle, a1, a2", chemical.c_str());
            ImGui::DragFloat3("##tensor", values, 0.05f);
            if (ImGui::IsItemDeactivatedAfterEdit())
                guarded("tensor", [&] {
                    Session s = edited(base, [&](json& j) {
                        j["diffusion"]["tensors"][chemical] = {
                            {"theta", values[0]}, {"a1", values[1]}, {"a2", values[2]}};
                    });
                    m_doc.replace(std::move(s), "tensor of " + chemical);
                });
            ImGui::PopID();
        }
        if (base.surface.active())
            drawDirectionControls(base);
    } else if (base.diffusion.type == DiffusionType::Generalized) {
        for (const auto& entry : base.diffusion.generalized) {
            const std::string& chemical = entry.first;
            const std::string& set = entry.second;
            ImGui::PushID(chemical.c_str());
            if (ImGui::BeginCombo(("tensors " + chemical).c_str(), set.c_str())) {
                for (const char* letter : {"a", "b", "c", "d", "e", "f"})
                    if (ImGui::Selectable(letter, set == letter) && set != letter)
                        guarded("tensor set", [&] {
                            Session s = edited(base, [&](json& j) {
                                j["diffusion"]["tensors"][chemical] = letter;
                            });
                            m_doc.replace(std::move(s), "tensor set " + std::string(letter));
                        });
                ImGui::EndCombo();
            }
            drawPropagator(set);
            ImGui::PopID();
        }
    }

    int integrator = base.integrator == Integrator::ExplicitEuler ? 0 : 1;
    const char* integrators[] = {"explicit Euler", "semi-implicit"};
    if (ImGui::Combo("integrator", &integrator, integrators, 2))
        guarded("integrator", [&] {
            Session s = edited(base, [&](json& j) {
                j["integrator"] = integrator == 0 ? "explicit_euler" : "semi_implicit";
            });
            m_doc.replace(std::move(s), std::string("integrator ") + integrators[integrator]);
        });
    drawGravityControls(base);
    // On a model the tiles' connectivity is the surface: no canvas edges, and
    // the atlas's size comes from its tiles (the session's surface block).
    if (base.surface.active())
        return;
    int edges = base.edges == EdgeMode::Periodic ? 0 : 1;
    const char* edgeNames[] = {"periodic (tiles seamlessly)", "clamped"};
    if (ImGui::Combo("edges", &edges, edgeNames, 2))
        guarded("edges", [&] {
            Session s =
                edited(base, [&](json& j) { j["edges"] = edges == 0 ? "periodic" : "clamped"; });
            m_doc.replace(std::move(s), "edges");
        });
    int size[2] = {base.width, base.height};
    ImGui::InputInt2("grid", size);
    if (ImGui::IsItemDeactivatedAfterEdit() && (size[0] != base.width || size[1] != base.height))
        guarded("grid size", [&] {
            if (size[0] < 8 || size[1] < 8 || size[0] > 4096 || size[1] > 4096)
                throw InputError("grid " + std::to_string(size[0]) + " x " +
                                 std::to_string(size[1]) +
                                 " is outside 8..4096 per side (the canvas; exports go larger)");
            Session s = base;
            resizeSession(s, size[0], size[1]);
            m_doc.replace(std::move(s), "grid size");
        });
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("cells of the canvas; the pattern keeps its size in the picture");
}

// Drops on a tilted canvas or running down a model (Session::gravity): on,
// the downhill angle on the canvas or gravity's direction in the model's
// object space, and the drift speed; each change is a new session, as the
// edges are (on a model the surface's drift weights are rebuilt).
void Designer::drawGravityControls(const Session& base) {
    const bool model = base.surface.active();
    bool on = base.gravity.active();
    float angle = float(base.gravity.angle);
    float down[3] = {float(base.gravity.direction[0]), float(base.gravity.direction[1]),
                     float(base.gravity.direction[2])};
    float strength = float(on ? base.gravity.strength : 0.3);
    bool changed = ImGui::Checkbox("gravity", &on);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(model ? "water and everything that diffuses runs down the model\n"
                                  "(paint wet drops with the watercolour brush)"
                                : "tilt the canvas: water and everything that diffuses drifts "
                                  "downhill\n(drops run down the page; 270 degrees is down)");
    if (on) {
        if (model) {
            ImGui::DragFloat3("down", down, 0.01f, -1.0f, 1.0f);
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("gravity in the model's object space (0, -1, 0: down its y "
                                  "axis);\ndrops follow its projection on the surface");
        } else {
            ImGui::DragFloat("downhill", &angle, 1.0f, -360.0f, 360.0f, "%.0f degrees");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("counter-clockwise from +x: 270 is down the page");
        }
        ImGui::DragFloat("drift", &strength, 0.01f, 0.0f, float(kMaxGravityStrength),
                         "%.2f units/time");
        changed |= ImGui::IsItemDeactivatedAfterEdit();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("how fast things run downhill, model units per unit time");
    }
    // On a model the drift can follow a carrier (Gravity::carrier): none, or
    // one of the model's first four chemicals (the GPU step reads them there).
    const ReactionModel& reaction = base.reactionModel();
    std::vector<std::string> carriers = {"none"};
    for (int c = 0; c < std::min(4, int(reaction.chemicals().size())); ++c)
        carriers.push_back(reaction.chemicals()[std::size_t(c)].name);
    int carrier = 0;
    for (std::size_t i = 1; i < carriers.size(); ++i)
        if (carriers[i] == base.gravity.carrier)
            carrier = int(i);
    float cling = float(base.gravity.cling);
    if (on && model) {
        std::vector<const char*> names;
        for (const std::string& n : carriers)
            names.push_back(n.c_str());
        changed |= ImGui::Combo("carrier", &carrier, names.data(), int(names.size()));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("the drift follows this chemical: where it is thin, things cling\n"
                              "(watercolour's w: drops keep a head and leave a wet trail)");
        if (carrier > 0) {
            ImGui::DragFloat("cling", &cling, 0.01f, 0.001f, 10.0f, "%.2f deep");
            changed |= ImGui::IsItemDeactivatedAfterEdit();
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("the carrier's depth at which things run at half speed");
        }
    }
    if (!changed)
        return;
    guarded("gravity", [&] {
        Session s = edited(base, [&](json& j) {
            if (!on) {
                j.erase("gravity");
                return;
            }
            // The block's other fields (a carrier, its cling) stay as they were.
            json& g = j["gravity"];
            if (!g.is_object())
                g = json::object();
            g["strength"] = strength;
            if (model) {
                g["direction"] = json::array({down[0], down[1], down[2]});
                if (carrier > 0) {
                    g["carrier"] = carriers[std::size_t(carrier)];
                    g["cling"] = std::max(cling, 0.001f);
                } else {
                    g.erase("carrier");
                }
            } else {
                g["angle"] = angle;
            }
        });
        m_doc.replace(std::move(s), on ? "gravity" : "gravity off");
    });
}

// On a model the tensors' angles are measured from a direction field on the
// surface (SurfaceSpec::direction): along an axis, or around one.
void Designer::drawDirectionControls(const Session& base) {
    const SurfaceDirection& d = base.surface.direction;
    int kind = d.type == SurfaceDirection::Type::Along ? 0 : 1;
    const char* kinds[] = {"along an axis", "around an axis"};
    float axis[3] = {float(d.axis[0]), float(d.axis[1]), float(d.axis[2])};
    float through[3] = {float(d.through[0]), float(d.through[1]), float(d.through[2])};
    bool changed = ImGui::Combo("angle 0", &kind, kinds, 2);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("on the model, the tensors' angle 0 follows this direction field:\n"
                          "an axis projected onto the surface, or circles about an axis");
    ImGui::DragFloat3("axis", axis, 0.01f, -1.0f, 1.0f);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    if (kind == 1) {
        ImGui::DragFloat3("through", through, 0.01f);
        changed |= ImGui::IsItemDeactivatedAfterEdit();
    }
    if (!changed)
        return;
    guarded("direction", [&] {
        const auto vector = [](const float* v) { return json::array({v[0], v[1], v[2]}); };
        Session s = edited(base, [&](json& j) {
            j["surface"]["direction"] =
                kind == 0 ? json{{"along", vector(axis)}}
                          : json{{"around", vector(axis)}, {"through", vector(through)}};
        });
        m_doc.replace(std::move(s), "direction on the model");
    });
}

void Designer::drawParamsSection() {
    const Session& live = m_doc.live();
    const ReactionModel& model = live.reactionModel();
    // Each row is slider, typed field, name. The field is as wide as the
    // longest value it shows and the names get their longest width, so the
    // panel's edge clips the slider, never a number ("evaporation" left the
    // field 3 characters: 0.002 read as 0.00).
    const ImGuiStyle& style = ImGui::GetStyle();
    const float fieldWidth = ImGui::CalcTextSize("-0.000000").x + 2 * style.FramePadding.x;
    float nameWidth = ImGui::CalcTextSize("dt").x;
    for (const ParamSpec& p : model.params())
        nameWidth = std::max(nameWidth, ImGui::CalcTextSize(p.name.c_str()).x);
    const float avail = ImGui::GetContentRegionAvail().x;
    const float sliderWidth =
        std::max(avail * 0.35f, avail - fieldWidth - nameWidth - 2 * style.ItemInnerSpacing.x);
    for (const ParamSpec& p : model.params()) {
        float value = live.params.at(p.name);
        ImGui::PushID(p.name.c_str());
        ImGui::SetNextItemWidth(sliderWidth);
        // Ctrl+click types a value; the range is the model's.
        const bool changed = ImGui::SliderFloat("##slider", &value, p.min, p.max, "%.5g",
                                                p.max / std::max(p.min, 1e-9f) > 1000 && p.min > 0
                                                    ? ImGuiSliderFlags_Logarithmic
                                                    : ImGuiSliderFlags_None);
        if (ImGui::IsItemActivated())
            m_doc.beginChange("change " + p.name);
        if (changed)
            guarded("parameter", [&] { m_doc.setParam(p.name, std::clamp(value, p.min, p.max)); });
        if (ImGui::IsItemDeactivated())
            m_doc.endChange();
        const auto tooltip = [&] {
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("%s\nrange %g .. %g, default %g\nCtrl+click to type a value",
                                  p.description.c_str(), p.min, p.max, p.defaultValue);
        };
        tooltip();
        if (const std::optional<float> typed = typedField(value, fieldWidth)) {
            if (*typed < p.min || *typed > p.max)
                reportError(p.name + " = " + std::to_string(*typed) + " is outside its range " +
                            std::to_string(p.min) + " .. " + std::to_string(p.max));
            else
                changeParam(p.name, *typed);
        }
        ImGui::SameLine(0, style.ItemInnerSpacing.x);
        ImGui::TextUnformatted(p.name.c_str());
        tooltip();
        ImGui::PopID();
    }
    // dt, as a session dt (the run divides it among substeps), in the same
    // slider | typed field | name row as the parameters.
    float dt = live.dt * float(m_doc.run().substeps());
    ImGui::PushID("dt");
    ImGui::SetNextItemWidth(sliderWidth);
    const bool changed =
        ImGui::SliderFloat("##slider", &dt, 0.001f, 4.0f, "%.4g", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemActivated())
        m_doc.beginChange("change dt");
    if (changed)
        guarded("dt", [&] { m_doc.setDt(std::max(dt, 1e-4f)); });
    if (ImGui::IsItemDeactivated())
        m_doc.endChange();
    if (const std::optional<float> typed = typedField(dt, fieldWidth)) {
        // The bounds a session file accepts, so what is typed can be saved and reopened.
        if (!(*typed >= float(kMinDt) && *typed <= float(kMaxDt))) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "dt = %g is outside %g .. %g (the stability line says how large it "
                          "can be)",
                          double(*typed), kMinDt, kMaxDt);
            reportError(text);
        } else {
            guarded("dt", [&] { m_doc.changeOnce("change dt", [&] { m_doc.setDt(*typed); }); });
        }
    }
    ImGui::SameLine(0, style.ItemInnerSpacing.x);
    ImGui::TextUnformatted("dt");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the session's time step: drag (0.001 .. 4) or type a value (1e-06 .. 100)");
    ImGui::PopID();

    // The stability report of the values in force, as the CLI checks them:
    // recomputed when a setting or the running stage changes, not per frame.
    const std::pair<std::uint64_t, int> key{m_doc.revision(), m_doc.run().position().segment};
    if (key != m_stabilityKey) {
        m_stabilityKey = key;
        m_stabilityText.clear();
        m_stabilityWarning = false;
        Session check = live;
        check.steps = 1;
        check.stages.clear();
        check.dt = dt;
        try {
            const StabilityReport report = checkSessionStability(check, true);
            for (const StabilityNote& n : report.notes) {
                m_stabilityText += n.text + "\n";
                m_stabilityWarning = m_stabilityWarning || n.warning;
            }
            if (report.refused) {
                m_stabilityText += *report.refused;
                m_stabilityWarning = true;
            }
            if (report.capped) {
                m_stabilityText += "dt is above the stable limit: the CLI would cap it to " +
                                   std::to_string(check.dt);
                m_stabilityWarning = true;
            }
        } catch (const std::exception& e) {
            m_stabilityText = e.what();
            m_stabilityWarning = true;
        }
        if (m_stabilityText.empty())
            m_stabilityText = "stable";
    }
    ImGui::PushStyleColor(ImGuiCol_Text, m_stabilityWarning ? ImVec4(1, 0.7f, 0.3f, 1)
                                                            : ImVec4(0.6f, 0.9f, 0.6f, 1));
    ImGui::TextWrapped("%s", m_stabilityText.c_str());
    ImGui::PopStyleColor();
}

void Designer::drawBrushSection() {
    const ReactionModel& model = m_doc.live().reactionModel();
    const char* modes[] = {"add", "remove", "set", "hold", "release", "distort", "paint"};
    int mode = int(m_brush.mode);
    if (ImGui::Combo("mode", &mode, modes, IM_ARRAYSIZE(modes)))
        m_brush.mode = BrushMode(mode);
    const bool paintsWater = model.chemicalIndex("w") >= 0 && m_brush.mode == BrushMode::Add;
    if (paintsWater)
        ImGui::Checkbox("watercolour: water + pigment", &m_brush.watercolour);
    if (watercolourBrush() || (paintsWater && m_brush.watercolour)) {
        ImGui::SliderFloat("water", &m_brush.water, 0.0f, 4.0f, "%.2f");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("More water bleeds wider and stays wet longer (Lo Fig. 9).");
        if (ImGui::BeginCombo("pigment", m_brush.pigment.c_str())) {
            for (const ChemicalSpec& c : model.chemicals())
                if (c.name.size() == 2 && c.name[0] == 'p' && std::isdigit(c.name[1]) &&
                    ImGui::Selectable(c.name.c_str(), c.name == m_brush.pigment))
                    m_brush.pigment = c.name;
            ImGui::EndCombo();
        }
        ImGui::SliderFloat("amount", &m_brush.value, 0.0f, 2.0f, "%.3f");
    } else if (writesChemical(m_brush.mode)) {
        const int shown = m_brush.chemical >= 0 && m_brush.chemical < int(model.chemicals().size())
                              ? m_brush.chemical
                              : model.displayChemical();
        if (ImGui::BeginCombo("chemical", model.chemicals()[std::size_t(shown)].name.c_str())) {
            for (int c = 0; c < int(model.chemicals().size()); ++c)
                if (ImGui::Selectable(model.chemicals()[std::size_t(c)].name.c_str(), c == shown))
                    m_brush.chemical = c;
            ImGui::EndCombo();
        }
        ImGui::SliderFloat("amount", &m_brush.value, -2.0f, 2.0f, "%.3f");
    } else if (m_brush.mode == BrushMode::Paint) {
        const ParamSpec* p = model.param(m_brush.param);
        if (!p) {
            p = &model.params().front();
            m_brush.param = p->name;
            m_brush.value = m_doc.live().params.at(p->name);
        }
        if (ImGui::BeginCombo("parameter", m_brush.param.c_str())) {
            for (const ParamSpec& q : model.params())
                if (ImGui::Selectable(q.name.c_str(), q.name == m_brush.param)) {
                    m_brush.param = q.name;
                    m_brush.value = m_doc.live().params.at(q.name);
                }
            ImGui::EndCombo();
        }
        p = model.param(m_brush.param);
        ImGui::SliderFloat("value", &m_brush.value, p->min, p->max, "%.5g");
    }
    ImGui::SliderFloat("radius", &m_brush.radius, 0.002f, 0.5f,
                       m_surface ? "%.3f of the model" : "%.3f of width",
                       ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("falloff", &m_brush.falloff, 0.0f, 1.0f, "%.2f");
    if (m_surface) {
        ImGui::Checkbox("re-grow locally", &m_brush.localized);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "After a stroke only the tiles it can reach step, ring by ring, until "
                "the pattern there settles (Lo's localized reaction-diffusion): "
                "fast on a settled pattern; the rest of the model waits meanwhile.");
        ImGui::SameLine();
        ImGui::Checkbox("show active tiles", &m_showActiveTiles);
        ImGui::Checkbox("deform", &m_brush.deform);
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Left drag on the model stretches it instead of painting (Lo 5.5): "
                              "the surface under the brush where the drag starts, along the "
                              "drag (fading out beyond the brush, further for strong "
                              "stretches); the pattern re-grows there.");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
        ImGui::SliderFloat("stretch", &m_brush.stretch, float(kMinDeformFactor),
                           float(kMaxDeformFactor), "x %.2f", ImGuiSliderFlags_Logarithmic);
        if (m_brush.deform) {
            ImGui::Checkbox("across the model", &m_brush.across);
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("Stretch the whole slab across the model, not only under "
                                  "the brush: everything beyond it moves rigidly.");
        }
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Left drag paints, right or middle drag pans, the wheel zooms, [ and ] "
                       "size the brush.");
    ImGui::PopStyleColor();
}

void Designer::drawDisplaySection() {
    const Session& base = m_doc.live();
    const ReactionModel& model = base.reactionModel();
    const int shown = m_displayChemical >= 0 ? m_displayChemical : m_doc.liveChemical();
    if (ImGui::BeginCombo("shows", model.chemicals()[std::size_t(shown)].name.c_str())) {
        for (int c = 0; c < int(model.chemicals().size()); ++c)
            if (ImGui::Selectable(model.chemicals()[std::size_t(c)].name.c_str(), c == shown))
                m_displayChemical = c;
        ImGui::EndCombo();
    }
    // The colour map changes the picture, not the run: no restart.
    if (ImGui::BeginCombo("colours", base.colormap.name.c_str())) {
        for (const std::string& name : colormapNames())
            // The watercolour map paints the watercolour model's pigments only.
            if (name != "custom" && (name != "watercolour" || paintsAsWatercolour(model)) &&
                ImGui::Selectable(name.c_str(), name == base.colormap.name))
                guarded("colour map", [&] {
                    ColorMapSpec spec = base.colormap;
                    spec.name = name;
                    m_doc.setColormap(spec);
                });
        ImGui::EndCombo();
    }
    if (isWatercolourMap(base.colormap))
        drawWatercolourEdges();
    ImGui::Checkbox("tiled 3x3", &m_tiled);
    ImGui::SameLine();
    ImGui::Checkbox("nearest texels", &m_nearest);
}

void Designer::drawWatercolourEdges() {
    ColorMapSpec spec = m_colormapDraft ? *m_colormapDraft : m_doc.live().colormap;
    bool changed = false, done = false;
    const auto slider = [&](const char* label, float* value, float low, float high,
                            const char* format, ImGuiSliderFlags flags, const char* tip) {
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
        changed |= ImGui::SliderFloat(label, value, low, high, format, flags);
        done |= ImGui::IsItemDeactivatedAfterEdit();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s", tip);
    };
    slider("dark edges", &spec.edgeDarkening, 0.0f, 4.0f, "%.2f", ImGuiSliderFlags_None,
           "How much denser a dried wash is painted at its edge (1: twice, where the edge is "
           "sharp). A render effect on where the paper was wet; the simulation is unchanged. "
           "Not on a model.");
    slider("edge width", &spec.edgeWidth, 0.001f, 0.25f, "%.3f", ImGuiSliderFlags_Logarithmic,
           "The dark band's width, a fraction of the canvas width (as brush radii are).");
    if (changed) {
        spec.edgeDarkening = std::clamp(spec.edgeDarkening, 0.0f, 4.0f);
        spec.edgeWidth = std::clamp(spec.edgeWidth, 0.001f, 0.25f);
        m_colormapDraft = spec;
    }
    if (done && m_colormapDraft) {
        const ColorMapSpec draft = *m_colormapDraft;
        m_colormapDraft.reset();
        guarded("colour map", [&] { m_doc.setColormap(draft); });
    }
}

} // namespace morphogen::ui
