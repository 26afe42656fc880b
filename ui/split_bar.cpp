#include "ui/split_bar.h"

#include "renderer/settings/field_table.h"
#include "ui/field_rules.h"
#include "ui/field_widgets.h"
#include "ui/layout.h"
#include "ui/legends.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace st::ui {

std::vector<float> innerSplits(const Settings& s, const std::vector<float>& rendered) {
    const auto inner = static_cast<std::size_t>(std::max(s.cascades.count - 1, 0));
    if (s.cascades.scheme == SplitScheme::Manual && s.cascades.manualSplits.size() == inner)
        return s.cascades.manualSplits;
    if (rendered.size() < 2) return {};
    return {rendered.begin() + 1, rendered.end() - 1};
}

float clampedSplit(const std::vector<float>& inner, int index, float nearDepth, float farDepth, float depth) {
    const auto i = static_cast<std::size_t>(index);
    const float lo = i == 0 ? nearDepth : inner[i - 1];
    const float hi = i + 1 >= inner.size() ? farDepth : inner[i + 1];
    // No cascade thinner than 1 % of the bar's range or half a metre, whichever is more (a 0.2 m
    // cascade between 59.5 and 59.7 m wastes a whole map, issue 21 #12); between neighbours already
    // closer than that, a quarter of their gap, so the handle still moves and never meets them.
    const float minimum = std::max(0.01f * (farDepth - nearDepth), 0.5f);
    const float gap = std::min(minimum, (hi - lo) * 0.25f);
    return std::clamp(depth, lo + gap, hi - gap);
}

float draggedSplit(const std::vector<float>& inner, int index, float nearDepth, float farDepth, float fraction) {
    const float depth = nearDepth + std::clamp(fraction, 0.0f, 1.0f) * (farDepth - nearDepth);
    return clampedSplit(inner, index, nearDepth, farDepth, depth);
}

void storeManualSplits(UiFrame& f, const std::vector<float>& inner) {
    const FieldInfo* scheme = findField("cascades.scheme");
    const FieldInfo* splits = findField("cascades.manualSplits");
    if (!scheme || !splits) return;
    bool changed = storeField(*scheme, f.s, static_cast<int>(SplitScheme::Manual));
    changed = storeField(*splits, f.s, inner) || changed;
    f.edited = f.edited || changed;
}

namespace {

struct Bar {
    ImVec2 min, max;
    float nearDepth, farDepth;
    float x(float depth) const { return min.x + (max.x - min.x) * (depth - nearDepth) / (farDepth - nearDepth); }
};

std::string percentOf(float part, float whole) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f %%", whole > 0.0f ? 100.0 * double(part / whole) : 0.0);
    return text;
}

// One segment: its tint, and "C<i> a - b m" over "p %" where it fits; the tooltip always.
void drawSegment(ImDrawList* list, const Bar& bar, int i, float from, float to, float shadowDistance) {
    const ImVec2 a{bar.x(from), bar.min.y}, b{bar.x(to), bar.max.y};
    ImVec4 colour = cascadeColour(i);
    colour.w = 0.75f;
    list->AddRectFilled(a, b, ImGui::GetColorU32(colour));
    const std::string range = "C" + std::to_string(i) + " " + formatLength(from) + " - " + formatLength(to);
    const std::string share = percentOf(to - from, shadowDistance);
    const float line = ImGui::GetTextLineHeight();
    const ImU32 ink = IM_COL32(10, 10, 10, 255);
    list->PushClipRect(a, b, true);
    if (ImGui::CalcTextSize(range.c_str()).x + 6.0f <= b.x - a.x) {
        list->AddText({a.x + 3.0f, a.y + 1.0f}, ink, range.c_str());
        list->AddText({a.x + 3.0f, a.y + 1.0f + line}, ink, share.c_str());
    } else if (ImGui::CalcTextSize(share.c_str()).x + 4.0f <= b.x - a.x) {
        list->AddText({a.x + 2.0f, a.y + 1.0f}, ink, ("C" + std::to_string(i)).c_str());
        list->AddText({a.x + 2.0f, a.y + 1.0f + line}, ink, share.c_str());
    }
    list->PopClipRect();
    if (ImGui::IsMouseHoveringRect(a, b) && ImGui::IsWindowHovered())
        ImGui::SetTooltip("Cascade %d: view depth %s, %s of the shadow distance", i, range.substr(range.find(' ') + 1).c_str(),
                          share.c_str());
}

