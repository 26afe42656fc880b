#pragma once
// The panels EditorUi::draw() calls, one file each. Each takes the frame bundle, reads
// UiInputs, edits Settings only through the field table and reports through UiRequests.
#include "ui/ui_state.h"

#include <string_view>
#include <vector>

namespace st::ui {

void drawMenuBar(UiFrame& f);         // menu_bar.cpp: File / Edit / View
void handleShortcuts(UiFrame& f);     // shortcuts.cpp: Ctrl+Z, Ctrl+Shift+Z, Ctrl+S, F, Tab, F1
void drawSettingsPanel(UiFrame& f);   // settings_panel.cpp: every field, grouped, with issues
void drawEngineSection(UiFrame& f);   // engine_section.cpp: Engine choice, its knobs, lacks, paste-ready text
std::vector<xport::Engine> engineChoices();  // engine_section.cpp: the engines the Engine choice offers
// engine_section.cpp: whether the chosen engine has no knob for the field at `path` (greyed then).
bool engineLacksField(const UiFrame& f, std::string_view path);
void drawPresetsPanel(UiFrame& f);    // presets_panel.cpp: list, save, save as, undo, messages
void drawShadowViewer(UiFrame& f);    // shadow_viewer.cpp: a tile per cascade, zoom on click
void drawSideView(UiFrame& f);        // side_view.cpp: picture-in-picture with orbit input
void drawHelpWindow(UiFrame& f);      // help_window.cpp: shortcuts (F1)
void drawAccuracyPanel(UiFrame& f);   // accuracy_panel.cpp: ground-truth figures, overlay toggle
void drawConfirmDiscard(UiFrame& f);  // confirm_modal.cpp: "discard unsaved changes?"
void drawSunAnimation(UiFrame& f);    // sun_preview.cpp: "animate sun", a preview undone when stopped
void drawOpenDialog(UiFrame& f);      // open_dialog.cpp: File > Open, a path with completion
void showOpenDialog(UiState& state);  // open_dialog.cpp: opens it, the cursor in the path
void drawSplitBar(UiFrame& f);        // split_bar.cpp: cascade ranges under the scene, draggable splits
void drawStatusBar(UiFrame& f);       // status_bar.cpp: frame rate, scene viewport size
void drawSceneLegends(UiFrame& f);    // legends.cpp: colour keys over the scene viewport's corner
void drawCompare(UiFrame& f);         // ab_split.cpp: Compare menu, Set as A, split divider; sweep_panel.cpp
void drawSweepPanel(UiFrame& f);      // sweep_panel.cpp (called by drawCompare)
void drawTunePanel(UiFrame& f);       // tune_panel.cpp (called by drawCompare): budget, objective, Go, front, apply
void setAsA(UiFrame& f);              // ab_split.cpp: snapshot the settings as A, split on
void toggleSplit(UiFrame& f);         // ab_split.cpp: split on/off (A = now if none yet)

}  // namespace st::ui
