#include "app/key_queue.h"

#include <algorithm>
#include <vector>

namespace st::app {

void KeyQueue::push(int key, bool down) { events_.push_back({key, down}); }

bool KeyQueue::feed(std::span<bool> keysDown) {
    std::vector<int> changed;  // keys that changed this frame: a few at most
    while (!events_.empty()) {
        const Event e = events_.front();
        if (e.key < 0 || static_cast<std::size_t>(e.key) >= keysDown.size()) {
            events_.pop_front();
            continue;
        }
        const auto i = static_cast<std::size_t>(e.key);
        if (keysDown[i] == e.down) {  // a repeat, or a release of a key never seen down
            events_.pop_front();
            continue;
        }
        if (std::find(changed.begin(), changed.end(), e.key) != changed.end()) break;
        keysDown[i] = e.down;
        changed.push_back(e.key);
        events_.pop_front();
    }
    return !events_.empty();
}

}  // namespace st::app
