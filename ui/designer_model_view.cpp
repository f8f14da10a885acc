// The designer's 3D view of a session that grows on a mesh: the pattern on
// the model with the colour map and bump mapping (the renderer of `render
// --mesh`), an orbit camera (drag to orbit, wheel to zoom, F to frame).

#include <algorithm>
#include <cmath>

#include <glad/gl.h>
#include <imgui.h>

#include "core/surface/surface_colours.hpp"
#include "core/surface/textured_surface.hpp"
#include "gl/surface_view.hpp"
#include "ui/designer_app.hpp"

namespace morphogen::ui {

namespace {

// Re-rendered this often while the pattern changes: the texture bake and the
// picture cost about as much as a few simulation frames.
constexpr double kModelRefreshSeconds = 0.25;

} // namespace

void Designer::drawModelView(float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin("Model", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    if (!m_surface || !m_doc.isOpen() || size.x < 16 || size.y < 16) {
        ImGui::End();
        return;
    }
    ImGui::InvisibleButton("model", size,
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActive() && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0)) {
        m_orbit.azimuth = std::fmod(m_orbit.azimuth - io.MouseDelta.x * 0.4, 360.0);
        m_orbit.elevation = std::clamp(m_orbit.elevation + io.MouseDelta.y * 0.4, -89.0, 89.0);
        m_modelStale = true;
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0) {
        const double current = m_orbit.distance > 0 ? m_orbit.distance : 3.0;
        m_orbit.distance = std::clamp(current * std::pow(0.9, io.MouseWheel), 1.05, 50.0);
        m_modelStale = true;
    }
    if (ImGui::IsItemHovered() && !io.WantTextInput && ImGui::IsKeyPressed('F', false)) {
        m_orbit = Orbit{};
        m_modelStale = true;
    }
    const int width = int(size.x), height = int(size.y);
    const bool resized = m_modelImage.width() != width || m_modelImage.height() != height;
    const bool due = m_playing && seconds(Clock::now() - m_lastModelRender) > kModelRefreshSeconds;
    if (resized || m_modelStale || due)
        guarded("3D view", [&] { renderModelView(width, height); });
    if (m_modelImage.width() > 0)
        ImGui::GetWindowDrawList()->AddImage(
            reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(m_modelImage.id())), origin,
            ImVec2(origin.x + size.x, origin.y + size.y));
    ImGui::SetCursorScreenPos(ImVec2(origin.x + 8, origin.y + 6));
    ImGui::TextDisabled("%s  |  drag to orbit, wheel to zoom, F to frame",
                        m_doc.session().surface.mesh.c_str());
    ImGui::End();
}

void Designer::renderModelView(int width, int height) {
    m_modelStale = false;
    m_lastModelRender = Clock::now();
    const Session& live = m_doc.live();
    const SurfaceColours c = surfaceColours(m_doc.run().state(), live, *live.atlas);
    const gl::SurfaceRenderer renderer(texturedSurface(m_surface->tiles, c.height, c.colours));
    gl::ViewOptions view;
    view.width = width;
    view.height = height;
    view.azimuth = m_orbit.azimuth;
    view.elevation = m_orbit.elevation;
    view.distance = m_orbit.distance;
    view.supersample = 1; // live: the exported screenshot supersamples
    view.background = {0.09f, 0.09f, 0.1f, 1.0f};
    const gl::SurfaceImage image = renderer.render(view);
    if (m_modelImage.width() != width || m_modelImage.height() != height)
        m_modelImage = gl::Texture2D(width, height, GL_RGBA8);
    std::vector<float> rgba(image.rgba.size());
    for (std::size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = image.rgba[i] / 255.0f;
    m_modelImage.uploadRgba(rgba);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace morphogen::ui
