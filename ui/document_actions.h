#pragma once
// What menu items, buttons and shortcuts do to the document and the settings: load (asking first
// when changes would be lost), save, undo/redo, quit. Shared so every path behaves the same.
#include "ui/ui_state.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace st::ui {

// Loads `file`, or opens the discard confirmation first when there are unsaved changes.
void requestLoad(UiFrame& f, const std::filesystem::path& file);
void loadNow(UiFrame& f, const std::filesystem::path& file);

// Saves to the current file; without one, to the "Save as" path.
void saveCurrent(UiFrame& f);
void saveAs(UiFrame& f, const std::filesystem::path& file);

// The folder relative file references of the document are taken from: the file's, or presetDir
// while untitled.
std::filesystem::path documentFolder(const UiState& state);

// Why `scene` would not load (UiInputs::checkScene), or "" when it loads or nobody can tell.
std::string sceneProblem(const UiFrame& f, const std::string& scene, bool ground, const std::filesystem::path& baseDir);

// Quits at once when nothing is unsaved, otherwise after the confirmation.
void requestQuitFrom(UiState& state, bool dirty);

// Carries out the action the confirmation held (the user chose to discard).
void runPendingDiscard(UiFrame& f);

// Records the widget edit in progress as one undo step once no widget is active any more.
void trackEditGesture(UiFrame& f, const Settings& beforeWidgets);

// One undo step from `before` to `after` (e.g. a camera gesture the app made); false when they
// differ in nothing the document holds.
bool recordStep(UiState& state, Settings before, const Settings& after);
// Replaces the settings with `after` as one undo step (a picked sweep point, a pasted method).
void applyEdit(UiFrame& f, Settings after);

// `s` with each (field path, value as JSON text) set through the field table, as a sweep point or
// a tune's explanation names them; a cascade count change keeps the per-cascade bias lists valid.
// A pair this build cannot read is skipped (a point written by another build).
Settings withAssignments(Settings s, const std::vector<std::pair<std::string, std::string>>& assignments);

void undoEdit(UiFrame& f);
void redoEdit(UiFrame& f);

// The undo history starts over (after a load or a new document).
void resetHistory(UiState& state);

}  // namespace st::ui
