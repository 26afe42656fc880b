#include "ui/undo_stack.h"

#include <algorithm>
#include <utility>

namespace st::ui {

UndoStack::UndoStack(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

bool UndoStack::push(const Settings& before, const Settings& after) {
    if (before == after) return false;
    undo_.push_back(before);
    if (undo_.size() > capacity_) undo_.pop_front();
    redo_.clear();
    return true;
}

std::optional<Settings> UndoStack::undo(const Settings& current) {
    if (undo_.empty()) return std::nullopt;
    Settings restored = std::move(undo_.back());
    undo_.pop_back();
    redo_.push_back(current);
    return restored;
}

std::optional<Settings> UndoStack::redo(const Settings& current) {
    if (redo_.empty()) return std::nullopt;
    Settings restored = std::move(redo_.back());
    redo_.pop_back();
    undo_.push_back(current);
    return restored;
}

void UndoStack::clear() {
    undo_.clear();
    redo_.clear();
}

void UndoStack::forEach(const std::function<void(Settings&)>& fn) {
    for (Settings& s : undo_) fn(s);
    for (Settings& s : redo_) fn(s);
}

}  // namespace st::ui
