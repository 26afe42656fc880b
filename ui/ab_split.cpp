// A/B comparison: "Set as A" snapshots the settings; the split view shows A left of a draggable
// divider and the live settings right (the app renders both), each half labelled with its
// accuracy and cost. The Compare menu, its shortcuts and the divider live here.
#include "ui/document_actions.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace st::ui {

namespace {

// GLFW key codes as imgui_impl_glfw 1.86 writes them into io.KeysDown (see ShortcutKeys).
constexpr int kKeyA = 65;
constexpr int kKeyB = 66;

}  // namespace

void setAsA(UiFrame& f) {
    f.state.compare.a = f.s;
    f.state.compare.split = true;
}

void toggleSplit(UiFrame& f) {
    if (!f.state.compare.a) f.state.compare.a = f.s;  // nothing to compare with yet: A = now
    f.state.compare.split = !f.state.compare.split;
}

namespace {

void compareMenu(UiFrame& f) {
    if (!ImGui::BeginMainMenuBar()) return;  // appends to the menu bar of drawMenuBar()
    const bool open = ImGui::BeginMenu("Compare");
    recordItem(f.state.rects, "menu.compare");
    if (open) {
        if (ImGui::MenuItem("Set as A", "Ctrl+Shift+A")) setAsA(f);
        recordItem(f.state.rects, "menu.compare.setA");
        if (ImGui::MenuItem("Split A | live", "Ctrl+Shift+B", f.state.compare.split)) toggleSplit(f);
        recordItem(f.state.rects, "menu.compare.split");
        if (ImGui::MenuItem("Forget A", nullptr, false, f.state.compare.a.has_value())) {
            f.state.compare.a.reset();
            f.state.compare.split = false;
        }
        ImGui::Separator();
        ImGui::MenuItem("Sweep panel", nullptr, &f.state.compare.showSweep);
        recordItem(f.state.rects, "menu.compare.sweep");
        ImGui::MenuItem("Tune panel", nullptr, &f.state.tune.show);
        recordItem(f.state.rects, "menu.compare.tune");
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void shortcuts(UiFrame& f) {
    const ImGuiIO& io = ImGui::GetIO();
    if (!io.KeyCtrl || !io.KeyShift || io.WantTextInput || ImGui::IsAnyItemActive()) return;
    if (ImGui::IsKeyPressed(kKeyA, false)) setAsA(f);
    if (ImGui::IsKeyPressed(kKeyB, false)) toggleSplit(f);
}

std::string accuracyText(const AccuracyView& a) {
    char text[96];
    switch (a.state) {
    case AccuracyView::State::Off: return "accuracy: open its panel";
    case AccuracyView::State::Settling: return "accuracy: settling";
    case AccuracyView::State::Computing:
        std::snprintf(text, sizeof text, "accuracy: %.0f%%", 100.0 * a.progress);
        return text;
    case AccuracyView::State::Failed: return "accuracy failed";
    case AccuracyView::State::Done:
        std::snprintf(text, sizeof text, "%.3f%% misclass.", 100.0 * a.all.share(a.all.misclassified()));
        return text;
    }
    return "";
}

std::string costText(const FrameStats* s) {
    if (!s) return "model - ms, - MiB";
    // The modelled cost first: it is the same every frame; the timers beside it are not.
    char text[128];
    // The model prices the frame at the size it was drawn (the Tune panel's budget is priced at the
    // tune's size): the size goes with the figure. The timers are every pass of the last frame drawn.
    const double timed = s->gpuShadowMs + s->gpuFilterMs + s->gpuDepthBoundsMs + s->gpuMainMs;
    if (s->modelMs >= 0.0)
        std::snprintf(text, sizeof text, "modelled %.1f ms at %dx%d, %.1f MiB; timed %.1f ms", s->modelMs, s->width, s->height,
                      double(s->shadowMapBytes) / (1024.0 * 1024.0), timed);
    else
        std::snprintf(text, sizeof text, "timed %.1f ms (shadow %.1f, main %.1f), %.1f MiB", timed, s->gpuShadowMs, s->gpuMainMs,
                      double(s->shadowMapBytes) / (1024.0 * 1024.0));
    return text;
}

// A label box whose right (A) or left (live) edge is at x, moved inside the scene viewport when
// the divider is near its edge (a panel covered "live: 1.089 ..." there, issue 21 #10), and below
// `other` when that puts it over the other label.
Rect label(UiFrame& f, const std::string& key, float x, float y, bool rightAligned, ImU32 accent,
           const std::string& name, const AccuracyView& a, const FrameStats* s, const Rect* other = nullptr) {
    const std::string l1 = name + ": " + accuracyText(a), l2 = costText(s);
    const ImVec2 pad{6.0f, 4.0f};
    const float w = std::max(ImGui::CalcTextSize(l1.c_str()).x, ImGui::CalcTextSize(l2.c_str()).x) + 2.0f * pad.x;
    const float h = 2.0f * ImGui::GetTextLineHeightWithSpacing() + pad.y;
    const Rect& scene = f.state.layout.scene;
    constexpr float kInset = 4.0f;
    const float x0 = std::clamp(rightAligned ? x - w : x, scene.min.x + kInset, std::max(scene.min.x + kInset, scene.max.x - kInset - w));
    if (other && Rect{{x0, y}, {x0 + w, y + h}}.overlaps(*other)) y = other->max.y + kInset;
    const ImVec2 min{x0, y}, max{min.x + w, y + h};
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->AddRectFilled(min, max, IM_COL32(0, 0, 0, 170), 3.0f);
    dl->AddRect(min, max, accent, 3.0f);
    dl->AddText({min.x + pad.x, min.y + pad.y}, IM_COL32_WHITE, l1.c_str());
    dl->AddText({min.x + pad.x, min.y + pad.y + ImGui::GetTextLineHeightWithSpacing()}, IM_COL32_WHITE, l2.c_str());
    f.state.rects[key] = {min, max};
    return {min, max};
}

// The divider: a thin window (so the app's camera does not take the drag) with a grip to drag.
void divider(UiFrame& f) {
    CompareUiState& c = f.state.compare;
    // The split divides the scene viewport the panels leave, not the window.
    const Rect& scene = f.state.layout.scene;
    const float left = scene.min.x, width = scene.width();
    const float top = scene.min.y, bottom = scene.min.y + scene.height();
    const float x = left + c.divider * width;
    constexpr float kGrip = 12.0f;
    ImGui::SetNextWindowPos({x - kGrip * 0.5f, top});
    ImGui::SetNextWindowSize({kGrip, std::max(bottom - top, 16.0f)});
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                                       ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus;
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0.0f, 0.0f});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, {1.0f, 1.0f});  // the default 32 px would off-centre the grip
    bool active = false;
    if (ImGui::Begin("##abDivider", nullptr, flags)) {
        ImGui::InvisibleButton("abDividerGrip", ImGui::GetContentRegionAvail());
        recordItem(f.state.rects, "ab.divider");
        if (ImGui::IsItemHovered() || ImGui::IsItemActive()) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
        active = ImGui::IsItemActive();
        if (active && width > 0.0f) c.divider = std::clamp((ImGui::GetIO().MousePos.x - left) / width, 0.02f, 0.98f);
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
    ImGui::GetBackgroundDrawList()->AddLine({x, top}, {x, bottom}, active ? IM_COL32(255, 220, 80, 255) : IM_COL32_WHITE, 2.0f);
    const float y = top + 8.0f;
    const Rect a = label(f, "ab.labelA", x - 10.0f, y, true, IM_COL32(80, 200, 255, 255), "A", f.in.ab.accuracy, f.in.ab.stats);
    label(f, "ab.labelLive", x + 10.0f, y, false, IM_COL32(80, 220, 90, 255), "live", f.in.accuracy, f.in.stats, &a);
}

}  // namespace

void drawCompare(UiFrame& f) {
    shortcuts(f);
    compareMenu(f);
    CompareUiState& c = f.state.compare;
    if (c.a) f.req.abSettings = &*c.a;
    if (c.split && c.a) {
        divider(f);
        f.req.abSplit = true;
        f.req.abDivider = c.divider;
    }
    drawSweepPanel(f);
    drawTunePanel(f);
}

}  // namespace st::ui
