// The designer's parameter-map panel: two of the model's parameters swept
// across a picture rendered by the engine (the session's own setup with the
// two parameters as linear maps, as `morphogen map` renders it), a marker at
// the current values, and a click that sets both.

#include <algorithm>
#include <cmath>

#include <glad/gl.h>
#include <imgui.h>

#include "core/base/errors.hpp"
#include "core/sim/cpu_simulator.hpp"
#include "core/sim/exploration_points.hpp"
#include "ui/coloured_state.hpp"
#include "ui/designer_app.hpp"

namespace morphogen::ui {

namespace {

constexpr int kMapSide = 160;   // cells: the picture
constexpr int kMapSteps = 4000; // enough for most models' patterns to form at this size

ImTextureID textureId(unsigned id) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id));
}

} // namespace

bool Designer::syncMapAxes() {
    const Session& live = m_doc.live();
    const ReactionModel& model = live.reactionModel();
    if (model.params().size() < 2)
        return false;
    // The axes: the model's first two parameters by default (F and k for
    // Gray-Scott), each over 0.75 to 1.25 times its current value; a new
    // model (a preset, a cascade's next stage) starts them afresh.
    if (m_mapModel != model.name()) {
        m_mapModel = model.name();
        m_mapAxes[0].param = model.params()[0].name;
        m_mapAxes[1].param = model.params()[1].name;
        for (MapAxis& a : m_mapAxes) {
            const ParamSpec* p = model.param(a.param);
            const float v = live.params.at(a.param);
            a.min = std::max(p->min, v * 0.75f);
            a.max = std::min(p->max, v > 0 ? v * 1.25f : p->max);
        }
        m_mapImage = gl::Texture2D();
    }
    return m_mapAxes[0].param != m_mapAxes[1].param && m_mapAxes[0].min < m_mapAxes[0].max &&
           m_mapAxes[1].min < m_mapAxes[1].max;
}

void Designer::drawMapPanel() {
    const Session& live = m_doc.live();
    const ReactionModel& model = live.reactionModel();
    if (model.params().size() < 2) {
        ImGui::TextDisabled("The model has fewer than two parameters.");
        return;
    }
    syncMapAxes();
    for (int i = 0; i < 2; ++i) {
        MapAxis& a = m_mapAxes[i];
        ImGui::PushID(i);
        ImGui::SetNextItemWidth(90);
        if (ImGui::BeginCombo(i == 0 ? "x" : "y", a.param.c_str())) {
            for (const ParamSpec& p : model.params())
                if (ImGui::Selectable(p.name.c_str(), p.name == a.param)) {
                    a.param = p.name;
                    const float v = live.params.at(p.name);
                    a.min = std::max(p.min, v * 0.75f);
                    a.max = std::min(p.max, v > 0 ? v * 1.5f : p.max);
                }
            ImGui::EndCombo();
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        const ParamSpec* p = model.param(a.param);
        float range[2] = {a.min, a.max};
        if (ImGui::InputFloat2("##range", range, "%.5g")) {
            a.min = std::clamp(range[0], p->min, p->max);
            a.max = std::clamp(range[1], p->min, p->max);
        }
        ImGui::PopID();
    }
    const bool valid = m_mapAxes[0].param != m_mapAxes[1].param &&
                       m_mapAxes[0].min < m_mapAxes[0].max && m_mapAxes[1].min < m_mapAxes[1].max;
    ImGui::BeginDisabled(!valid || m_job != nullptr);
    if (ImGui::Button("Render map", ImVec2(-1, 0)))
        renderMap();
    ImGui::EndDisabled();
    if (!valid)
        ImGui::TextDisabled("two different parameters, each with min < max");

    if (m_mapImage.width() == 0) {
        ImGui::TextWrapped("The map runs the session from noise with %s varying left to right "
                           "and %s bottom to top (%d x %d cells, %d steps, in the background).",
                           m_mapAxes[0].param.c_str(), m_mapAxes[1].param.c_str(), kMapSide,
                           kMapSide, kMapSteps);
        return;
    }
    const MapAxis& x = m_mapRendered[0];
    const MapAxis& y = m_mapRendered[1];
    const float side = std::min(ImGui::GetContentRegionAvail().x, 360.0f);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Image(textureId(m_mapImage.id()), ImVec2(side, side));
    // Where the current values sit, and a click to take a point's values.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float vx = live.params.count(x.param) ? live.params.at(x.param) : x.min;
    const float vy = live.params.count(y.param) ? live.params.at(y.param) : y.min;
    const float px = origin.x + (vx - x.min) / (x.max - x.min) * side;
    const float py = origin.y + (1.0f - (vy - y.min) / (y.max - y.min)) * side;
    if (px >= origin.x && px <= origin.x + side && py >= origin.y && py <= origin.y + side) {
        draw->AddCircle(ImVec2(px, py), 6, IM_COL32(0, 0, 0, 220), 16, 3.0f);
        draw->AddCircle(ImVec2(px, py), 6, IM_COL32(255, 255, 255, 255), 16, 1.5f);
    }
    if (ImGui::IsItemHovered()) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        const float fx = std::clamp((m.x - origin.x) / side, 0.0f, 1.0f);
        const float fy = std::clamp(1.0f - (m.y - origin.y) / side, 0.0f, 1.0f);
        const float ax = x.min + fx * (x.max - x.min), ay = y.min + fy * (y.max - y.min);
        ImGui::SetTooltip("%s = %.5g\n%s = %.5g\nclick to use", x.param.c_str(), ax,
                          y.param.c_str(), ay);
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && live.reactionModel().param(x.param) &&
            live.reactionModel().param(y.param))
            guarded("map", [&] {
                m_doc.changeOnce("map point", [&] {
                    m_doc.setParam(x.param, ax);
                    m_doc.setParam(y.param, ay);
                });
            });
    }
    // One axis a line: wrapped as one sentence, a narrow panel broke a number in two.
    ImGui::Text("%s %.4g .. %.4g (x)", x.param.c_str(), x.min, x.max);
    ImGui::Text("%s %.4g .. %.4g (y)", y.param.c_str(), y.min, y.max);
}

