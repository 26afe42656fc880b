#pragma once
// Mouse events queued from the window's callbacks and handed to Dear ImGui a frame at a time.
// ImGui 1.86 reads io.MouseDown and io.MousePos once per frame, and imgui_impl_glfw 1.86 latches
// presses but not releases and takes the position from glfwGetCursorPos at NewFrame, so a click
// between two frames that moves on (a quick click at 2-6 fps) was seen as a press where the
// cursor had gone, and a drag started where the cursor was a frame later (issue 13 #3).
// Here a frame takes the queued events up to and including the first button change, and shows
// the position that change happened at: a press in one frame at the press position, its release
// in a later frame at the release position. Pure, no GLFW or ImGui. Wheel events are not queued:
// the backend sums them into io.MouseWheel, which ImGui reads as one turn per frame.
#include <array>
#include <deque>
#include <optional>

namespace st::app {

class MouseQueue {
public:
    static constexpr int kButtons = 5;  // io.MouseDown's size in ImGui 1.86; GLFW's higher buttons are dropped

    struct Position {
        float x = 0.0f, y = 0.0f;
        bool operator==(const Position&) const = default;
    };

    // From the cursor-position callback, in the order they came.
    void move(double x, double y);
    // Where the cursor is before its first move (the window opened under it): the position a
    // button uses, with no event, so the frame keeps the window's own position until a click.
    void place(double x, double y) { last_ = {static_cast<float>(x), static_cast<float>(y)}; }
    // From the button callback: at the position of the latest move (GLFW reports none with the
    // button, and glfwGetCursorPos asks the X server for where the cursor is now, not where it was).
    void button(int button, bool down);

    // One frame's events: moves up to the first button change are merged, that change is applied
    // and the rest wait. Returns the position the frame should show, or nothing when no event
    // was queued (the window's own cursor position stands).
    std::optional<Position> feed();

    const std::array<bool, kButtons>& down() const { return down_; }
    bool empty() const { return events_.empty(); }

private:
    struct Event {
        int button;  // -1: a move
        bool down;
        Position at;
    };
    std::deque<Event> events_;
    Position last_;                       // where the latest queued move went
    std::array<bool, kButtons> pending_{};  // the buttons' state once every queued event is applied
    std::array<bool, kButtons> down_{};     // the buttons' state as fed to ImGui
};

}  // namespace st::app
