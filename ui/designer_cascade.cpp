// The designer's cascade editor (Turk's stages): the current session's stage
// list, each stage's steps and its whole description as JSON (model switch,
// start, dt, parameters, freeze rule, reset), add, remove, and the stage
// running now. An edit restarts the run from the edited session (a saved
// session reproduces a run only from its start): undoable as any restart.

#include <algorithm>

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "ui/designer_app.hpp"

namespace morphogen::ui {

namespace {

using nlohmann::json;

// The stages of `base` replaced by `stages` (the steps total follows), read
// back through the session reader so every rule a file obeys holds.
Session withStages(const Session& base, const json& stages) {
    json j = sessionToJson(base);
    if (stages.empty()) {
        j.erase("stages");
        long long total = 0;
        for (const Stage& s : base.stages)
            total += s.steps;
        j["steps"] = total > 0 ? total : base.steps;
    } else {
        j["stages"] = stages;
        long long total = 0;
        for (const json& s : stages)
            total += s.value("steps", 0LL);
        j["steps"] = total;
    }
    j.erase("edits"); // a restart: the edits belonged to the old run
    Session s = sessionFromJson(j, "the cascade editor");
    s.baseDir = base.baseDir;
    validateSession(s, "the cascade editor");
    return s;
}

} // namespace

void Designer::drawCascadeSection() {
    const Session base = m_doc.session(); // a copy: an edit replaces it
    const RunPosition at = m_doc.run().position();
    json stages = base.stages.empty() ? json::array() : stagesToJson(base.stages);
    std::optional<json> change;
    if (stages.empty())
        ImGui::TextWrapped("One stage: the whole run. Add a stage to grow a cascade (Turk's "
                           "giraffe: spots, then frozen spots with stripes round them).");
    for (std::size_t i = 0; i < stages.size(); ++i) {
        ImGui::PushID(int(i));
        json& stage = stages[i];
        const bool current = at.stages && int(i) == at.segment;
        ImGui::TextColored(
            current ? ImVec4(1, 0.85f, 0.4f, 1) : ImVec4(0.8f, 0.8f, 0.8f, 1), "%s stage %zu%s%s",
            current ? ">" : " ", i + 1,
            stage.contains("model") ? (": " + stage["model"].get<std::string>()).c_str() : "",
            stage.contains("freeze") ? ", freezes" : "");
        int steps = stage.value("steps", 0);
        ImGui::SetNextItemWidth(110);
        ImGui::InputInt("steps", &steps, 100, 1000);
        if (ImGui::IsItemDeactivatedAfterEdit()) {
            stage["steps"] = std::max(0, steps);
            change = stages;
        }
        ImGui::SameLine();
        if (ImGui::SmallButton("remove")) {
            json rest = json::array();
            for (std::size_t k = 0; k < stages.size(); ++k)
                if (k != i)
                    rest.push_back(stages[k]);
            change = rest;
        }
        if (ImGui::TreeNode("as JSON")) {
            // The whole stage, for what the quick controls do not cover.
            std::string& text = m_stageText[i];
            if (text.empty())
                text = stage.dump(1);
            char buffer[8192];
            std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
            if (ImGui::InputTextMultiline("##json", buffer, sizeof buffer, ImVec2(-1, 140)))
                text = buffer;
            if (ImGui::SmallButton("apply")) {
                try {
                    stage = json::parse(text);
                    change = stages;
                } catch (const std::exception& e) {
                    reportError(std::string("stage ") + std::to_string(i + 1) +
                                " is not JSON: " + e.what());
                }
            }
            ImGui::SameLine();
            if (ImGui::SmallButton("revert"))
                text.clear();
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (ImGui::Button("Add stage")) {
        json next = stages.empty() ? json::array({{{"steps", base.steps}}}) : stages;
        next.push_back({{"steps", 1000}});
        change = next;
    }
    if (change)
        guarded("cascade", [&] {
            Session s = withStages(base, *change);
            m_stageText.clear();
            m_doc.replace(std::move(s), "edit cascade");
        });
}

} // namespace morphogen::ui
