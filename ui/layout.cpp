#include "ui/layout.h"

#include <imgui.h>

#include <algorithm>

namespace st::ui {
namespace {

constexpr float kLeftWidth = 430.0f;   // Settings: labels, widgets and the per-cascade tables
constexpr float kRightWidth = 330.0f;  // Presets, Shadow maps, Side view stacked on the right

struct Area {
    ImVec2 pos;
    ImVec2 size;
};

// The display below the main menu bar. Computed from the frame height, not the viewport's work
// area, which leaves out the menu bar only from the frame after the bar was first drawn.
Area workArea() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float menuBar = ImGui::GetFrameHeight();
    return {{viewport->Pos.x, viewport->Pos.y + menuBar}, {viewport->Size.x, viewport->Size.y - menuBar}};
}

// Right column: presets 34 %, shadow maps 33 %, side view the rest of the height.
Area rightSlot(float top, float height) {
    const Area work = workArea();
    const float width = std::min(kRightWidth, work.size.x * 0.4f);
    return {{work.pos.x + work.size.x - width, work.pos.y + work.size.y * top},
            {width, work.size.y * height}};
}

// Accuracy: along the bottom of the scene view, between the side columns, so most of the view
// (and the error overlay on it) stays visible.
Area bottomMiddle(float height) {
    const Area work = workArea();
    const float left = std::min(kLeftWidth, work.size.x * 0.5f);
    const float right = std::min(kRightWidth, work.size.x * 0.4f);
    const float width = std::max(work.size.x - left - right, 240.0f);
    return {{work.pos.x + left, work.pos.y + work.size.y - height}, {width, height}};
}

Area centred(float width, float height) {
    const Area work = workArea();
    return {{work.pos.x + (work.size.x - width) * 0.5f, work.pos.y + (work.size.y - height) * 0.5f},
            {width, height}};
}

Area areaOf(Panel panel) {
    const Area work = workArea();
    switch (panel) {
        case Panel::Settings: return {work.pos, {std::min(kLeftWidth, work.size.x * 0.5f), work.size.y}};
        case Panel::Presets: return rightSlot(0.0f, 0.34f);
        case Panel::ShadowMaps: return rightSlot(0.34f, 0.33f);
        case Panel::SideView: return rightSlot(0.67f, 0.33f);
        case Panel::Accuracy: return bottomMiddle(std::min(250.0f, work.size.y * 0.4f));
        case Panel::ShadowZoom: return centred(560.0f, 600.0f);
        case Panel::Help: return centred(460.0f, 330.0f);
        case Panel::Confirm: return centred(380.0f, 0.0f);
    }
    return work;
}

}  // namespace

void placeNextWindow(Panel panel) {
    const Area area = areaOf(panel);
    const ImGuiCond cond = panel == Panel::Confirm ? ImGuiCond_Appearing : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(area.pos, cond);
    if (area.size.y > 0.0f) ImGui::SetNextWindowSize(area.size, cond);
}

}  // namespace st::ui
