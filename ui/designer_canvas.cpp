// The designer's canvas (zoom, pan, brush strokes, the readout under the
// cursor) and its side panel (presets browser, growth history).

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include <glad/gl.h>
#include <imgui.h>

#include "core/base/names.hpp"
#include "ui/designer_app.hpp"
#include "ui/layout_window.hpp"

namespace morphogen::ui {

namespace {

ImTextureID textureId(unsigned id) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(id));
}

} // namespace

void Designer::drawCanvas(float x, float y, float w, float h) {
    beginView("Canvas", x, y, w, h);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    m_canvasRect = {origin.x, origin.y, size.x, size.y};
    if (!m_display || size.x < 8 || size.y < 8) {
        ImGui::End();
        return;
    }
    const int cw = m_display->texture().width(), ch = m_display->texture().height();
    if (!m_viewFramed) {
        m_view.frame(cw, ch, size.x, size.y);
        if (m_tiled)
            m_view.zoom /= 3.0;
        m_viewFramed = true;
    }

    ImGui::InvisibleButton("canvas", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const bool hovered = ImGui::IsItemHovered();
    const ImGuiIO& io = ImGui::GetIO();
    const std::array<double, 2> mouse = {io.MousePos.x - origin.x, io.MousePos.y - origin.y};
    const std::array<double, 2> cell = m_view.toCanvas(mouse, size.x, size.y);

    // Zoom to the cursor, pan with the right or middle button.
    if (hovered && io.MouseWheel != 0)
        m_view.zoomAt(std::pow(1.2, io.MouseWheel), mouse, size.x, size.y);
    if (ImGui::IsItemActive() && (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0) ||
                                  ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0)))
        m_view.pan(io.MouseDelta.x, io.MouseDelta.y);

    // Strokes: the left button paints through the engine's brush writes.
    const std::array<double, 2> fraction = {cell[0] / cw, cell[1] / ch};
    // On a mesh the brush works in the 3D view (across tile seams): the atlas
    // canvas is for looking.
    if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && !m_scrub &&
        !m_surface) {
        const StrokeSpec stroke = strokeFromBrush();
        const std::optional<StrokeSpec> companion = companionFromBrush();
        ++m_brush.seed;
        guarded("brush", [&] {
            m_doc.beginStroke(stroke, companion);
            m_doc.extendStroke({fraction});
        });
    } else if (m_doc.stroking() && !m_surface && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)
            guarded("brush", [&] { m_doc.extendStroke({fraction}); });
    }
    if (m_doc.stroking() && !ImGui::IsMouseDown(ImGuiMouseButton_Left))
        guarded("brush", [&] { m_doc.endStroke(); });

    // The picture: 3x3 copies in the tiled preview (a periodic pattern must
    // show no seams), nearest texels once a texel is several pixels wide.
    glBindTexture(GL_TEXTURE_2D, m_display->texture().id());
    const GLint filter = m_nearest && m_view.zoom >= 3.0 ? GL_NEAREST : GL_LINEAR;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
    // The background only where the picture is not: on a software
    // rasterizer every covered pixel drawn twice is frame time taken from the
    // simulation.
    {
        const ImU32 background = IM_COL32(18, 18, 20, 255);
        const ImVec2 end(origin.x + size.x, origin.y + size.y);
        const auto a = m_view.toScreen({0.0, 0.0}, size.x, size.y);
        const auto b = m_view.toScreen({double(cw), double(ch)}, size.x, size.y);
        const float x0 = std::clamp(origin.x + float(a[0]), origin.x, end.x);
        const float y0 = std::clamp(origin.y + float(a[1]), origin.y, end.y);
        const float x1 = std::clamp(origin.x + float(b[0]), x0, end.x);
        const float y1 = std::clamp(origin.y + float(b[1]), y0, end.y);
        if (m_tiled) {
            draw->AddRectFilled(origin, end, background);
        } else {
            draw->AddRectFilled(origin, ImVec2(end.x, y0), background);
            draw->AddRectFilled(ImVec2(origin.x, y1), end, background);
            draw->AddRectFilled(ImVec2(origin.x, y0), ImVec2(x0, y1), background);
            draw->AddRectFilled(ImVec2(x1, y0), ImVec2(end.x, y1), background);
        }
    }
    const int copies = m_tiled ? 1 : 0;
    // The picture is opaque: drawn without blending, which a software
    // rasterizer would pay for on every covered pixel.
    draw->AddCallback([](const ImDrawList*, const ImDrawCmd*) { glDisable(GL_BLEND); }, nullptr);
    for (int ty = -copies; ty <= copies; ++ty)
        for (int tx = -copies; tx <= copies; ++tx) {
            const auto a = m_view.toScreen({double(tx * cw), double(ty * ch)}, size.x, size.y);
            const auto b =
                m_view.toScreen({double((tx + 1) * cw), double((ty + 1) * ch)}, size.x, size.y);
            draw->AddImage(textureId(m_display->texture().id()),
                           ImVec2(origin.x + float(a[0]), origin.y + float(a[1])),
                           ImVec2(origin.x + float(b[0]), origin.y + float(b[1])));
        }
    draw->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
    if (m_tiled) {
        const auto a = m_view.toScreen({0, 0}, size.x, size.y);
        const auto b = m_view.toScreen({double(cw), double(ch)}, size.x, size.y);
        draw->AddRect(ImVec2(origin.x + float(a[0]), origin.y + float(a[1])),
                      ImVec2(origin.x + float(b[0]), origin.y + float(b[1])),
                      IM_COL32(255, 255, 255, 60));
    }
    // The localized re-growth's active tiles (Lo's Fig. 4) on the atlas.
    const LocalRegrowth* regrowth = m_doc.isOpen() ? m_doc.run().regrowth() : nullptr;
    if (m_showActiveTiles && regrowth && m_doc.live().atlas) {
        const Atlas& atlas = *m_doc.live().atlas;
        for (int t : regrowth->tiles()) {
            const std::uint32_t corner = atlas.tileCell(t, 0, 0);
            const double x = corner % std::uint32_t(atlas.width()),
                         y = corner / std::uint32_t(atlas.width()), n = atlas.tileSize();
            const auto a = m_view.toScreen({x, y}, size.x, size.y);
            const auto b = m_view.toScreen({x + n, y + n}, size.x, size.y);
            draw->AddRectFilled(ImVec2(origin.x + float(a[0]), origin.y + float(a[1])),
                                ImVec2(origin.x + float(b[0]), origin.y + float(b[1])),
                                IM_COL32(255, 140, 30, 70));
        }
    }
    // The brush outline: its radius and, inside, where the falloff starts.
    if (hovered || m_doc.stroking()) {
        const float r = float(m_brush.radius * cw * m_view.zoom);
        const ImVec2 c(io.MousePos.x, io.MousePos.y);
        draw->AddCircle(c, r, IM_COL32(255, 255, 255, 200), 64, 1.5f);
        draw->AddCircle(c, r, IM_COL32(0, 0, 0, 160), 64, 3.0f);
        if (m_brush.falloff > 0 && m_brush.falloff < 1)
            draw->AddCircle(c, r * (1 - m_brush.falloff), IM_COL32(255, 255, 255, 90), 48, 1.0f);
    }
    draw->PopClipRect();

    // The readout under the cursor: every chemical and parameter there.
    if (hovered && !m_doc.stroking()) {
        const int ix = int(std::floor(cell[0])), iy = int(std::floor(cell[1]));
        const int wx = ((ix % cw) + cw) % cw, wy = ((iy % ch) + ch) % ch;
        const bool inside = m_tiled || (ix >= 0 && iy >= 0 && ix < cw && iy < ch);
        if (inside) {
            const Clock::time_point now = Clock::now();
            if (seconds(now - m_lastReadout) > 0.1 || m_readout.width() == 0) {
                guarded("readout", [&] {
                    m_readout = m_scrub ? m_doc.history().state(*m_scrub) : m_doc.run().state();
                });
                m_lastReadout = now;
            }
            if (m_readout.width() == cw && m_readout.height() == ch) {
                const Session& live = m_doc.live();
                const ReactionModel& model = live.reactionModel();
                std::string text = "cell " + std::to_string(wx) + ", " + std::to_string(wy);
                for (int c = 0; c < int(model.chemicals().size()) && c < m_readout.channels();
                     ++c) {
                    char line[96];
                    std::snprintf(line, sizeof line, "\n%s = %.5g",
                                  model.chemicals()[std::size_t(c)].name.c_str(),
                                  m_readout.at(c, wx, wy));
                    text += line;
                }
                // A parameter that varies per cell shows the value the step uses
                // there (a map's, a painted one's, a sweep tile's), not the
                // base value the map replaces.
                const Simulator* simulator =
                    m_doc.run().finished() ? nullptr : &m_doc.run().simulator();
                for (const auto& [name, value] : live.params) {
                    const std::optional<float> here =
                        simulator ? simulator->cellParam(name, wx, wy) : std::nullopt;
                    char line[96];
                    std::snprintf(line, sizeof line, "\n%s = %.5g%s", name.c_str(),
                                  here ? *here : value, here ? " here" : "");
                    text += line;
                }
                ImGui::SetTooltip("%s", text.c_str());
            }
        }
    }
    if (m_scrub) {
        ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 8));
        ImGui::TextColored(ImVec4(1, 0.85f, 0.4f, 1),
                           "history: step %lld (Branch to continue from here)",
                           m_doc.history().step(*m_scrub));
    }
    ImGui::End();
}

