#include "ui/layout.h"

#include "ui/ui_state.h"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <string_view>
#include <string>

namespace st::ui {
namespace {

// Column limits: at 1000 px the scene keeps about 40 % of the width; below the minimum widths
// the columns' widgets stop being usable, so the scene shrinks instead.
constexpr float kMinLeft = 260.0f, kMaxLeftShare = 0.34f;
constexpr float kMinRight = 200.0f, kMaxRightShare = 0.26f;
constexpr float kMinBottom = 90.0f, kMaxBottomShare = 0.4f;
constexpr float kMinSceneShare = 0.34f;

Rect rect(float x0, float y0, float x1, float y1) { return {{x0, y0}, {x1, y1}}; }

float clampTo(float value, float lo, float hi) { return std::clamp(value, lo, std::max(lo, hi)); }

// Presets 34 %, Shadow maps 33 %, Side view 33 % of the right column; closed panels give their
// share to the ones still open.
void stackRight(Layout& l, float x0, float x1, float y0, float y1, PanelsShown shown) {
    const float weights[3] = {0.34f, shown.shadowMaps ? 0.33f : 0.0f, shown.sideView ? 0.33f : 0.0f};
    const float total = weights[0] + weights[1] + weights[2];
    Rect* slots[3] = {&l.presets, &l.shadowMaps, &l.sideView};
    float y = y0;
    for (int i = 0; i < 3; ++i) {
        if (weights[i] <= 0.0f) continue;
        const float h = (y1 - y0) * weights[i] / total;
        *slots[i] = rect(x0, y, x1, y + h);
        y += h;
    }
}

Rect centred(float width, float height) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const ImVec2 c{viewport->Pos.x + viewport->Size.x * 0.5f, viewport->Pos.y + viewport->Size.y * 0.5f};
    return rect(c.x - width * 0.5f, c.y - height * 0.5f, c.x + width * 0.5f, c.y + height * 0.5f);
}

// The user resized a docked window: keep the new column width or panel height. Only a drag of
// its edge does: ImGui also gives a window another size than the one placed when the display
// shrinks under it, and keeping that made the next launch cramped (issue 21 #5). What is kept
// is never below a column's minimum; the small window's squeeze is computeLayout's, per frame.
void takeBackSize(UiFrame& f, Panel panel, const Rect& placed) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) return;
    const ImVec2 size = ImGui::GetWindowSize();
    LayoutPrefs& p = f.state.prefs;
    switch (panel) {
        case Panel::Settings:
            if (size.x != placed.width()) p.leftWidth = std::max(size.x, kMinLeft);
            break;
        case Panel::Presets:
        case Panel::ShadowMaps:
        case Panel::SideView:
            if (size.x != placed.width()) p.rightWidth = std::max(size.x, kMinRight);
            break;
        case Panel::Accuracy:
            if (size.y != placed.height()) p.bottomHeight = std::max(size.y, kMinBottom);
            break;
        default: break;
    }
}

}  // namespace

const Rect& Layout::of(Panel panel) const {
    switch (panel) {
        case Panel::Settings: return settings;
        case Panel::Presets: return presets;
        case Panel::ShadowMaps: return shadowMaps;
        case Panel::SideView: return sideView;
        case Panel::Accuracy: return accuracy;
        case Panel::SplitBar: return splitBar;
        case Panel::Status: return status;
        default: return scene;
    }
}

Layout computeLayout(ImVec2 origin, ImVec2 size, const LayoutMetrics& m, const LayoutPrefs& prefs, PanelsShown shown) {
    Layout l;
    const float x0 = origin.x, x1 = origin.x + size.x;
    const float top = origin.y + m.menuBar, bottom = origin.y + size.y - m.statusBar;
    l.status = rect(x0, bottom, x1, origin.y + size.y);
    if (prefs.panelsHidden) {
        l.scene = rect(x0, top, x1, bottom);
        return l;
    }
    float left = clampTo(prefs.leftWidth, kMinLeft * m.scale, size.x * kMaxLeftShare);
    float right = clampTo(prefs.rightWidth, kMinRight * m.scale, size.x * kMaxRightShare);
    // A window below the supported 1000 px: the columns shrink together so the scene keeps a
    // third of the width rather than vanishing under them.
    if (const float room = size.x * (1.0f - kMinSceneShare); left + right > room) {
        const float scale = room / (left + right);
        left *= scale;
        right *= scale;
    }
    const float cx0 = x0 + left, cx1 = x1 - right;
    l.settings = rect(x0, top, cx0, bottom);
    stackRight(l, cx1, x1, top, bottom, shown);
    float sceneBottom = bottom;
    if (shown.accuracy) {
        const float h = clampTo(prefs.bottomHeight, kMinBottom * m.scale, (bottom - top) * kMaxBottomShare);
        l.accuracy = rect(cx0, bottom - h, cx1, bottom);
        sceneBottom -= h;
    }
    l.splitBar = rect(cx0, sceneBottom - m.splitBar, cx1, sceneBottom);
    l.scene = rect(cx0, top, cx1, sceneBottom - m.splitBar);
    return l;
}