// Handle `index` between cascades index and index + 1; true when it was dragged this frame.
bool dragHandle(UiFrame& f, const Bar& bar, std::vector<float>& inner, int index) {
    const float x = bar.x(inner[static_cast<std::size_t>(index)]);
    ImGui::SetCursorScreenPos({x - 4.0f, bar.min.y});
    ImGui::PushID(index);
    ImGui::InvisibleButton("handle", {8.0f, bar.max.y - bar.min.y});
    ImGui::PopID();
    recordItem(f.state.rects, "splitBar.handle" + std::to_string(index));
    const bool hot = ImGui::IsItemActive() || ImGui::IsItemHovered();
    if (hot) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    ImDrawList* list = ImGui::GetWindowDrawList();
    list->AddRectFilled({x - 3.0f, bar.min.y - 2.0f}, {x + 3.0f, bar.max.y + 2.0f}, IM_COL32(20, 20, 20, 255));
    list->AddRectFilled({x - 1.5f, bar.min.y}, {x + 1.5f, bar.max.y}, hot ? IM_COL32(255, 255, 255, 255) : IM_COL32(200, 200, 200, 255));
    if (!ImGui::IsItemActive() || ImGui::GetIO().MouseDelta.x == 0.0f) return false;
    const float fraction = (ImGui::GetIO().MousePos.x - bar.min.x) / (bar.max.x - bar.min.x);
    inner[static_cast<std::size_t>(index)] = draggedSplit(inner, index, bar.nearDepth, bar.farDepth, fraction);
    return true;
}

void drawBar(UiFrame& f, const std::vector<float>& rendered) {
    std::vector<float> inner = innerSplits(f.s, rendered);
    const float nearDepth = rendered.front(), farDepth = rendered.back();
    if (inner.size() + 2 != rendered.size() || !(farDepth > nearDepth)) {
        ImGui::TextDisabled("Splits change with the cascade count: shown after the next frame.");
        return;
    }
    ImGui::Text("Splits %s - %s", formatLength(nearDepth).c_str(), formatLength(farDepth).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(drag a handle: manual splits, one undo step)");
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const Bar bar{origin, {origin.x + width, origin.y + ImGui::GetTextLineHeight() * 2.0f + 2.0f}, nearDepth, farDepth};
    ImDrawList* list = ImGui::GetWindowDrawList();
    for (std::size_t i = 0; i + 1 < rendered.size(); ++i) {
        const float from = i == 0 ? nearDepth : inner[i - 1];
        const float to = i + 1 == rendered.size() - 1 ? farDepth : inner[i];
        drawSegment(list, bar, int(i), from, to, farDepth);
    }
    ImGui::Dummy({width, bar.max.y - bar.min.y});
    recordItem(f.state.rects, "splitBar");
    bool dragged = false;
    for (int i = 0; i < int(inner.size()); ++i) dragged = dragHandle(f, bar, inner, i) || dragged;
    if (dragged) storeManualSplits(f, inner);
}

}  // namespace

void drawSplitBar(UiFrame& f) {
    if (f.state.layout.splitBar.empty()) return;
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;
    if (beginDockedPanel(f, Panel::SplitBar, "Cascade splits", nullptr, flags)) {
        if (f.in.stats && f.in.stats->splits.size() >= 2) drawBar(f, f.in.stats->splits);
        else ImGui::TextDisabled("Cascade splits appear after the first frame.");
    }
    ImGui::End();
}

}  // namespace st::ui
