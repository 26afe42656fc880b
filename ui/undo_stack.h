#pragma once
// Undo/redo of Settings edits as whole snapshots. Pure (no ImGui): EditorUi pushes one entry per
// finished edit gesture (a whole slider drag is one entry), so Ctrl+Z steps back a gesture, not a
// frame. Settings is small (a few hundred bytes), so snapshots are simpler than diffs.
#include "renderer/settings/settings.h"

#include <cstddef>
#include <deque>
#include <functional>
#include <optional>

namespace st::ui {

class UndoStack {
public:
    explicit UndoStack(std::size_t capacity = 256);  // oldest entries are dropped beyond this

    // Records an edit from `before` to `after`. Returns false (and records nothing) when they are
    // equal, e.g. a slider dragged back to where it started. Clears the redo entries.
    bool push(const Settings& before, const Settings& after);

    // The settings to restore, or nullopt when there is nothing to undo/redo. `current` is what
    // the caller holds now; it becomes the redo (undo) entry.
    std::optional<Settings> undo(const Settings& current);
    std::optional<Settings> redo(const Settings& current);

    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    std::size_t undoCount() const { return undo_.size(); }
    std::size_t redoCount() const { return redo_.size(); }
    void clear();
    // Applies `fn` to every entry, e.g. to rewrite relative paths after a save into another folder.
    void forEach(const std::function<void(Settings&)>& fn);

private:
    std::size_t capacity_;
    std::deque<Settings> undo_;  // back = most recent
    std::deque<Settings> redo_;  // back = next to redo
};

}  // namespace st::ui
