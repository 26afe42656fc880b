// File > Open: a path field (relative paths start in the preset folder, as in "Save as") with
// the presets, glTF scenes and folders that continue it listed below; Tab completes the common part.
#include "ui/document_actions.h"
#include "ui/panels.h"
#include "ui/path_completion.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace st::ui {
namespace {

constexpr std::size_t kMaxShown = 12;

int completeOnTab(ImGuiInputTextCallbackData* data) {
    const auto& state = *static_cast<const UiState*>(data->UserData);
    const std::string typed(data->Buf, static_cast<std::size_t>(data->BufTextLen));
    const std::string common = commonPrefix(completePresetPath(state.presetDir, typed));
    if (common.size() > typed.size()) {
        data->DeleteChars(0, data->BufTextLen);
        data->InsertChars(0, common.c_str());
    }
    return 0;
}

const std::vector<std::string>& candidatesFor(UiState& state) {
    if (state.openText != state.openCandidatesFor || !state.openCandidatesKnown) {
        state.openCandidates = completePresetPath(state.presetDir, state.openText);
        state.openCandidatesFor = state.openText;
        state.openCandidatesKnown = true;
    }
    return state.openCandidates;
}

void open(UiFrame& f) {
    if (f.state.openText.empty()) return;
    requestLoad(f, resolveSavePath(f.state.presetDir, f.state.openText));
    // Loaded, or waiting for the unsaved-changes question: the window has done its part. A failed
    // load keeps it open, with the reason below the field and the cursor back in the field
    // (Enter let it go), so the path can be corrected and Tab completes instead of swapping views.
    if (f.req.presetLoaded || f.state.openConfirm) f.state.showOpen = false;
    else f.state.focusOpenPath = true;
}

void drawCandidates(UiFrame& f) {
    const std::vector<std::string> candidates = candidatesFor(f.state);  // a click changes the text
    for (std::size_t i = 0; i < candidates.size() && i < kMaxShown; ++i) {
        const std::string& c = candidates[i];
        if (ImGui::Selectable(c.c_str())) {
            f.state.openText = c;
            f.state.focusOpenPath = true;
            if (!c.ends_with('/')) open(f);
        }
        recordItem(f.state.rects, "open:" + c);
    }
    if (candidates.size() > kMaxShown) ImGui::TextDisabled("... %zu more", candidates.size() - kMaxShown);
    if (candidates.empty()) ImGui::TextDisabled("(no preset, glTF scene or folder starts so)");
}

void drawErrors(const UiFrame& f) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    for (const std::string& e : f.state.doc.errors) ImGui::TextWrapped("%s", e.c_str());
    ImGui::PopStyleColor();
}

}  // namespace

void showOpenDialog(UiState& state) {
    state.showOpen = true;
    state.focusOpenPath = true;
    state.selectOpenPath = true;  // the last path is offered, and typing replaces it (issue 21 #7)
    state.openCandidatesKnown = false;  // the folder may have changed since
}

void drawOpenDialog(UiFrame& f) {
    if (!f.state.showOpen) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.3f), ImGuiCond_Appearing, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(520.0f, 0.0f), ImGuiCond_Appearing);
    if (ImGui::Begin("Open preset", &f.state.showOpen, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::TextDisabled("A preset (.json) or a glTF scene (.gltf, .glb: a new preset for it), relative to %s/; Tab completes, Enter opens.", f.state.presetDir.string().c_str());
        if (f.state.focusOpenPath) {  // until it takes: a new window may skip a frame
            ImGui::SetWindowFocus();
            ImGui::SetKeyboardFocusHere();
        }
        ImGui::SetNextItemWidth(-70.0f);
        const bool entered = ImGui::InputTextWithHint(
            "##openPath", "scenes/fox.json", &f.state.openText,
            ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CallbackCompletion |
                (f.state.selectOpenPath ? ImGuiInputTextFlags_AutoSelectAll : 0),
            completeOnTab, &f.state);
        recordItem(f.state.rects, "open.path");
        if (ImGui::IsItemActive()) f.state.focusOpenPath = f.state.selectOpenPath = false;
        ImGui::SameLine();
        const bool pressed = ImGui::Button("Open");
        recordItem(f.state.rects, "open.open");
        if (entered || pressed) open(f);
        if (f.state.showOpen) {
            drawErrors(f);
            ImGui::Separator();
            drawCandidates(f);
        }
    }
    ImGui::End();
}

}  // namespace st::ui
