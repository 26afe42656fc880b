#pragma once
// The editor's Dear ImGui layer: the entry points the app calls each frame.
//
// The app owns the ImGui context and the platform/renderer backends (GLFW + OpenGL3); ui/ never
// calls GL or GLFW. Each frame:
//
//     ImGui_ImplOpenGL3_NewFrame(); ImGui_ImplGlfw_NewFrame(); ImGui::NewFrame();
//     UiRequests r = ui.draw(settings, inputs);   // edits `settings` in place
//     ... render the scene with `settings` ...
//     if (r.errorOverlay && the overlay describes that frame) drawErrorOverlay(overlay);
//     ImGui::Render(); ImGui_ImplOpenGL3_RenderDrawData(...)
//     if (r.change != ChangeClass::None && r.settingsValid) apply it (r.change says how much to redo)
//
// Every widget comes from the settings field table and writes through FieldInfo::set, clamped to
// the field's range; cross-field problems (validate()) are shown in red, never thrown. Presets
// are loaded and saved here (atomically); the app only lists the files and reacts to requests.
#include "renderer/export/engine_export.h"
#include "renderer/render/frame_stats.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"
#include "ui/accuracy_view.h"
#include "ui/compare_view.h"
#include "ui/item_rects.h"
#include "ui/layout.h"
#include "ui/memory_view.h"
#include "ui/probe.h"
#include "ui/split_bar.h"
#include "ui/status_bar.h"
#include "ui/tune_view.h"

#include <imgui.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace st::ui {

struct UiState;

// View > Motion (issue 21 #3): what the menu shows of the app's motion state, and what it asks.
struct MotionView {
    bool fullQuality = false;     // Full quality while moving is on
    bool previewOn = false;       // Preview path is rendering or playing
    bool flickerOverlay = false;  // its per-pixel flicker map is shown
};
struct MotionRequests {
    bool toggleFullQuality = false;
    bool previewStart = false;
    bool previewStop = false;
    bool toggleFlickerOverlay = false;
};

// What the app shows the UI this frame. Nothing here is written back.
struct UiInputs {
    const FrameStats* stats = nullptr;       // the last rendered frame's figures; nullptr: none yet
    double cpuFrameMs = 0.0;                 // wall time of the previous frame (the CPU plot)
    SceneRenderFigures scene;                // the scene image on screen: its cost, scale, reuse
    std::vector<ImTextureID> shadowLayers;   // one GL texture per cascade, depth already remapped for
                                             // display; shown with texel row 0 at the bottom
    std::vector<int> shadowMapSizes;         // texels per side of each cascade's map
    ImTextureID shadowAtlas = nullptr;       // storage "atlas": the whole atlas, tiles outlined;
                                             // shown instead of the per-cascade tiles
    int shadowAtlasWidth = 0;                // the atlas's texels
    int shadowAtlasHeight = 0;
    std::vector<ImTextureID> shadowVariance; // moment filters: per cascade the moments' spread
                                             // (black none .. yellow wide); empty otherwise
    ImTextureID sideView = nullptr;          // picture-in-picture image (the side camera, or the main
                                             // view when swapped); nullptr hides the window
    bool sideViewSwapped = false;            // Tab: the side camera fills the scene viewport, the main
                                             // view is the small picture
    std::vector<std::filesystem::path> presetFiles;  // offered in the Presets list, in this order
    std::string statusLine;                  // one line from the app (scene load error, fps, ...)
    AccuracyView accuracy;                   // the background ground truth's state and figures
    // Loads a scene the panels are about to put into the settings (relative paths from baseDir):
    // "" when it loads, else why not; the UI then leaves the settings as they are. Unset: every
    // scene is taken.
    std::function<std::string(const std::string& scene, bool ground, const std::filesystem::path& baseDir)> checkScene;
    // File > Open on a .gltf or .glb: a new, untitled preset for that scene (its camera framing the
    // scene, a sun, a ground under it, cascades spanning it: app/scene_preset.h). Throws
    // std::exception with the reason when the file does not load. Unset: glTF files are refused.
    std::function<Settings(const std::filesystem::path& gltf)> presetForScene;
    ProbeView probe;                         // the frame at the pixel the last draw() asked for
    std::vector<SideSplitHandle> sideSplitHandles;  // inner split planes in the side view picture
    AbView ab;                               // the A half of the split view (while it is on)
    const SweepView* sweep = nullptr;        // the Sweep panel's run; nullptr: none yet
    std::vector<std::string> sweepableFields;  // field paths a sweep may vary (sweep::isSweepable)
    const TuneView* tune = nullptr;          // the Tune panel's run; nullptr: none yet
    std::vector<std::pair<std::string, std::string>> tuneObjectives;  // `tune --objective` choices: name, label
    MotionView motion;
    MemoryView memory;                       // where the memory goes: the Help window's Memory table
};

