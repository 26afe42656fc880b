#include "ui/legends.h"

#include "renderer/render/cascade_tints.h"
#include "ui/field_rules.h"
#include "ui/panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace st::ui {
namespace {

float encodeSrgb(float linear) { return std::pow(std::clamp(linear, 0.0f, 1.0f), 1.0f / 2.2f); }

ImVec4 lerp(ImVec4 a, ImVec4 b, float t) {
    return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t, 1.0f};
}

std::string tickLabel(float ppt) {
    char text[16];
    if (ppt < 1.0f) std::snprintf(text, sizeof text, "1/%.0f", 1.0f / ppt);
    else std::snprintf(text, sizeof text, "%.0f", ppt);
    return text;
}

const ImU32 kBackdrop = IM_COL32(15, 15, 15, 200);
const ImU32 kText = IM_COL32(240, 240, 240, 255);

ItemRect asItem(const Rect& r) { return {r.min, r.max}; }

}  // namespace

ImVec4 cascadeColour(int cascade) {
    const LinearRgb t = cascadeTintOf(cascade);
    return {encodeSrgb(t.r), encodeSrgb(t.g), encodeSrgb(t.b), 1.0f};
}

ImVec4 texelDensityColour(float pixelsPerTexel) {
    const float v = std::clamp(std::log2(std::max(pixelsPerTexel, 1e-12f)) / 4.0f, -1.0f, 1.0f);
    const ImVec4 green{0.0f, 0.8f, 0.1f, 1.0f}, blue{0.1f, 0.2f, 1.0f, 1.0f}, red{1.0f, 0.1f, 0.0f, 1.0f};
    const ImVec4 linear = v < 0.0f ? lerp(green, blue, -v) : lerp(green, red, v);
    return {encodeSrgb(linear.x), encodeSrgb(linear.y), encodeSrgb(linear.z), 1.0f};
}

void cascadeSwatch(int cascade) {
    const float side = ImGui::GetTextLineHeight();
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImGui::GetWindowDrawList()->AddRectFilled(p, {p.x + side, p.y + side}, ImGui::GetColorU32(cascadeColour(cascade)));
    ImGui::Dummy({side, side});
    ImGui::SameLine(0.0f, 4.0f);
    ImGui::Text("C%d", cascade);
}

void cascadeKey(int count) {
    ImGui::TextUnformatted("Cascades:");
    for (int i = 0; i < count; ++i) {
        ImGui::SameLine();
        cascadeSwatch(i);
    }
}

// A swatch and a label per cascade, under an optional title line.
static Rect drawLabelledCascadeLegend(ImDrawList* list, const Rect& scene, const std::vector<std::string>& labels,
                                       const std::string& title) {
    const float line = ImGui::GetTextLineHeight(), pad = 6.0f;
    float text = title.empty() ? 0.0f : ImGui::CalcTextSize(title.c_str()).x - line - 4.0f;
    for (const std::string& l : labels) text = std::max(text, ImGui::CalcTextSize(l.c_str()).x);
    const float width = std::min(pad * 2.0f + text + line + 4.0f, scene.width() - 2.0f * pad);
    const float top = title.empty() ? 0.0f : line + 2.0f;
    const Rect r{{scene.max.x - width - pad, scene.min.y + pad},
                 {scene.max.x - pad, scene.min.y + pad * 2.0f + top + float(labels.size()) * (line + 2.0f)}};
    list->AddRectFilled(r.min, r.max, kBackdrop, 3.0f);
    list->PushClipRect(r.min, r.max, true);
    if (!title.empty()) list->AddText({r.min.x + pad, r.min.y + pad}, kText, title.c_str());
    for (std::size_t i = 0; i < labels.size(); ++i) {
        const ImVec2 p{r.min.x + pad, r.min.y + pad + top + float(i) * (line + 2.0f)};
        list->AddRectFilled(p, {p.x + line, p.y + line}, ImGui::GetColorU32(cascadeColour(int(i))));
        list->AddText({p.x + line + 4.0f, p.y}, kText, labels[i].c_str());
    }
    list->PopClipRect();
    return r;
}

static std::vector<std::string> cascadeNames(int count) {
    std::vector<std::string> out;
    for (int i = 0; i < count; ++i) out.push_back("C" + std::to_string(i));
    return out;
}