StrokeSpec Designer::strokeFromBrush() const {
    const ReactionModel& model = m_doc.live().reactionModel();
    StrokeSpec stroke;
    stroke.mode = m_brush.mode;
    if (writesChemical(m_brush.mode)) {
        const int c = m_brush.chemical >= 0 && m_brush.chemical < int(model.chemicals().size())
                          ? m_brush.chemical
                          : model.displayChemical();
        stroke.chemical = model.chemicals()[std::size_t(c)].name;
    }
    stroke.param = m_brush.mode == BrushMode::Paint ? m_brush.param : "";
    stroke.value = m_brush.value;
    stroke.seed = m_brush.seed;
    stroke.radius = m_brush.radius;
    stroke.falloff = m_brush.falloff;
    if (watercolourBrush()) {
        stroke.chemical = "w";
        stroke.value = m_brush.water;
    }
    return stroke;
}

bool Designer::watercolourBrush() const {
    const ReactionModel& model = m_doc.live().reactionModel();
    return m_brush.watercolour && m_brush.mode == BrushMode::Add && model.chemicalIndex("w") >= 0 &&
           model.chemicalIndex(m_brush.pigment) >= 0;
}

std::optional<StrokeSpec> Designer::companionFromBrush() const {
    if (!watercolourBrush() || !(m_brush.value > 0))
        return std::nullopt;
    StrokeSpec pigment = strokeFromBrush();
    pigment.chemical = m_brush.pigment;
    pigment.value = m_brush.value;
    return pigment;
}

