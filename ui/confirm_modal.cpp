// The modal asked before an action would discard unsaved changes (loading another preset, quit).
#include "ui/document_actions.h"
#include "ui/layout.h"
#include "ui/panels.h"

#include <imgui.h>

namespace st::ui {
namespace {

constexpr const char* kTitle = "Unsaved changes";

std::string actionText(const PendingDiscard& pending) {
    if (pending.kind == PendingDiscard::Kind::Quit) return "Quit without saving?";
    return "Load " + pending.file.filename().string() + " and discard the unsaved changes?";
}

bool modalButton(UiFrame& f, const char* label, const char* key) {
    const bool pressed = ImGui::Button(label, ImVec2(110.0f, 0.0f));
    recordItem(f.state.rects, key);
    return pressed;
}

void drawChoices(UiFrame& f) {
    const bool canSave = !f.state.doc.file.empty();
    if (canSave && modalButton(f, "Save first", "confirm.save")) {
        saveCurrent(f);
        if (f.state.doc.errors.empty()) {
            runPendingDiscard(f);
        } else {
            f.state.pending = {};  // the save failed: nothing is discarded, the errors are shown
        }
        ImGui::CloseCurrentPopup();
    }
    if (canSave) ImGui::SameLine();
    if (modalButton(f, "Discard", "confirm.discard")) {
        runPendingDiscard(f);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (modalButton(f, "Cancel", "confirm.cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        f.state.pending = {};
        ImGui::CloseCurrentPopup();
    }
}

}  // namespace

void drawConfirmDiscard(UiFrame& f) {
    if (f.state.openConfirm) {
        ImGui::OpenPopup(kTitle);
        f.state.openConfirm = false;
    }
    placeNextWindow(Panel::Confirm);
    if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    ImGui::TextUnformatted(f.state.doc.file.empty() ? "The untitled settings have unsaved changes."
                                                    : (f.state.doc.file.filename().string() +
                                                       " has unsaved changes.").c_str());
    ImGui::TextUnformatted(actionText(f.state.pending).c_str());
    ImGui::Spacing();
    drawChoices(f);
    ImGui::EndPopup();
}

}  // namespace st::ui
