#pragma once
// Key events queued from the window's callback and handed to Dear ImGui a frame at a time.
// ImGui 1.86 reads io.KeysDown once per frame, so a key pressed and released between two
// frames (a 10 ms tap at 6 fps) was never seen (issue 13 #3). Here a key changes at most once
// per frame: the press shows in one frame, the release in the next. Pure, no GLFW or ImGui.
#include <cstddef>
#include <deque>
#include <span>

namespace st::app {

// Ctrl, Shift, Alt, Super from the GLFW key codes held in `keysDown` (as imgui_impl_glfw 1.86
// derives them), so a modifier tapped with a key is seen in the same frame as the key.
struct Modifiers {
    bool ctrl = false, shift = false, alt = false, super = false;
};
Modifiers modifiersOf(std::span<const bool> keysDown);

class KeyQueue {
public:
    void push(int key, bool down);  // from the key callback, in the order they came

    // Applies the queued events to `keysDown` (indexed by key code) in order, one change per key
    // per frame: a key's further events wait for the next frame, other keys' do not (so typing
    // "ss" at 5 fps delays the second s, not the keys after it, which would then arrive after
    // the mouse and text they came with). A modifier's change that comes after another key's
    // press waits a frame too, so the press is seen with the modifiers it was made with. Codes
    // outside `keysDown` are dropped. Returns true if events are still waiting.
    bool feed(std::span<bool> keysDown);

    bool empty() const { return events_.empty(); }

private:
    struct Event {
        int key;
        bool down;
    };
    std::deque<Event> events_;
};

}  // namespace st::app