float uiScaleFor(int height, const char* override) {
    if (override && *override) {
        char* end = nullptr;
        const float v = std::strtof(override, &end);
        if (end != override && *end == '\0' && v >= 1.0f && v <= 3.0f) return v;
    }
    return height > 2000 ? 2.0f : height > 1440 ? 1.5f : 1.0f;
}

LayoutPrefs scaledDefaults(float scale) {
    LayoutPrefs p;
    p.leftWidth *= scale;
    p.rightWidth *= scale;
    p.bottomHeight *= scale;
    return p;
}

LayoutMetrics currentLayoutMetrics() {
    LayoutMetrics m;
    m.scale = ImGui::GetFontSize() / 13.0f;  // ImGui's default font: 13 px
    const ImGuiStyle& style = ImGui::GetStyle();
    m.menuBar = ImGui::GetFrameHeight();
    // ImGui grows any window to WindowMinSize: a shorter bar would overlap the panels above.
    m.statusBar = std::max(style.WindowMinSize.y, ImGui::GetTextLineHeight() + 2.0f * style.WindowPadding.y);
    // Two text lines of labels over the bar itself, inside the window padding.
    m.splitBar = ImGui::GetTextLineHeight() * 2.0f + ImGui::GetFrameHeight() + style.ItemSpacing.y * 2.0f +
                 style.WindowPadding.y * 2.0f;
    return m;
}

bool beginDockedPanel(UiFrame& f, Panel panel, const char* name, bool* open, ImGuiWindowFlags flags) {
    const Rect& placed = f.state.layout.of(panel);
    ImGui::SetNextWindowPos(placed.min, ImGuiCond_Always);
    ImGui::SetNextWindowSize({placed.width(), placed.height()}, ImGuiCond_Always);
    const bool visible = ImGui::Begin(name, open, flags | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                                      ImGuiWindowFlags_NoSavedSettings);
    takeBackSize(f, panel, placed);
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    // Reported by its ID ("Title###ID": the ID, a title that changes with what it shows does not move the key).
    const std::string_view full(name);
    const std::string_view id = full.find("###") == std::string_view::npos ? full : full.substr(full.find("###") + 3);
    f.state.rects["window." + std::string(id)] = {pos, {pos.x + size.x, pos.y + size.y}};
    return visible;
}

void placeOverRightColumn(const UiFrame& f, float width) {
    const Layout& l = f.state.layout;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float top = l.scene.min.y, bottom = l.status.empty() ? display.y : l.status.min.y;
    const float w = std::min(std::max(width * currentLayoutMetrics().scale, l.presets.width()), display.x * 0.5f);
    ImGui::SetNextWindowPos({display.x - w, top}, ImGuiCond_Appearing);
    ImGui::SetNextWindowSize({w, std::max(200.0f, bottom - top)}, ImGuiCond_Appearing);
}

void placeNextWindow(Panel panel) {
    Rect area;
    switch (panel) {
        case Panel::ShadowZoom: area = centred(560.0f, 600.0f); break;
        case Panel::Help: area = centred(460.0f, 330.0f); break;
        default: area = centred(380.0f, 0.0f); break;
    }
    const ImGuiCond cond = panel == Panel::Confirm ? ImGuiCond_Appearing : ImGuiCond_FirstUseEver;
    ImGui::SetNextWindowPos(area.min, cond);
    if (area.height() > 0.0f) ImGui::SetNextWindowSize({area.width(), area.height()}, cond);
}

}  // namespace st::ui
