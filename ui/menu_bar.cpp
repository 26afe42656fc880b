// The main menu bar: the same actions as the shortcuts and panel buttons, discoverable.
#include "ui/document_actions.h"
#include "ui/panels.h"

#include <imgui.h>

namespace st::ui {
namespace {

void fileMenu(UiFrame& f) {
    if (!ImGui::BeginMenu("File")) return;
    if (ImGui::MenuItem("Save", "Ctrl+S")) saveCurrent(f);
    if (ImGui::MenuItem("Quit")) requestQuitFrom(f.state, isDirty(f.state.doc, f.s));
    ImGui::EndMenu();
}

void editMenu(UiFrame& f) {
    if (!ImGui::BeginMenu("Edit")) return;
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, f.state.undo.canUndo())) undoEdit(f);
    if (ImGui::MenuItem("Redo", "Ctrl+Shift+Z", false, f.state.undo.canRedo())) redoEdit(f);
    ImGui::EndMenu();
}

void viewMenu(UiFrame& f) {
    const bool open = ImGui::BeginMenu("View");
    recordItem(f.state.rects, "menu.view");
    if (!open) return;
    if (ImGui::MenuItem("Frame scene", "F")) f.req.frameScene = true;
    if (ImGui::MenuItem("Swap side view", "Tab")) f.req.swapSideView = true;
    ImGui::Separator();
    ImGui::MenuItem("Hide panels", "H", &f.state.prefs.panelsHidden);
    recordItem(f.state.rects, "menu.hidePanels");
    ImGui::MenuItem("Shadow maps", nullptr, &f.state.showShadowMaps);
    ImGui::MenuItem("Side view", nullptr, &f.state.showSideView);
    ImGui::MenuItem("Accuracy", nullptr, &f.state.showAccuracy);
    ImGui::MenuItem("Help", "F1", &f.state.showHelp);
    ImGui::EndMenu();
}

}  // namespace

void drawMenuBar(UiFrame& f) {
    if (!ImGui::BeginMainMenuBar()) return;
    fileMenu(f);
    editMenu(f);
    viewMenu(f);
    ImGui::EndMainMenuBar();
}

}  // namespace st::ui
