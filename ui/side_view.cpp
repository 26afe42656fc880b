// The side view as a picture-in-picture window: shows the app's texture and hands mouse drags
// and the wheel over it back to the app, which orbits its side camera.
#include "ui/layout.h"
#include "ui/field_rules.h"
#include "ui/legends.h"
#include "ui/split_bar.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <string>

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

struct DrawnHandle {
    ImVec2 at;
    int cascade;
    bool hot;
};

// Split planes dragged in the picture: the mouse movement along the handle's own direction
// (pixels per metre of split depth, from the app's side camera) becomes metres. Submitted before
// the picture's own button, so the handles, not the orbit, take a press on them.
std::vector<DrawnHandle> dragSplitPlanes(UiFrame& f, ImVec2 origin, ImVec2 size) {
    std::vector<DrawnHandle> drawn;
    const FrameStats* stats = f.in.stats;
    if (!stats || stats->splits.size() < 2) return drawn;
    std::vector<float> inner = innerSplits(f.s, stats->splits);
    if (inner.size() != f.in.sideSplitHandles.size()) return drawn;
    bool dragged = false;
    for (std::size_t i = 0; i < inner.size(); ++i) {
        const SideSplitHandle& h = f.in.sideSplitHandles[i];
        const ImVec2 at{origin.x + h.uv.x * size.x, origin.y + h.uv.y * size.y};
        if (at.x < origin.x || at.y < origin.y || at.x > origin.x + size.x || at.y > origin.y + size.y) continue;
        ImGui::SetCursorScreenPos({at.x - 7.0f, at.y - 7.0f});
        ImGui::PushID(static_cast<int>(i));
        ImGui::InvisibleButton("splitPlane", {14.0f, 14.0f});
        ImGui::PopID();
        recordItem(f.state.rects, "sideView.split" + std::to_string(i));
        drawn.push_back({at, static_cast<int>(i), ImGui::IsItemActive() || ImGui::IsItemHovered()});
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Split %zu: %s (drag: manual splits)", i + 1, formatLength(inner[i]).c_str());
        const ImVec2 perMetre{h.uvPerMetre.x * size.x, h.uvPerMetre.y * size.y};
        const float lengthSq = perMetre.x * perMetre.x + perMetre.y * perMetre.y;
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        if (!ImGui::IsItemActive() || lengthSq <= 0.0f || (delta.x == 0.0f && delta.y == 0.0f)) continue;
        const float metres = (delta.x * perMetre.x + delta.y * perMetre.y) / lengthSq;
        inner[i] = clampedSplit(inner, static_cast<int>(i), stats->splits.front(), stats->splits.back(), inner[i] + metres);
        dragged = true;
    }
    if (dragged) storeManualSplits(f, inner);
    ImGui::SetCursorScreenPos(origin);
    return drawn;
}

// The split plane at the far end of cascade i is drawn in its tint: so is its handle.
void drawHandles(const std::vector<DrawnHandle>& handles) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    for (const DrawnHandle& h : handles) {
        const float radius = h.hot ? 6.0f : 4.5f;
        list->AddCircleFilled(h.at, radius, ImGui::GetColorU32(cascadeColour(h.cascade)));
        list->AddCircle(h.at, radius, IM_COL32(20, 20, 20, 255), 0, 1.5f);
    }
}

void drawImage(UiFrame& f) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 size{std::max(avail.x, 16.0f), std::max(avail.y, 16.0f)};
    const std::vector<DrawnHandle> handles = dragSplitPlanes(f, ImGui::GetCursorScreenPos(), size);
    ImGui::InvisibleButton("sideViewInput", size, ImGuiButtonFlags_MouseButtonLeft |
                                                      ImGuiButtonFlags_MouseButtonRight |
                                                      ImGuiButtonFlags_MouseButtonMiddle);
    recordItem(f.state.rects, "sideView");
    // Texel row 0 of a GL texture is the bottom row: flip v.
    ImGui::GetWindowDrawList()->AddImage(f.in.sideView, ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                         ImVec2(0.0f, 1.0f), ImVec2(1.0f, 0.0f));
    f.req.sideViewSize = size;
    // Which wireframe is which cascade; the camera frustum is white, a colour no cascade uses.
    // Swapped, this picture is the main view: its wireframe key is on the big viewport.
    if (f.in.stats && !f.in.sideViewSwapped) drawCascadeLegend(ImGui::GetWindowDrawList(), {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()},
                                      static_cast<int>(f.in.stats->cascades.size()));
    reportInput(f);
    drawHandles(handles);
}

}  // namespace

void drawSideView(UiFrame& f) {
    if (!f.state.showSideView || !f.in.sideView) return;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2.0f, 2.0f));
    // The title names what the picture shows; the ID stays, so the window keeps its place.
    const char* title = f.in.sideViewSwapped ? "Main view (Tab: swap back)###Side view" : "Side view###Side view";
    if (beginDockedPanel(f, Panel::SideView, title, &f.state.showSideView)) drawImage(f);
    ImGui::End();
    ImGui::PopStyleVar();
}

}  // namespace st::ui
