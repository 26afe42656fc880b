#pragma once
// Everything EditorUi remembers between frames (no static-local UI state, so a run can be
// replayed: docs/architecture.md#no-static-local-ui-state), and the per-frame bundle the
// panels draw from. Internal to ui/.
#include "renderer/settings/validation.h"
#include "ui/compare_state.h"
#include "ui/document.h"
#include "ui/engine_state.h"
#include "ui/editor_ui.h"
#include "ui/field_widgets.h"
#include "ui/history.h"
#include "ui/layout.h"
#include "ui/tune_state.h"
#include "ui/map_cost.h"
#include "ui/undo_stack.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace st::ui {

// An action that would discard unsaved changes, held while the confirmation modal is open.
struct PendingDiscard {
    enum class Kind { None, Load, Quit };
    Kind kind = Kind::None;
    std::filesystem::path file;  // for Load
};

struct UiState {
    std::filesystem::path presetDir;
    ShortcutKeys keys;
    Document doc;
    UndoStack undo;
    std::optional<Settings> gestureStart;  // settings before the widget edit in progress
    bool dirty = false;                    // as of the end of the last draw()

    bool animateSun = false;               // UI state, not Settings: advances light.azimuth
    float sunDegPerSecond = 10.0f;
    float sunPreviewFrom = 0.0f;           // light.azimuth when the animation started: restored at stop
    TimingHistory timing;

    bool showShadowMaps = true;
    bool showSideView = true;
    bool showHelp = false;
    ImVec2 probeTooltipSize{0.0f, 0.0f};  // as last drawn: where it goes is decided before it is drawn
    bool showAccuracy = true;              // the Accuracy panel; closed, no ground truth is computed
    // Its error overlay over the scene view. Off until the panel's toggle (issue 39 #3): drawn by
    // default it covered the scene with colours a new user took for part of the picture.
    bool errorOverlay = false;
    int zoomLayer = -1;                    // cascade shown in the zoom window; -1: closed

    std::string saveAsText;                // the "Save as" path field
    bool showOpen = false;                 // File > Open's window
    bool focusOpenPath = false;            // ... put the cursor in its path field this frame
    bool selectOpenPath = false;           // ... with its text selected, so typing replaces the last path
    std::string openText;                  // its path field
    std::string openCandidatesFor;         // the text openCandidates were listed for
    std::vector<std::string> openCandidates;
    bool openCandidatesKnown = false;
    std::string gltfText;                  // the scene's glTF path field
    std::string gltfTextFor;               // the scene value gltfText was last synced from
    std::string sceneError;                // why the scene last chosen did not load (shown in red)
    std::string sceneErrorFor;             // ... the value refused; the message goes when the field changes

    PendingDiscard pending;
    bool openConfirm = false;              // open the confirmation modal this frame
    bool quitConfirmed = false;            // draw() returns quit
    MapCostAsk mapAsk;                     // an expensive map-size change held while the editor asks

    LayoutPrefs prefs;                     // column widths, hidden panels: kept by the app across runs
    Layout layout;                         // this frame's panel and scene rectangles (beginFrame)
    CompareUiState compare;                // A/B split and Sweep panel (ab_split.cpp, sweep_panel.cpp)
    TuneUiState tune;                      // the Tune panel (tune_panel.cpp)
    EngineUiState engine;                  // the Engine section of the Settings panel (engine_section.cpp)

    std::vector<SettingsIssue> issues;     // validate() of this frame's settings, before widgets
    FieldEdits fieldEdits;                 // numbers being typed, and typed numbers refused
    ItemRects rects;
};

// One draw() call: the state, the settings being edited and what is reported back.
struct UiFrame {
    UiState& state;
    Settings& s;
    const UiInputs& in;
    UiRequests& req;
    bool edited = false;                   // a widget changed `s` this frame (an undo gesture)
    bool replaced = false;                 // undo/redo/load replaced `s` wholesale this frame
};

}  // namespace st::ui
