// The designer's 3D view of a session that grows on a mesh: the pattern on
// the model with the colour map and bump mapping (the renderer of `render
// --mesh`), an orbit camera (right drag orbits, the wheel zooms, F frames),
// and the brush on the surface (left drag: the stroke goes through the atlas
// across tile seams, recorded as a surface stroke of the session).

#include <algorithm>
#include <array>
#include <cmath>

#include <glad/gl.h>
#include <imgui.h>

#include "core/surface/mesh_surface.hpp"
#include "core/surface/surface_colours.hpp"
#include "core/surface/textured_surface.hpp"
#include "gl/surface_view.hpp"
#include "ui/designer_app.hpp"
#include "ui/layout_window.hpp"

namespace morphogen::ui {

namespace {

// Re-rendered this often while the pattern changes: the texture bake and the
// picture cost about as much as a few simulation frames.
constexpr double kModelRefreshSeconds = 0.25;

} // namespace

void Designer::drawModelView(float x, float y, float w, float h) {
    beginView("Model", x, y, w, h);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    m_modelRect = {origin.x, origin.y, size.x, size.y};
    syncSurface();
    if (!m_surface || !m_doc.isOpen() || size.x < 16 || size.y < 16) {
        ImGui::End();
        return;
    }
    ImGui::InvisibleButton("model", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                               ImGuiButtonFlags_MouseButtonMiddle);
    const ImGuiIO& io = ImGui::GetIO();
    const bool hovered = ImGui::IsItemHovered();
    // Right or middle drag orbits; the left button paints on the model.
    if (ImGui::IsItemActive() && !ImGui::IsMouseDown(ImGuiMouseButton_Left) &&
        (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        m_orbit.azimuth = std::fmod(m_orbit.azimuth - io.MouseDelta.x * 0.4, 360.0);
        m_orbit.elevation = std::clamp(m_orbit.elevation + io.MouseDelta.y * 0.4, -89.0, 89.0);
        m_modelStale = true;
    }
    if (hovered && io.MouseWheel != 0) {
        const double current = m_orbit.distance > 0 ? m_orbit.distance : 3.0;
        m_orbit.distance = std::clamp(current * std::pow(0.9, io.MouseWheel), 1.05, 50.0);
        m_modelStale = true;
    }
    if (hovered && !io.WantTextInput && ImGui::IsKeyPressed('F', false)) {
        m_orbit = Orbit{};
        m_modelStale = true;
    }
    // The point under the cursor, in the last picture's camera (its pixels
    // are the view's: the picture fills the view).
    std::optional<Eigen::Vector3f> hit;
    if ((hovered || m_doc.stroking()) && m_modelImage.width() > 0)
        hit = gl::pickSurface(m_surface->mesh.mesh, m_modelBounds, m_modelView,
                              io.MousePos.x - origin.x, io.MousePos.y - origin.y);
    const double worldRadius = m_brush.radius * 2.0 * m_modelBounds.radius;
    if (m_brush.deform) {
        deformDrag(hit, worldRadius);
    } else if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && hit &&
               !m_scrub) {
        StrokeSpec stroke = strokeFromBrush();
        std::optional<StrokeSpec> companion = companionFromBrush();
        ++m_brush.seed;
        stroke.surface = true;
        stroke.localized = m_brush.localized;
        stroke.radius = worldRadius;
        if (companion) {
            companion->surface = true;
            companion->localized = stroke.localized;
            companion->radius = worldRadius;
        }
        guarded("brush", [&] {
            m_doc.beginStroke(stroke, companion);
            m_doc.extendSurfaceStroke({{hit->x(), hit->y(), hit->z()}});
        });
        m_modelStale = true;
    } else if (m_doc.stroking() && ImGui::IsMouseDown(ImGuiMouseButton_Left) && hit &&
               (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        guarded("brush", [&] { m_doc.extendSurfaceStroke({{hit->x(), hit->y(), hit->z()}}); });
        m_modelStale = true;
    }
    if (m_doc.stroking() && !ImGui::IsMouseDown(ImGuiMouseButton_Left))
        guarded("brush", [&] { m_doc.endStroke(); });
    const int width = int(size.x), height = int(size.y);
    const bool resized = m_modelImage.width() != width || m_modelImage.height() != height;
    const bool due = m_playing && seconds(Clock::now() - m_lastModelRender) > kModelRefreshSeconds;
    if (resized || m_modelStale || due)
        guarded("3D view", [&] { renderModelView(width, height); });
    if (m_modelImage.width() > 0)
        ImGui::GetWindowDrawList()->AddImage(
            reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(m_modelImage.id())), origin,
            ImVec2(origin.x + size.x, origin.y + size.y));
    // The brush outline: a circle of the brush's radius at the point's depth
    // (its size on screen from the camera's field of view and distance).
    if (hit) {
        const double distance =
            (m_modelView.distance > 0 ? m_modelView.distance : 3.0) * m_modelBounds.radius;
        const double pixelsPerUnit =
            size.y / (2.0 * distance * std::tan(m_modelView.fieldOfView * M_PI / 360.0));
        const float r = float(worldRadius * pixelsPerUnit);
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddCircle(io.MousePos, r, IM_COL32(0, 0, 0, 160), 48, 3.0f);
        draw->AddCircle(io.MousePos, r, IM_COL32(255, 255, 255, 200), 48, 1.5f);
    }
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 6));
    // Kept inside the view (half a 1600-pixel window cut it off), and wrapped
    // phrase by phrase: wrapped at spaces, "F frames" broke into "F" and "frames".
    ImGui::PushTextWrapPos(0.0f);
    const std::string& mesh = m_doc.session().surface.mesh;
    const std::array<const char*, 4> hints = {"left drag paints", "right drag orbits",
                                              "wheel zooms", "F frames"};
    ImGui::TextDisabled("%s", mesh.c_str());
    const float right = origin.x + size.x - 8;
    for (const char* hint : hints) {
        const float width = ImGui::CalcTextSize(hint).x + ImGui::CalcTextSize("  |  ").x;
        ImGui::SameLine();
        if (ImGui::GetCursorScreenPos().x + width > right) {
            ImGui::NewLine();
            ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, ImGui::GetCursorScreenPos().y));
        } else {
            ImGui::TextDisabled(" | ");
            ImGui::SameLine();
        }
        ImGui::TextDisabled("%s", hint);
    }
    ImGui::PopTextWrapPos();
    ImGui::End();
}

