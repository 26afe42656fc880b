#pragma once
// Screen rectangles of named widgets from the last frame, so scripted-input tests can click and
// drag real widgets without hard-coded coordinates. Filled as the widgets are drawn.
#include <imgui.h>

#include <map>
#include <string>

namespace st::ui {

struct ItemRect {
    ImVec2 min{0.0f, 0.0f};
    ImVec2 max{0.0f, 0.0f};
    ImVec2 center() const { return {(min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f}; }
    // The point at fraction (fx, fy) of the rectangle, (0, 0) top left.
    ImVec2 at(float fx, float fy) const { return {min.x + (max.x - min.x) * fx, min.y + (max.y - min.y) * fy}; }
};

using ItemRects = std::map<std::string, ItemRect, std::less<>>;

// Stores the last submitted item's rectangle under `key`: for sliders, drags and combos the frame
// without the label (a slider's value maps onto its frame), otherwise the whole item.
void recordItem(ItemRects& rects, std::string key);

}  // namespace st::ui
