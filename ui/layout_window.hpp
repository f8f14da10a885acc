#pragma once

#include <imgui.h>

namespace morphogen::ui {

// The designer's fixed layout: each area is a Dear ImGui window placed and
// sized by the frame every frame (no docking in Debian's Dear ImGui 1.86).
// A panel keeps its padding and scrolls; a view (canvas, 3D) has neither,
// and its content region is the whole area. Call ImGui::End() after.
//
// Neither draws a background: the areas tile the window, and the frame's
// clear gives the panels' colour (Designer::run). On a software rasterizer
// (llvmpipe under Xvfb) a second full-window layer cost a third of the
// frame, taken from the simulation.
inline void beginPanel(const char* name, float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoTitleBar |
                     ImGuiWindowFlags_NoBackground);
}

inline void beginView(const char* name, float x, float y, float w, float h) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::Begin(name, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollWithMouse |
                     ImGuiWindowFlags_NoBackground);
    ImGui::PopStyleVar();
}

} // namespace morphogen::ui
