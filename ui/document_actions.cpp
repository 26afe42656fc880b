#include "ui/document_actions.h"

#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "ui/path_completion.h"

#include <imgui.h>

namespace st::ui {
namespace {

// An edit gesture still open (e.g. Ctrl+Z pressed before the frame that would close it).
// A change of the debug view alone is no undo step unless the view is saved with the preset.
void closeGesture(UiFrame& f) {
    if (!f.state.gestureStart) return;
    recordStep(f.state, *f.state.gestureStart, f.s);
    f.state.gestureStart.reset();
}

void replaceSettings(UiFrame& f, Settings restored) {
    if (!f.state.doc.saveViewWithPreset) restored.output.view = f.s.output.view;
    f.s = std::move(restored);
    f.replaced = true;
}

}  // namespace

void requestLoad(UiFrame& f, const std::filesystem::path& file) {
    if (!isDirty(f.state.doc, f.s)) return loadNow(f, file);
    f.state.pending = {PendingDiscard::Kind::Load, file};
    f.state.openConfirm = true;
}

namespace {
// A glTF of the user's own: a new, untitled preset for its scene (the camera, sun, ground and
// cascades made for it; no notes, splits or problems of the scene before). Saving asks where.
void openScene(UiFrame& f, const std::filesystem::path& file) {
    if (!f.in.presetForScene) {
        f.state.doc.errors = {file.string() + ": this editor opens presets (.json) only"};
        return;
    }
    Settings made;
    try {
        made = f.in.presetForScene(std::filesystem::absolute(file));
    } catch (const std::exception& e) {
        f.state.doc.errors = {file.string() + ": " + e.what()};
        f.state.doc.status.clear();
        return;
    }
    if (const std::string sceneError = sceneProblem(f, made.scene, made.ground, folderOf(file)); !sceneError.empty()) {
        f.state.doc.errors = {file.string() + ": scene: " + sceneError};
        return;
    }
    Document next;
    next.schemaHint = f.state.doc.schemaHint;
    next.status = "new preset for " + file.filename().string() + ": not saved yet (Save as asks where)";
    f.state.doc = std::move(next);
    f.state.doc.clean = made;
    f.s = std::move(made);
    resetHistory(f.state);
    f.state.saveAsText = (f.state.presetDir / (file.stem().string() + ".json")).string();
    f.replaced = true;
    f.req.presetLoaded = true;
}
}  // namespace

// A preset whose scene does not load is refused as a whole: the document, the settings and the
// history stay as they were (issue 13 #1).
void loadNow(UiFrame& f, const std::filesystem::path& file) {
    if (isGltfFile(file)) return openScene(f, file);
    Document next = f.state.doc;
    Settings loaded = f.s;
    const bool read = loadDocument(next, file, loaded);
    const std::string sceneError = read ? sceneProblem(f, loaded.scene, loaded.ground, folderOf(file)) : "";
    if (!read || !sceneError.empty()) {
        f.state.doc.errors = read ? std::vector<std::string>{file.string() + ": scene: " + sceneError} : next.errors;
        f.state.doc.status.clear();
        return;
    }
    next.schemaHint = f.state.doc.schemaHint;
    f.state.doc = std::move(next);
    f.s = std::move(loaded);
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

// Relative file references (the scene) follow the document into the new file's folder: in the
// file written, in the settings being edited and in the undo history, so all of them keep naming
// the same files (issue 13 #1).
void saveAs(UiFrame& f, const std::filesystem::path& file) {
    closeGesture(f);
    const std::filesystem::path from = documentFolder(f.state), to = folderOf(file);
    Settings rebased = rebasePaths(f.s, from, to);
    if (!saveDocument(f.state.doc, rebased, file)) return;
    f.req.presetsChanged = true;
    if (rebased == f.s) return;
    f.s = std::move(rebased);
    f.state.undo.forEach([&](Settings& s) { s = rebasePaths(std::move(s), from, to); });
    f.replaced = true;
}

std::string sceneProblem(const UiFrame& f, const std::string& scene, bool ground, const std::filesystem::path& baseDir) {
    return f.in.checkScene ? f.in.checkScene(scene, ground, baseDir) : std::string();
}

std::filesystem::path documentFolder(const UiState& state) {
    return state.doc.file.empty() ? state.presetDir : folderOf(state.doc.file);
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

bool recordStep(UiState& state, Settings before, const Settings& after) {
    if (!state.doc.saveViewWithPreset) before.output.view = after.output.view;
    return state.undo.push(before, after);
}

void applyEdit(UiFrame& f, Settings after) {
    closeGesture(f);
    if (recordStep(f.state, f.s, after)) replaceSettings(f, std::move(after));
}

Settings withAssignments(Settings s, const std::vector<std::pair<std::string, std::string>>& assignments) {
    for (const auto& [path, json] : assignments) {
        const FieldInfo* field = findField(path);
        if (!field) continue;
        try {
            field->set(s, readFieldValue(*field, nlohmann::json::parse(json), path));
            keepCascadeListsValid(s, path);
        } catch (const std::exception&) {
            // A foreign point keeps what this build cannot set.
        }
    }
    return s;
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
