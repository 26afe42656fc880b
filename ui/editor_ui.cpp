#include "ui/editor_ui.h"

#include "renderer/settings/preset_paths.h"

#include "ui/document_actions.h"
#include "ui/field_rules.h"
#include "ui/field_widgets.h"
#include "ui/figures_panel.h"
#include "ui/map_cost_confirm.h"
#include "ui/panels.h"
#include "ui/ui_state.h"

#include <imgui.h>

namespace st::ui {
namespace {

// The "animate sun" toggle turns light.azimuth through the field table, like any other edit.
void animateSun(UiFrame& f) {
    if (!f.state.animateSun) return;
    const FieldInfo* azimuth = findField("light.azimuth");
    if (!azimuth) return;
    const float delta = f.state.sunDegPerSecond * ImGui::GetIO().DeltaTime;
    storeField(*azimuth, f.s, advanceAzimuth(f.s.light.azimuth, delta));
}

void beginFrame(UiFrame& f) {
    if (!f.state.doc.clean) f.state.doc.clean = f.s;
    f.state.rects.clear();
    recordTimings(f.state.timing, f.in.stats, f.in.cpuFrameMs);
    if (f.state.saveAsText.empty()) f.state.saveAsText = (f.state.presetDir / "untitled.json").string();
}

// After the shortcuts, so H hides the panels in the frame it is pressed.
void placePanels(UiFrame& f) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    f.state.layout = computeLayout(viewport->Pos, viewport->Size, currentLayoutMetrics(), f.state.prefs,
                                   {f.state.showShadowMaps, f.state.showSideView, f.state.showAccuracy});
}

void drawPanels(UiFrame& f) {
    placePanels(f);
    drawMenuBar(f);
    if (f.state.prefs.panelsHidden) {
        f.state.issues = findIssues(f.s);  // what the Settings panel would have listed
    } else {
        drawSettingsPanel(f);
        drawPresetsPanel(f);
        drawShadowViewer(f);
        drawSideView(f);
        drawAccuracyPanel(f);
        drawSplitBar(f);
    }
    drawSceneLegends(f);
    drawStatusBar(f);
    drawCompare(f);
    drawHelpWindow(f);
    drawConfirmDiscard(f);
    drawConfirmMapCost(f);
    drawProbe(f);  // last: a popup opened this frame stops it
}

void finishFrame(UiFrame& f, const Settings& atStart) {
    f.req.change = classifyChange(atStart, f.s);
    f.req.settingsValid = f.req.change == ChangeClass::None ? f.state.issues.empty() : validate(f.s).empty();
    f.req.quit = f.state.quitConfirmed;
    f.req.scenePos = f.state.layout.scene.min;
    f.req.sceneSize = {f.state.layout.scene.width(), f.state.layout.scene.height()};
    f.req.accuracyWanted = f.state.showAccuracy;
    f.req.errorOverlay = f.state.showAccuracy && f.state.errorOverlay;
    f.state.dirty = isDirty(f.state.doc, f.s);
}

}  // namespace

EditorUi::EditorUi(std::filesystem::path presetDir, ShortcutKeys keys) : state_(std::make_unique<UiState>()) {
    state_->presetDir = std::move(presetDir);
    state_->doc.schemaHint = state_->presetDir;
    state_->keys = keys;
}

EditorUi::~EditorUi() = default;

UiRequests EditorUi::draw(Settings& s, const UiInputs& in) {
    UiRequests req;
    UiFrame f{*state_, s, in, req};
    const Settings atStart = s;
    beginFrame(f);
    animateSun(f);
    handleShortcuts(f);
    const Settings beforeWidgets = s;
    // Tab swaps the views; ImGui would also move the keyboard into the next widget (issue 13 #3).
    ImGui::PushAllowKeyboardFocus(false);
    drawPanels(f);
    ImGui::PopAllowKeyboardFocus();
    trackEditGesture(f, beforeWidgets);
    // Undo, redo, a load or Revert replaced the values a refusal was about (issue 21 #11).
    if (f.replaced) f.state.fieldEdits = {};
    finishFrame(f, atStart);
    return req;
}

void EditorUi::setDocument(const Settings& clean, std::filesystem::path file) {
    state_->doc = Document{std::move(file), clean, {}, {}};
    state_->doc.schema = state_->doc.file.empty() ? "" : presetSchemaRef(state_->doc.file);
    state_->doc.schemaHint = state_->presetDir;
    state_->dirty = false;
    if (!state_->doc.file.empty()) state_->saveAsText = state_->doc.file.string();
    resetHistory(*state_);
}

bool EditorUi::openPreset(const std::filesystem::path& file, Settings& s) {
    if (!loadDocument(state_->doc, file, s)) return false;
    state_->dirty = false;
    state_->saveAsText = file.string();
    resetHistory(*state_);
    return true;
}

void EditorUi::recordEdit(const Settings& before, const Settings& after) {
    if (state_->gestureStart) {  // a widget gesture still open: close it at `before`
        state_->undo.push(*state_->gestureStart, before);
        state_->gestureStart.reset();
    }
    recordStep(*state_, before, after);
}

void EditorUi::requestQuit() { requestQuitFrom(*state_, state_->dirty); }

bool EditorUi::dirty() const { return state_->dirty; }

void EditorUi::setEngine(std::optional<xport::Engine> engine) { state_->engine = {engine, {}, {}}; }

std::optional<xport::Engine> EditorUi::engine() const { return state_->engine.engine; }

void EditorUi::setErrorOverlay(bool on) { state_->errorOverlay = on; }

std::string EditorUi::windowTitle() const { return documentTitle(state_->doc, state_->dirty); }

const std::filesystem::path& EditorUi::presetFile() const { return state_->doc.file; }

const std::vector<std::string>& EditorUi::errors() const { return state_->doc.errors; }

const ItemRects& EditorUi::itemRects() const { return state_->rects; }

std::size_t EditorUi::undoSteps() const { return state_->undo.undoCount(); }

const LayoutPrefs& EditorUi::layoutPrefs() const { return state_->prefs; }

void EditorUi::setLayoutPrefs(const LayoutPrefs& prefs) { state_->prefs = prefs; }

}  // namespace st::ui