// What the app should do after this frame. Default: nothing.
struct UiRequests {
    ChangeClass change = ChangeClass::None;  // what changed in Settings during draw(): widgets,
                                             // undo/redo, a loaded preset, the animated sun
    bool settingsValid = true;               // validate(settings) is empty; if not, keep rendering
                                             // the last valid settings (the problems are on screen)
    bool presetLoaded = false;               // settings were replaced by presetFile(): resolve a
                                             // relative glTF scene against its folder
    bool presetsChanged = false;             // a preset file was written: rescan the preset folder
    bool quit = false;                       // quit now (confirmed, or nothing unsaved)
    bool frameScene = false;                 // F, or View > Frame scene
    bool swapSideView = false;               // Tab, or View > Swap side view
    ImVec2 sideViewSize{0.0f, 0.0f};         // pixels the side view image is shown at (0: hidden)
    ImVec2 sideViewOrbit{0.0f, 0.0f};        // mouse movement dragged with the left/right button
    ImVec2 sideViewPan{0.0f, 0.0f};          // ... with the middle button
    float sideViewZoom = 0.0f;               // mouse wheel over the side view
    ImVec2 scenePos{0.0f, 0.0f};             // the scene viewport the panels leave free, in display
    ImVec2 sceneSize{0.0f, 0.0f};            // pixels from the top left: render the scene there only
    bool probeWanted = false;                // the mouse rests over the scene: sample probePixel
    ImVec2 probePixel{0.0f, 0.0f};           // scene pixel from the viewport's top left
    bool accuracyWanted = false;             // the Accuracy panel is open: compute its figures
    bool errorOverlay = false;               // ... and its error overlay is switched on: pass the
                                             // overlay to drawErrorOverlay() when it is current
    const Settings* abSettings = nullptr;    // A ("Set as A"), while one is set; valid until the next draw()
    bool abSplit = false;                    // the split view is on: render A left of the divider
    float abDivider = 0.5f;                  // the divider, as a fraction of the window's width
    std::optional<SweepRequest> sweepStart;  // Run pressed in the Sweep panel, with valid axes
    bool sweepCancel = false;                // Cancel pressed
    std::optional<TuneRequest> tuneStart;    // Go pressed in the Tune panel, with valid fields
    bool tuneCancel = false;                 // its Cancel pressed
    MotionRequests motion;                   // View > Motion's items
};

// Native key codes the platform backend writes into io.KeysDown. ImGui 1.86 names only a few keys
// (Tab and Z are read through io.KeyMap); the defaults are GLFW_KEY_S, GLFW_KEY_F and GLFW_KEY_F1,
// which is what imgui_impl_glfw 1.86 stores.
struct ShortcutKeys {
    int save = 83;    // Ctrl+S
    int frame = 70;   // F: frame the scene
    int help = 290;   // F1: help window
    int open = 79;    // Ctrl+O: File > Open
    int hidePanels = 72;  // H: hide every panel, the scene fills the window
    int firstView = 49;   // 1..6: output.view shaded, cascades, shadow, texel-density, side, texel-grid
};

// Draws the Accuracy panel's error overlay (an RGBA texture, top row first, straight alpha) over
// the whole window, under every panel. Call after draw() and before ImGui::Render(), once the
// app knows the overlay describes the frame it is about to show: a frame that changed since the
// figures were computed must not show them.
void drawErrorOverlay(ImTextureID overlay);
// ... over the scene viewport only (UiRequests::scenePos/sceneSize).
void drawErrorOverlay(ImTextureID overlay, ImVec2 pos, ImVec2 size);

class EditorUi {
public:
    // presetDir: where "Save as" puts relative names (usually presets/).
    explicit EditorUi(std::filesystem::path presetDir, ShortcutKeys keys = {});
    ~EditorUi();
    EditorUi(const EditorUi&) = delete;
    EditorUi& operator=(const EditorUi&) = delete;

    // Draws every panel and edits `s`. Call between ImGui::NewFrame() and ImGui::Render().
    UiRequests draw(Settings& s, const UiInputs& in);

    // The settings the app starts with and the preset they came from (empty path: untitled);
    // they become the clean state and the undo history is cleared. Without a call, the first
    // draw() takes its settings as clean.
    void setDocument(const Settings& clean, std::filesystem::path file);

    // Loads `file` into `s` (no confirmation asked). On failure `s` is untouched, the problems
    // are listed in the Presets panel and the result is false. Clears the undo history.
    bool openPreset(const std::filesystem::path& file, Settings& s);

    // Records a change the app made to the settings outside draw() (a camera fly or orbit gesture,
    // frame scene) as one undo step. `after` must be what the next draw() is given.
    void recordEdit(const Settings& before, const Settings& after);

    // The window's close button was pressed: a later draw() returns quit, after a confirmation
    // if there are unsaved changes.
    void requestQuit();

    bool dirty() const;                                // as of the last draw()
    // The engine the artist ships in (the Settings panel's Engine section): its knobs shown, what it
    // lacks greyed, the Tune panel tuning in its knobs. nullopt: every method (the default).
    void setEngine(std::optional<xport::Engine> engine);
    std::optional<xport::Engine> engine() const;
    // The Accuracy panel's error overlay toggle (off by default; `editor --error-overlay` starts with it on).
    void setErrorOverlay(bool on);
    std::string windowTitle() const;                   // "shadowtune - default.json *"
    const std::filesystem::path& presetFile() const;   // empty: untitled
    const std::vector<std::string>& errors() const;    // of the last failed load/save (shown in the UI)
    const ItemRects& itemRects() const;                // named widgets of the last draw() (tests)
    std::size_t undoSteps() const;                     // steps Ctrl+Z can undo
    const LayoutPrefs& layoutPrefs() const;            // column widths, hidden panels (the app saves them)
    void setLayoutPrefs(const LayoutPrefs& prefs);

private:
    std::unique_ptr<UiState> state_;
};

}  // namespace st::ui
