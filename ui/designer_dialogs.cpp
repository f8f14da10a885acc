// The designer's dialogs: open, save as, export, keyboard help, and the
// offer to restore the autosave after a crash.

#include <algorithm>
#include <filesystem>

#include <imgui.h>

#include "core/io/image_io.hpp"
#include "ui/designer_app.hpp"

namespace morphogen::ui {

namespace {

namespace fs = std::filesystem;

// Session files in `folder`, sorted (none when it cannot be read).
std::vector<std::string> sessionFiles(const std::string& folder) {
    std::vector<std::string> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(folder.empty() ? "." : folder, ec))
        if (e.is_regular_file(ec) && e.path().extension() == ".json")
            files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

void setBuffer(char* buffer, std::size_t size, const std::string& text) {
    std::snprintf(buffer, size, "%s", text.c_str());
}

const char* kShortcuts[][2] = {
    {"Space", "play / pause"},
    {".", "single step"},
    {"R / Shift+R", "reset / reseed"},
    {"Ctrl+Z", "undo"},
    {"Ctrl+Shift+Z, Ctrl+Y", "redo"},
    {"Ctrl+O", "open a session"},
    {"Ctrl+S / Ctrl+Shift+S", "save / save as"},
    {"Ctrl+E", "export"},
    {"F", "frame the canvas"},
    {"T", "tiled 3x3 preview"},
    {"[ / ]", "brush smaller / larger"},
    {"left drag", "paint with the brush"},
    {"right or middle drag", "pan"},
    {"mouse wheel", "zoom to the cursor"},
    {"Ctrl+click a slider", "type a value"},
    {"1 / 2 / 3", "canvas and model / canvas / model (sessions on a mesh)"},
    {"left drag in the 3D view", "orbit"},
    {"F1", "this help"},
};

} // namespace

void Designer::drawPopups() {
    const std::string folder =
        m_settings.lastFolder.empty() ? fs::current_path().string() : m_settings.lastFolder;
    if (m_showOpen) {
        ImGui::OpenPopup("Open session");
        setBuffer(m_pathBuffer, sizeof m_pathBuffer, (fs::path(folder) / "").string());
        m_showOpen = false;
    }
    if (m_showSave) {
        ImGui::OpenPopup("Save session as");
        const std::string name =
            m_doc.path().empty() ? (fs::path(folder) / (m_doc.session().name + ".json")).string()
                                 : m_doc.path();
        setBuffer(m_pathBuffer, sizeof m_pathBuffer, name);
        m_showSave = false;
    }
    if (m_showExport) {
        ImGui::OpenPopup("Export");
        setBuffer(m_pathBuffer, sizeof m_pathBuffer,
                  (fs::path(folder) / (m_doc.session().name + ".png")).string());
        m_exportSize[0] = m_doc.session().width;
        m_exportSize[1] = m_doc.session().height;
        m_showExport = false;
    }
    if (m_showHelp) {
        ImGui::OpenPopup("Keyboard shortcuts");
        m_showHelp = false;
    }
    if (m_offerRestore) {
        ImGui::OpenPopup("Restore");
        m_offerRestore = false;
    }

    if (ImGui::BeginPopupModal("Open session", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::SetNextItemWidth(520);
        const bool enter = ImGui::InputText("path", m_pathBuffer, sizeof m_pathBuffer,
                                            ImGuiInputTextFlags_EnterReturnsTrue);
        ImGui::BeginChild("files", ImVec2(520, 220), true);
        for (const std::string& f : sessionFiles(fs::path(m_pathBuffer).parent_path().string()))
            if (ImGui::Selectable(fs::path(f).filename().string().c_str(), f == m_pathBuffer,
                                  ImGuiSelectableFlags_AllowDoubleClick)) {
                setBuffer(m_pathBuffer, sizeof m_pathBuffer, f);
                if (ImGui::IsMouseDoubleClicked(0)) {
                    openSessionFile(f);
                    ImGui::CloseCurrentPopup();
                }
            }
        ImGui::EndChild();
        if (ImGui::Button("Open") || enter) {
            openSessionFile(m_pathBuffer);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (ImGui::BeginPopupModal("Save session as", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextDisabled("The session reproduces the canvas with morphogen render --session.");
        ImGui::SetNextItemWidth(520);
        const bool enter = ImGui::InputText("path", m_pathBuffer, sizeof m_pathBuffer,
                                            ImGuiInputTextFlags_EnterReturnsTrue);
        if (ImGui::Button("Save") || enter) {
            saveSession(m_pathBuffer);
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (ImGui::BeginPopupModal("Export", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextDisabled(".png / .tif: colour-mapped; .exr: raw concentrations. The session "
                            "is written next to it.");
        ImGui::SetNextItemWidth(520);
        ImGui::InputText("file", m_pathBuffer, sizeof m_pathBuffer);
        ImGui::InputInt2("size", m_exportSize);
        ImGui::RadioButton("8-bit", &m_exportBits, 8);
        ImGui::SameLine();
        ImGui::RadioButton("16-bit", &m_exportBits, 16);
        const bool canvasSize =
            m_exportSize[0] == m_doc.session().width && m_exportSize[1] == m_doc.session().height;
        if (ImGui::Button(canvasSize ? "Export the canvas" : "Render and export at this size")) {
            if (canvasSize)
                exportImage(m_pathBuffer, m_exportBits);
            else
                exportAtSize(m_pathBuffer, m_exportSize[0], m_exportSize[1], m_exportBits);
            ImGui::CloseCurrentPopup();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("A larger size re-runs the session from its start with every "
                              "stroke and change, in the background: the same pattern with "
                              "more detail.");
        ImGui::SameLine();
        if (ImGui::Button("Texture set (height, normal, mask)")) {
            exportTextureSet(fs::path(m_pathBuffer).replace_extension("").string() + "_maps");
            ImGui::CloseCurrentPopup();
        }
        if (m_surface) {
            if (ImGui::Button("Model (GLB)")) {
                exportModel(fs::path(m_pathBuffer).replace_extension(".glb").string());
                ImGui::CloseCurrentPopup();
            }
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("The model re-textured with the pattern: base colour and "
                                  "normal map, as render --mesh ... --out model.glb");
            ImGui::SameLine();
        }
        ImGui::SetNextItemWidth(80);
        ImGui::InputInt("steps per frame", &m_recordEvery);
        ImGui::SameLine();
        if (ImGui::Button(m_recordDir.empty() ? "Record growth frames" : "Stop recording")) {
            recordFrames(m_recordDir.empty()
                             ? fs::path(m_pathBuffer).replace_extension("").string() + "_frames"
                             : "",
                         m_recordEvery);
            ImGui::CloseCurrentPopup();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("While the pattern grows, a numbered PNG every N steps in a folder "
                              "next to the file (ffmpeg or render --frames make a video)");
        ImGui::SameLine();
        if (ImGui::Button("Cancel"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (ImGui::BeginPopupModal("Keyboard shortcuts", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
            for (const auto& row : kShortcuts) {
                ImGui::TableNextRow();
                ImGui::TableSetColumnIndex(0);
                ImGui::TextUnformatted(row[0]);
                ImGui::TableSetColumnIndex(1);
                ImGui::TextUnformatted(row[1]);
            }
            ImGui::EndTable();
        }
        if (ImGui::Button("Close"))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }

    if (ImGui::BeginPopupModal("Restore", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        if (m_recovered.empty()) {
            ImGui::CloseCurrentPopup();
        } else {
            ImGui::Text("The designer did not exit cleanly last time.");
            ImGui::Text("Its unsaved work is kept in %s.", m_recovered.front().c_str());
            if (m_recovered.size() > 1)
                ImGui::Text("(%zu more crashed sessions are kept in that folder.)",
                            m_recovered.size() - 1);
            if (ImGui::Button("Restore it")) {
                restoreAutosave();
                ImGui::CloseCurrentPopup();
            }
            ImGui::SameLine();
            if (ImGui::Button("Discard")) {
                discardRecovered();
                ImGui::CloseCurrentPopup();
            }
            ImGui::SameLine();
            if (ImGui::Button("Later"))
                ImGui::CloseCurrentPopup(); // kept, and offered again at the next start
        }
        ImGui::EndPopup();
    }
    // After the restore offer (one modal at a time); a script's run shows
    // the notice in the status line only, so no dialog takes its input.
    if (!m_startupNotice.empty() && m_options.script.empty() && !ImGui::IsPopupOpen("Restore")) {
        ImGui::OpenPopup("Could not reopen");
        if (ImGui::BeginPopupModal("Could not reopen", nullptr,
                                   ImGuiWindowFlags_AlwaysAutoResize)) {
            ImGui::PushTextWrapPos(ImGui::GetFontSize() * 40);
            ImGui::TextUnformatted(m_startupNotice.c_str());
            ImGui::PopTextWrapPos();
            if (ImGui::Button("OK")) {
                m_startupNotice.clear();
                ImGui::CloseCurrentPopup();
            }
            ImGui::EndPopup();
        }
    }
}

} // namespace morphogen::ui
