// The side view as a picture-in-picture window: shows the app's texture and hands mouse drags
// and the wheel over it back to the app, which orbits its side camera.
#include "ui/layout.h"
#include "ui/legends.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>

namespace st::ui {
namespace {

void reportInput(UiFrame& f) {
    const ImGuiIO& io = ImGui::GetIO();
    if (ImGui::IsItemActive()) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left) || ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
            f.req.sideViewOrbit = io.MouseDelta;
        }
        if (ImGui::IsMouseDown(ImGuiMouseButton_Middle)) f.req.sideViewPan = io.MouseDelta;
    }
    if (ImGui::IsItemHovered()) f.req.sideViewZoom = io.MouseWheel;
}

void drawImage(UiFrame& f) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 size{std::max(avail.x, 16.0f), std::max(avail.y, 16.0f)};
    ImGui::InvisibleButton("sideViewInput", size, ImGuiButtonFlags_MouseButtonLeft |
                                                      ImGuiButtonFlags_MouseButtonRight |
                                                      ImGuiButtonFlags_MouseButtonMiddle);
    recordItem(f.state.rects, "sideView");
    // Texel row 0 of a GL texture is the bottom row: flip v.
    ImGui::GetWindowDrawList()->AddImage(f.in.sideView, ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                         ImVec2(0.0f, 1.0f), ImVec2(1.0f, 0.0f));
    f.req.sideViewSize = size;
    // Which wireframe is which cascade; the camera frustum is white, a colour no cascade uses.
    if (f.in.stats) drawCascadeLegend(ImGui::GetWindowDrawList(), {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()},
                                      static_cast<int>(f.in.stats->cascades.size()));
    reportInput(f);
}

}  // namespace

void drawSideView(UiFrame& f) {
    if (!f.state.showSideView || !f.in.sideView) return;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2.0f, 2.0f));
    if (beginDockedPanel(f, Panel::SideView, "Side view", &f.state.showSideView)) drawImage(f);
    ImGui::End();
    ImGui::PopStyleVar();
}

}  // namespace st::ui
