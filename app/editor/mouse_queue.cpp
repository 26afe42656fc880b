#include "app/editor/mouse_queue.h"

namespace st::app {

void MouseQueue::move(double x, double y) {
    last_ = {static_cast<float>(x), static_cast<float>(y)};
    // Consecutive moves merge at once: only the last one before a button change is ever shown,
    // and a held-down drag would otherwise queue hundreds per slow frame.
    if (!events_.empty() && events_.back().button < 0) {
        events_.back().at = last_;
        return;
    }
    events_.push_back({-1, false, last_});
}

void MouseQueue::button(int button, bool down) {
    if (button < 0 || button >= kButtons) return;
    const auto i = static_cast<std::size_t>(button);
    // A repeat, or the release of a press that began outside the window: no change to show.
    if (pending_[i] == down) return;
    pending_[i] = down;
    events_.push_back({button, down, last_});
}

std::optional<MouseQueue::Position> MouseQueue::feed() {
    std::optional<Position> shown;
    while (!events_.empty()) {
        const Event e = events_.front();
        events_.pop_front();
        shown = e.at;
        if (e.button >= 0) {
            // The frame ends with its button change: a move after it would show the change at
            // the wrong place, a second change would hide the first from ImGui.
            down_[static_cast<std::size_t>(e.button)] = e.down;
            break;
        }
    }
    return shown;
}

}  // namespace st::app
