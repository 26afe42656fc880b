// Keyboard shortcuts of the UI layer. Camera flying (RMB + WASD/QE, wheel, MMB pan) belongs to
// the app; the discrete shortcuts live here so menus, buttons and keys share one code path.
#include "ui/document_actions.h"
#include "ui/field_widgets.h"
#include "ui/panels.h"

#include <imgui.h>

namespace st::ui {
namespace {

bool pressed(int keyCode) {
    return keyCode >= 0 && keyCode < IM_ARRAYSIZE(ImGuiIO::KeysDown) && ImGui::IsKeyPressed(keyCode, false);
}

// Ctrl+Z / Ctrl+Shift+Z / Ctrl+S / Ctrl+O: not while a text field has the keyboard (it has its own undo).
void editingShortcuts(UiFrame& f, const ImGuiIO& io) {
    if (!io.KeyCtrl || io.WantTextInput || ImGui::IsAnyItemActive()) return;
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Z))) {
        if (io.KeyShift) {
            redoEdit(f);
        } else {
            undoEdit(f);
        }
    }
    if (pressed(f.state.keys.save)) saveCurrent(f);
    if (pressed(f.state.keys.open)) showOpenDialog(f.state);
}

// F, Tab, F1, H: only when no widget wants the keyboard.
void viewShortcuts(UiFrame& f, const ImGuiIO& io) {
    if (io.WantCaptureKeyboard || io.KeyCtrl || io.KeyAlt) return;
    if (pressed(f.state.keys.frame)) f.req.frameScene = true;
    // Not while File > Open is up: Tab is its completion key, even in a frame the field let go.
    if (pressed(ImGui::GetKeyIndex(ImGuiKey_Tab)) && !f.state.showOpen) f.req.swapSideView = true;
    if (pressed(f.state.keys.help)) f.state.showHelp = !f.state.showHelp;
    if (pressed(f.state.keys.hidePanels)) f.state.prefs.panelsHidden = !f.state.prefs.panelsHidden;
    // 1..6: the debug views, as View's menu items set them (issue 39 #10: no keys for them).
    if (const FieldInfo* view = findField("output.view"))
        for (int i = 0; i < int(view->enumNames.size()); ++i)
            if (pressed(f.state.keys.firstView + i)) f.edited = storeField(*view, f.s, i) || f.edited;
}

}  // namespace

void handleShortcuts(UiFrame& f) {
    const ImGuiIO& io = ImGui::GetIO();
    editingShortcuts(f, io);
    viewShortcuts(f, io);
}

}  // namespace st::ui
