#include "ui/probe.h"

#include "ui/field_rules.h"
#include "ui/legends.h"
#include "ui/ui_state.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace st::ui {
namespace {

const char* litOrShadowed(float v) { return v >= 0.5f ? "lit" : "shadowed"; }

void probeLines(const ProbeView& p) {
    ImGui::Text("Pixel %d, %d", p.x, p.y);
    if (p.cascade < 0) {
        ImGui::TextUnformatted("Beyond the shadow distance: drawn lit");
        return;
    }
    cascadeSwatch(p.cascade);
    ImGui::SameLine();
    ImGui::Text("texel %s, %.2f px per texel", formatLength(p.texelWorldSize).c_str(), double(p.pixelsPerTexel));
    ImGui::Text("Shadow: test %s, filtered factor %.2f", litOrShadowed(p.hardResult), double(p.filteredFactor));
    if (!p.sunFacing) ImGui::TextDisabled("Truth: faces away from the sun (N.L %.2f)", double(p.nDotL));
    else if (p.truth < 0) ImGui::TextDisabled("Truth: not computed yet (Accuracy panel, camera still)");
    else if ((p.truth == 1) == (p.hardResult >= 0.5f)) ImGui::Text("Truth: %s (correct)", p.truth ? "lit" : "shadowed");
    else ImGui::TextColored({1.0f, 0.45f, 0.35f, 1.0f}, "Truth: %s (%s)", p.truth ? "lit" : "shadowed",
                            p.truth ? "false shadow" : "false light");
    ImGui::Text("Bias: %s constant + %s slope along the light", formatLength(p.constantBias).c_str(),
                formatLength(p.slopeBias).c_str());
    if (p.offsetOnCasters)
        ImGui::Text("      casters moved in %s x sin(N, L) (N.L here %.2f)", formatLength(p.normalOffset).c_str(), double(p.nDotL));
    else
        ImGui::Text("      %s normal offset (N.L %.2f)", formatLength(p.normalOffset).c_str(), double(p.nDotL));
}

// One axis: after the cursor, else before it, else as far after as `hi` lets it (from `lo` when
// it is larger than the room).
float placeAlong(float cursor, float size, float lo, float hi, float after, float before) {
    if (cursor + after + size <= hi) return cursor + after;
    if (cursor - before - size >= lo) return cursor - before - size;
    return std::max(lo, std::min(cursor + after, hi - size));
}

}  // namespace

ImVec2 placeProbeTooltip(ImVec2 mouse, ImVec2 size, const Rect& scene) {
    // ImGui's own offsets from the cursor (16 right, 24 down of its tip; 8 left and up).
    return {placeAlong(mouse.x, size.x, scene.min.x, scene.max.x, 16.0f, 8.0f),
            placeAlong(mouse.y, size.y, scene.min.y, scene.max.y, 24.0f, 8.0f)};
}

float probeWrapWidth(const Rect& scene) {
    const ImGuiStyle& style = ImGui::GetStyle();
    return std::max(8.0f * ImGui::GetFontSize(), std::min(scene.width(), 36.0f * ImGui::GetFontSize()) - 2.0f * style.WindowPadding.x);
}

void drawProbe(UiFrame& f) {
    const Rect& scene = f.state.layout.scene;
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    // Flying the camera, over a panel, or while a popup or modal is open (the Sweep panel's field
    // list, the Unsaved-changes question): the tooltip would be drawn over them (issue 21 #3).
    // WantCaptureMouse covers a hovered window and an open popup, as of this frame's start.
    // The help (F1) is read over the scene: no probe tooltip over it.
    if (!scene.contains(mouse) || f.state.showHelp || ImGui::GetIO().WantCaptureMouse || ImGui::IsWindowHovered(ImGuiHoveredFlags_AnyWindow) ||
        ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel) || ImGui::IsAnyItemActive() ||
        ImGui::IsAnyMouseDown())
        return;
    f.req.probeWanted = true;
    f.req.probePixel = {std::floor(mouse.x - scene.min.x), std::floor(mouse.y - scene.min.y)};
    const ProbeView& p = f.in.probe;
    // Only the pixel asked for: a readout of another pixel (the mouse moved on) is not shown.
    if (!p.valid || p.x != int(f.req.probePixel.x) || p.y != int(f.req.probePixel.y)) return;
    // Inside the scene viewport, not over the panels beside it (issue 21: at 1000x700 it covered
    // the Shadow maps panel): ImGui keeps a tooltip inside the display only. The lines wrap to
    // the viewport's width. The place is set before the tooltip begins (Begin draws its frame
    // where it is then), from its size as last drawn, which the few frames drawn after any
    // change bring up to date; before its first, from the wrap width and eight lines.
    const float wrap = probeWrapWidth(scene);
    const ImGuiStyle& style = ImGui::GetStyle();
    ImVec2& last = f.state.probeTooltipSize;
    const ImVec2 size = last.x > 0.0f ? last
                                      : ImVec2(wrap + 2.0f * style.WindowPadding.x,
                                               8.0f * ImGui::GetTextLineHeightWithSpacing() + 2.0f * style.WindowPadding.y);
    ImGui::SetNextWindowPos(placeProbeTooltip(mouse, size, scene));
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
    probeLines(p);
    ImGui::PopTextWrapPos();
    recordItem(f.state.rects, "probe");  // the tooltip's last line
    const ImVec2 pos = ImGui::GetWindowPos();
    last = ImGui::GetWindowSize();
    f.state.rects["probe.tooltip"] = {pos, {pos.x + last.x, pos.y + last.y}};
    ImGui::EndTooltip();
}

}  // namespace st::ui