void Designer::renderMap() {
    // Called by the panel's button and by scripts, perhaps before the panel
    // was first drawn: the axes must be the model's.
    if (!syncMapAxes()) {
        reportError("map: two different parameters of the model, each with min < max");
        return;
    }
    Session s = m_doc.live();
    s.colormap = m_doc.liveColormap();
    s.name = "map";
    s.atlas.reset();
    s.atlasWeights.reset();
    s.atlasPositions.reset();
    s.surface = SurfaceSpec{};
    s.stages.clear();
    s.edits.clear();
    s.schedule.clear();
    s.coarseToFine = false;
    s.edges = EdgeMode::Clamped; // the axes' ends stay apart
    resizeSession(s, kMapSide, kMapSide);
    s.steps = kMapSteps;
    // Perturbations everywhere (as `map --start noise`): each point shows the
    // pattern it settles to, not how far a front from a few seeds got.
    s.init = noiseStart(s.init, s.reactionModel());
    s.paramMaps.erase(m_mapAxes[0].param);
    s.paramMaps.erase(m_mapAxes[1].param);
    s.paramMaps[m_mapAxes[0].param] = {ParamMapSpec::Field::LinearX, m_mapAxes[0].min,
                                       m_mapAxes[0].max};
    s.paramMaps[m_mapAxes[1].param] = {ParamMapSpec::Field::LinearY, m_mapAxes[1].min,
                                       m_mapAxes[1].max};
    bool valid = false;
    guarded("map", [&] {
        validateSession(s, "the parameter map");
        valid = true;
    });
    if (!valid)
        return;
    m_job = std::make_unique<BackgroundJob>();
    m_job->title = "Rendering the " + m_mapAxes[0].param + " x " + m_mapAxes[1].param + " map";
    BackgroundJob* job = m_job.get();
    auto pixels = std::make_shared<std::vector<float>>();
    job->worker = std::thread([job, s, pixels] {
        try {
            RunOptions options;
            options.cancel = &job->cancel;
            options.progress = [job](int done, int total) {
                job->done = done;
                job->total = std::max(1, total);
            };
            const SimulatorFactory cpu = [](const Session& part) {
                return std::make_unique<CpuSimulator>(part);
            };
            // The map runs every pair of values from noise, some of them
            // stiffer than the session's own (a cascade stage tuned to start
            // from the stage before it, say): where the session's dt blows up
            // there, the map is run again at the suggested dt over as much
            // time, twice at most, rather than failing.
            Session run = s;
            for (int attempt = 0;; ++attempt) {
                try {
                    const RunResult r = runSession(run, cpu, options);
                    if (!r.cancelled) {
                        *pixels =
                            colouredRgba(r.state, colormapChemical(run.colormap, run.outputModel()),
                                         run.colormap, run.edges);
                        job->message = "rendered the map";
                        if (run.dt != s.dt)
                            job->message += " (at dt " + std::to_string(run.dt).substr(0, 6) +
                                            ": the session's dt " +
                                            std::to_string(s.dt).substr(0, 6) +
                                            " blew up in part of it)";
                    } else {
                        job->message = "map cancelled";
                    }
                    break;
                } catch (const BlowUpError& e) {
                    if (attempt == 2 || !(e.suggestedDt() < run.dt))
                        throw;
                    const double time = double(s.steps) * double(s.dt);
                    run.dt = e.suggestedDt();
                    run.steps = int(std::ceil(time / double(run.dt)));
                }
            }
        } catch (const std::exception& e) {
            job->message = std::string("map failed: ") + e.what();
        }
        job->finished = true;
    });
    const std::array<MapAxis, 2> axes = m_mapAxes;
    job->finish = [this, pixels, axes] {
        if (pixels->empty())
            return;
        m_mapImage = gl::Texture2D(kMapSide, kMapSide, GL_RGBA8);
        m_mapImage.uploadRgba(*pixels);
        m_mapRendered = axes;
        if (m_redraw)
            m_redraw->invalidate();
    };
}

} // namespace morphogen::ui
