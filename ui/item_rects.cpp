#include "ui/item_rects.h"

#include <imgui_internal.h>

namespace st::ui {

void recordItem(ItemRects& rects, std::string key) {
    // ImGui 1.86 keeps the frame of a labelled widget (slider, drag, combo) as the item's
    // navigation rectangle; for other items it equals the item rectangle.
    const ImRect& r = ImGui::GetCurrentContext()->LastItemData.NavRect;
    rects[std::move(key)] = {r.Min, r.Max};
}

}  // namespace st::ui
