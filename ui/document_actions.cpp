#include "ui/document_actions.h"

#include <imgui.h>

namespace st::ui {
namespace {

// An edit gesture still open (e.g. Ctrl+Z pressed before the frame that would close it).
void closeGesture(UiFrame& f) {
    if (!f.state.gestureStart) return;
    f.state.undo.push(*f.state.gestureStart, f.s);
    f.state.gestureStart.reset();
}

void replaceSettings(UiFrame& f, Settings restored) {
    f.s = std::move(restored);
    f.replaced = true;
}

}  // namespace

void requestLoad(UiFrame& f, const std::filesystem::path& file) {
    if (!isDirty(f.state.doc, f.s)) return loadNow(f, file);
    f.state.pending = {PendingDiscard::Kind::Load, file};
    f.state.openConfirm = true;
}

void loadNow(UiFrame& f, const std::filesystem::path& file) {
    if (!loadDocument(f.state.doc, file, f.s)) return;
    resetHistory(f.state);
    f.state.saveAsText = file.string();
    f.replaced = true;
    f.req.presetLoaded = true;
}

void saveCurrent(UiFrame& f) {
    const auto file = f.state.doc.file.empty() ? resolveSavePath(f.state.presetDir, f.state.saveAsText)
                                               : f.state.doc.file;
    saveAs(f, file);
}

void saveAs(UiFrame& f, const std::filesystem::path& file) {
    closeGesture(f);
    if (saveDocument(f.state.doc, f.s, file)) f.req.presetsChanged = true;
}

void requestQuitFrom(UiState& state, bool dirty) {
    if (!dirty) {
        state.quitConfirmed = true;
        return;
    }
    state.pending = {PendingDiscard::Kind::Quit, {}};
    state.openConfirm = true;
}

void runPendingDiscard(UiFrame& f) {
    const PendingDiscard pending = f.state.pending;
    f.state.pending = {};
    if (pending.kind == PendingDiscard::Kind::Load) loadNow(f, pending.file);
    if (pending.kind == PendingDiscard::Kind::Quit) f.state.quitConfirmed = true;
}

void trackEditGesture(UiFrame& f, const Settings& beforeWidgets) {
    if (f.replaced) {
        f.state.gestureStart.reset();
        return;
    }
    if (f.edited && !f.state.gestureStart) f.state.gestureStart = beforeWidgets;
    if (f.state.gestureStart && !ImGui::IsAnyItemActive()) closeGesture(f);
}

void applyEdit(UiFrame& f, Settings after) {
    closeGesture(f);
    if (f.state.undo.push(f.s, after)) replaceSettings(f, std::move(after));
}

void undoEdit(UiFrame& f) {
    closeGesture(f);
    if (auto restored = f.state.undo.undo(f.s)) replaceSettings(f, std::move(*restored));
}

void redoEdit(UiFrame& f) {
    closeGesture(f);
    if (auto restored = f.state.undo.redo(f.s)) replaceSettings(f, std::move(*restored));
}

void resetHistory(UiState& state) {
    state.undo.clear();
    state.gestureStart.reset();
}

}  // namespace st::ui