Rect drawCascadeLegend(ImDrawList* list, const Rect& scene, int count) {
    return drawLabelledCascadeLegend(list, scene, cascadeNames(count), {});
}

// Texel-grid view: what one checker square covers in each cascade, from the frame's texel sizes.
static std::vector<std::string> blockSizes(const UiFrame& f, int count) {
    std::vector<std::string> out;
    for (int i = 0; i < count; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const bool known = f.in.stats && k < f.in.stats->cascades.size();
        char text[64];
        if (known)
            std::snprintf(text, sizeof text, "C%d  %s", i,
                          formatLength(f.in.stats->cascades[k].texelWorldSize * float(f.s.output.texelBlock)).c_str());
        else
            std::snprintf(text, sizeof text, "C%d", i);
        out.push_back(text);
    }
    return out;
}

Rect drawDensityLegend(ImDrawList* list, const Rect& scene) {
    const float line = ImGui::GetTextLineHeight(), pad = 6.0f;
    const float barWidth = std::min(260.0f, scene.width() - 4.0f * pad);
    const char* title = "screen px per shadow texel (log scale; green = 1)";
    const float width = std::max(barWidth, std::min(ImGui::CalcTextSize(title).x, scene.width() - 4.0f * pad));
    const Rect r{{scene.max.x - width - 3.0f * pad, scene.max.y - pad * 3.0f - line * 3.0f},
                 {scene.max.x - pad, scene.max.y - pad}};
    list->AddRectFilled(r.min, r.max, kBackdrop, 3.0f);
    list->PushClipRect(r.min, r.max, true);
    list->AddText({r.min.x + pad, r.min.y + pad}, kText, title);
    const float x0 = r.min.x + pad, y0 = r.min.y + pad + line + 2.0f, y1 = y0 + line;
    // log2(ppt) runs -4..4 across the bar, as the shader's clamp.
    constexpr int kSteps = 64;
    for (int i = 0; i < kSteps; ++i) {
        const float a = float(i) / kSteps, b = float(i + 1) / kSteps;
        const float ppt = std::exp2(-4.0f + 8.0f * (a + b) * 0.5f);
        list->AddRectFilled({x0 + barWidth * a, y0}, {x0 + barWidth * b + 0.5f, y1}, ImGui::GetColorU32(texelDensityColour(ppt)));
    }
    for (const float tick : kDensityTicks) {
        const float x = x0 + barWidth * (std::log2(tick) + 4.0f) / 8.0f;
        const std::string label = tickLabel(tick);
        const float w = ImGui::CalcTextSize(label.c_str()).x;
        list->AddLine({x, y0}, {x, y1 + 2.0f}, kText);
        list->AddText({std::clamp(x - w * 0.5f, x0, x0 + barWidth - w), y1 + 2.0f}, kText, label.c_str());
    }
    list->PopClipRect();
    return r;
}

}  // namespace st::ui

namespace st::ui {

// The legend of the view the scene shows (the preset's debug view), in its top-right corner for
// the cascade key and its bottom-right corner for the density bar.
void drawSceneLegends(UiFrame& f) {
    const Rect& scene = f.state.layout.scene;
    if (scene.width() < 120.0f || scene.height() < 80.0f) return;
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    const int count = f.in.stats ? static_cast<int>(f.in.stats->cascades.size()) : f.s.cascades.count;
    // Swapped (Tab), the scene viewport shows the side camera's wireframes: their key goes with them.
    if (f.s.output.view == View::Cascades || f.in.sideViewSwapped)
        f.state.rects["legend.cascades"] = asItem(drawCascadeLegend(list, scene, count));
    if (f.in.sideViewSwapped) return;  // the view's own legends belong to the small picture now
    if (f.s.output.view == View::TexelGrid)
        f.state.rects["legend.texelGrid"] = asItem(drawLabelledCascadeLegend(
            list, scene, blockSizes(f, count), "square = " + std::to_string(f.s.output.texelBlock) + " texels:"));
    if (f.s.output.view == View::TexelDensity) f.state.rects["legend.density"] = asItem(drawDensityLegend(list, scene));
}

}  // namespace st::ui