void Designer::syncSurface() {
    if (!m_surface || !m_doc.isOpen() || m_doc.live().surfaceGeometry == m_shownGeometry)
        return;
    m_shownGeometry = m_doc.live().surfaceGeometry;
    if (auto mesh = std::dynamic_pointer_cast<const MeshSurface>(m_shownGeometry)) {
        m_surface = mesh->setup();
        m_modelStale = true;
    }
}

void Designer::deformDrag(const std::optional<Eigen::Vector3f>& hit, double worldRadius) {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && hit &&
        !m_scrub) {
        m_deformFrom = hit;
        m_deformStartScreen = {io.MousePos.x, io.MousePos.y};
    }
    if (!m_deformFrom)
        return;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (hit)
            m_deformTo = hit;
        // The drag as a line from where it started.
        ImGui::GetWindowDrawList()->AddLine(ImVec2(m_deformStartScreen[0], m_deformStartScreen[1]),
                                            io.MousePos, IM_COL32(255, 180, 60, 220), 2.0f);
        return;
    }
    // Released: the slab at the start, along the drag.
    const Eigen::Vector3f from = *m_deformFrom;
    const std::optional<Eigen::Vector3f> to = m_deformTo;
    m_deformFrom.reset();
    m_deformTo.reset();
    if (!to || (*to - from).norm() < 1e-3f * float(m_modelBounds.radius)) {
        m_status = "deform: drag along the model to give the direction";
        return;
    }
    const Eigen::Vector3f direction = (*to - from).normalized();
    DeformSpec spec;
    spec.centre = {from.x(), from.y(), from.z()};
    spec.direction = {direction.x(), direction.y(), direction.z()};
    spec.radius = worldRadius;
    spec.factor = m_brush.stretch;
    spec.reach = m_brush.across ? 0.0 : worldRadius;
    guarded("deform", [&] {
        m_doc.deform(spec);
        m_status = "deformed: stretched by " + std::to_string(m_brush.stretch).substr(0, 4) +
                   "; the pattern re-grows there";
    });
    m_modelStale = true;
}

void Designer::tintActiveTiles(std::vector<std::array<std::uint8_t, 4>>& colours,
                               const Atlas& atlas) const {
    const LocalRegrowth* regrowth = m_doc.run().regrowth();
    if (!regrowth)
        return;
    // Lo's Fig. 4: the active tiles washed towards orange, the pattern still readable.
    const std::array<int, 3> tint = {255, 140, 30};
    for (int t : regrowth->tiles())
        for (int v = 0; v < atlas.tileSize(); ++v)
            for (int u = 0; u < atlas.tileSize(); ++u) {
                std::array<std::uint8_t, 4>& c = colours[atlas.tileCell(t, u, v)];
                for (std::size_t k = 0; k < 3; ++k)
                    c[k] = std::uint8_t((c[k] * 3 + tint[k] * 2) / 5);
            }
}

void Designer::renderModelView(int width, int height) {
    m_modelStale = false;
    m_lastModelRender = Clock::now();
    const Session& live = m_doc.live();
    Session shown = live;
    shown.colormap = m_doc.liveColormap();
    // The atlas's own texels (scale 1): redrawn as the pattern grows, where
    // the exports map at a finer scale.
    SurfaceLook look;
    look.scale = 1;
    SurfaceColours c = surfaceColours(m_doc.run().state(), shown, *live.atlas, {}, look);
    if (m_showActiveTiles)
        tintActiveTiles(c.colours, *live.atlas);
    // The mesh and program stay; only the pattern's textures change.
    const TexturedMesh textured = texturedSurface(m_surface->tiles, c, look);
    if (!m_modelRenderer || m_modelRendererFor != m_surface) {
        m_modelRenderer = std::make_unique<gl::SurfaceRenderer>(textured);
        m_modelRendererFor = m_surface;
    } else {
        m_modelRenderer->setTextures(textured);
    }
    const gl::SurfaceRenderer& renderer = *m_modelRenderer;
    gl::ViewOptions view;
    view.width = width;
    view.height = height;
    view.azimuth = m_orbit.azimuth;
    view.elevation = m_orbit.elevation;
    view.distance = m_orbit.distance;
    view.supersample = 1; // live: the exported screenshot supersamples
    view.background = {0.09f, 0.09f, 0.1f, 1.0f};
    const gl::SurfaceImage image = renderer.render(view);
    m_modelView = view;
    m_modelBounds = renderer.bounds();
    if (m_modelImage.width() != width || m_modelImage.height() != height)
        m_modelImage = gl::Texture2D(width, height, GL_RGBA8);
    std::vector<float> rgba(image.rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = image.rgba[i] / 255.0f;
    m_modelImage.uploadRgba(rgba);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace morphogen::ui
