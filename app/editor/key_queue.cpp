#include "app/editor/key_queue.h"

#include <algorithm>
#include <vector>

namespace st::app {

namespace {
bool isModifier(int key) { return key >= 340 && key <= 347; }  // GLFW_KEY_LEFT_SHIFT .. GLFW_KEY_RIGHT_SUPER
}  // namespace

Modifiers modifiersOf(std::span<const bool> keysDown) {
    const auto down = [&](int key) { return static_cast<std::size_t>(key) < keysDown.size() && keysDown[static_cast<std::size_t>(key)]; };
    // GLFW_KEY_LEFT_SHIFT 340, _CONTROL 341, _ALT 342, _SUPER 343; the right ones 344..347.
    return {down(341) || down(345), down(340) || down(344), down(342) || down(346), down(343) || down(347)};
}

void KeyQueue::push(int key, bool down) { events_.push_back({key, down}); }

bool KeyQueue::feed(std::span<bool> keysDown) {
    struct Seen {
        int key;
        bool state;  // the key's state once this frame's and the waiting events are applied
    };
    std::vector<Seen> changed;  // keys that changed this frame: a few at most
    std::deque<Event> later;
    bool keyPressed = false;  // a key other than a modifier went down this frame
    for (const Event& e : events_) {
        if (e.key < 0 || static_cast<std::size_t>(e.key) >= keysDown.size()) continue;
        const auto i = static_cast<std::size_t>(e.key);
        auto seen = std::find_if(changed.begin(), changed.end(), [&](const Seen& c) { return c.key == e.key; });
        const bool state = seen == changed.end() ? keysDown[i] : seen->state;
        if (state == e.down) continue;  // a repeat, or a release of a key never seen down
        if (seen != changed.end()) {
            later.push_back(e);  // this key's next change waits a frame; other keys go on
            seen->state = e.down;
            continue;
        }
        if (isModifier(e.key) && keyPressed) {
            // A modifier changing after a key's press would change what the press meant: Ctrl
            // down in one frame, then A down and Ctrl up (xdotool's order, or a quick hand at
            // 5 fps) in the next read as a plain A, and Ctrl+A did not select all (issue 21 #7).
            later.push_back(e);
            changed.push_back({e.key, e.down});
            continue;
        }
        keysDown[i] = e.down;
        changed.push_back({e.key, e.down});
        keyPressed = keyPressed || (e.down && !isModifier(e.key));
    }
    events_ = std::move(later);
    return !events_.empty();
}

}  // namespace st::app