void Designer::drawSidePanel(float x, float y, float w, float h) {
    beginPanel("Library", x, y, w, h);
    if (ImGui::BeginTabBar("side")) {
        auto flags = [this](int tab) {
            return m_requestTab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
        };
        if (ImGui::BeginTabItem("Presets", nullptr, flags(0))) {
            drawPresets();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("History", nullptr, flags(1))) {
            drawHistory();
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Map", nullptr, flags(2))) {
            drawMapPanel();
            ImGui::EndTabItem();
        }
        m_requestTab = -1;
        ImGui::EndTabBar();
    }
    ImGui::End();
}

void Designer::drawPresets() {
    if (m_presets.empty())
        m_presets = allPresets();
    ImGui::SetNextItemWidth(-1);
    char filter[128];
    std::snprintf(filter, sizeof filter, "%s", m_presetFilter.c_str());
    if (ImGui::InputTextWithHint("##filter", "filter presets", filter, sizeof filter))
        m_presetFilter = filter;
    if (m_thumbnails.rendered() < m_thumbnails.total())
        ImGui::ProgressBar(float(m_thumbnails.rendered()) / float(m_thumbnails.total()),
                           ImVec2(-1, 0), "rendering thumbnails");
    std::map<std::string, std::vector<const Session*>> byModel;
    for (const Session& s : m_presets) {
        const std::string haystack = s.name + " " + s.model + " " + s.description;
        if (!m_presetFilter.empty() && haystack.find(m_presetFilter) == std::string::npos)
            continue;
        byModel[s.model].push_back(&s);
    }
    ImGui::BeginChild("presets");
    const float thumb = float(Thumbnails::kSize);
    for (const auto& [model, presets] : byModel) {
        if (!ImGui::CollapsingHeader(model.c_str(), ImGuiTreeNodeFlags_DefaultOpen))
            continue;
        for (const Session* s : presets) {
            ImGui::PushID(s->name.c_str());
            const unsigned texture = m_thumbnails.texture(s->name);
            const bool current = m_doc.isOpen() && m_doc.session().name == s->name;
            // The thumbnail and the wrapped description as one clickable row.
            ImGui::BeginGroup();
            if (texture)
                ImGui::Image(textureId(texture), ImVec2(thumb, thumb));
            else
                ImGui::Dummy(ImVec2(thumb, thumb));
            ImGui::SameLine();
            ImGui::BeginGroup();
            ImGui::TextUnformatted(s->name.c_str());
            ImGui::PushTextWrapPos(0);
            ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            if (s->surface.active())
                ImGui::Text("on a 3D model (%s)", s->surface.mesh.c_str());
            ImGui::TextUnformatted(s->description.c_str());
            ImGui::PopStyleColor();
            ImGui::PopTextWrapPos();
            ImGui::EndGroup();
            ImGui::EndGroup();
            const ImVec2 lo = ImGui::GetItemRectMin();
            const ImVec2 hi(lo.x + ImGui::GetContentRegionAvail().x, ImGui::GetItemRectMax().y);
            const bool hovered = ImGui::IsMouseHoveringRect(lo, hi) && ImGui::IsWindowHovered();
            if (current || hovered)
                ImGui::GetWindowDrawList()->AddRectFilled(
                    lo, hi, current ? IM_COL32(66, 150, 250, 60) : IM_COL32(255, 255, 255, 25));
            if (current && m_presetRevealed != s->name) {
                m_presetRevealed = s->name;
                if (!ImGui::IsRectVisible(lo, hi))
                    ImGui::SetScrollHereY(0.25f);
            }
            if (hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
                openPreset(s->name);
            ImGui::Dummy(ImVec2(0, 2));
            ImGui::PopID();
        }
    }
    ImGui::EndChild();
}

void Designer::drawHistory() {
    const auto& history = m_doc.history();
    ImGui::TextWrapped("Snapshots every %lld steps (%zu kept). Drag to look back; Branch "
                       "continues from the one shown.",
                       m_snapshotEvery, history.size());
    int every = int(m_snapshotEvery);
    if (ImGui::InputInt("every", &every, 100, 1000))
        m_snapshotEvery = std::clamp(every, 10, 1000000);
    if (history.empty()) {
        ImGui::TextDisabled("no snapshots yet");
        return;
    }
    int index = m_scrub ? int(*m_scrub) : int(history.size()) - 1;
    ImGui::SetNextItemWidth(-1);
    if (ImGui::SliderInt("##timeline", &index, 0, int(history.size()) - 1, "")) {
        m_scrub = std::size_t(index);
        m_playing = false;
    }
    ImGui::Text("step %lld", history.step(std::size_t(index)));
    ImGui::BeginDisabled(!m_scrub);
    if (ImGui::Button("Branch from here")) {
        guarded("branch", [&] { m_doc.branch(*m_scrub); });
        m_scrub.reset();
    }
    ImGui::SameLine();
    if (ImGui::Button("Back to live"))
        m_scrub.reset();
    ImGui::EndDisabled();
}

} // namespace morphogen::ui
