#pragma once
// Where each panel starts: fixed side windows relative to the display (Debian's ImGui 1.86 is
// built without docking). Positions apply on first use only, so imgui.ini keeps what the user
// arranged between runs.
namespace st::ui {

enum class Panel { Settings, Presets, ShadowMaps, SideView, Accuracy, ShadowZoom, Help, Confirm };

// Calls SetNextWindowPos/Size for `panel`; call right before its ImGui::Begin.
void placeNextWindow(Panel panel);

}  // namespace st::ui
