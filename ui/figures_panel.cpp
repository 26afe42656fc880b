#include "ui/figures_panel.h"

#include "ui/field_rules.h"
#include "ui/legends.h"
#include "renderer/render/frame_stats_text.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace st::ui {
namespace {

std::string splitList(const FrameStats& stats) {
    std::string text;
    for (const float split : stats.splits) text += (text.empty() ? "" : " | ") + formatLength(split);
    return text;
}

// Reach toward the sun beyond the slice, and the least that keeps every caster (the audit).
std::string zExtensionText(const CascadeStats& c) {
    const std::string minimal = formatLength(c.zExtensionMinimal);
    if (std::isinf(c.zExtensionUsed)) return "pancake / " + minimal;
    return formatLength(c.zExtensionUsed) + " / " + minimal;
}

// What the split scheme divided and, with depth bounds, the depths the camera saw.
std::string depthBoundsLine(const FrameStats& stats) {
    const DepthBoundsStats& d = stats.depthBounds;
    std::string text = "Depth bounds " + d.mode + ": splits divide " + formatLength(stats.splitBegin) + " - " +
                       formatLength(stats.splitEnd);
    if (d.reduced)
        text += d.seen ? "; seen " + formatLength(d.vsMin) + " - " + formatLength(d.vsMax) + " (" + d.source + ")"
                       : "; nothing seen (" + d.source + ")";
    return text;
}

void geometryRow(int index, const CascadeStats& c) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    cascadeSwatch(index);
    ImGui::TableNextColumn();
    ImGui::Text("%s - %s", formatLength(c.vsNear).c_str(), formatLength(c.vsFar).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%s x %s", formatLength(c.lsExtent.x).c_str(), formatLength(c.lsExtent.y).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%s", formatLength(c.lsExtent.z).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%s", formatLength(c.texelWorldSize).c_str());
    ImGui::TableNextColumn();
    if (c.zExtensionCuts)
        ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.2f, 1.0f), "%s!", zExtensionText(c).c_str());
    else
        ImGui::Text("%s", zExtensionText(c).c_str());
}

void costRow(int index, const CascadeStats& c) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    cascadeSwatch(index);
    ImGui::TableNextColumn();
    ImGui::Text("%d", c.casterDraws);
    ImGui::TableNextColumn();
    ImGui::Text("%zu", c.casterTriangles);
    ImGui::TableNextColumn();
    ImGui::Text("%zu", c.lowerBoundTriangles);
    ImGui::TableNextColumn();
    ImGui::Text("%zu / %zu", c.casterClusters, c.casterClustersTotal);
    ImGui::TableNextColumn();
    if (c.redrawn) ImGui::Text("%.2f ms", c.gpuMs);
    else ImGui::TextUnformatted("kept");  // no work this frame: its timer's 0 is no cost
    ImGui::TableNextColumn();
    ImGui::Text("%s: %s", c.redrawn ? "redrawn" : "cached", c.mapReason.c_str());
}

constexpr ImGuiTableFlags kTableFlags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;

void headers(std::initializer_list<const char*> names) {
    for (const char* name : names) ImGui::TableSetupColumn(name);
    ImGui::TableHeadersRow();
}

void geometryTable(const FrameStats& stats) {
    if (!ImGui::BeginTable("cascadeGeometry", 6, kTableFlags)) return;
    headers({"#", "view depth", "light box x*y", "z range", "texel", "z ext / min"});
    for (std::size_t i = 0; i < stats.cascades.size(); ++i) geometryRow(static_cast<int>(i), stats.cascades[i]);
    ImGui::EndTable();
}

void costTable(const FrameStats& stats) {
    if (!ImGui::BeginTable("cascadeCost", 7, kTableFlags)) return;
    headers({"#", "caster draws", "triangles", "lower bound", "clusters", "GPU", "map"});
    for (std::size_t i = 0; i < stats.cascades.size(); ++i) costRow(static_cast<int>(i), stats.cascades[i]);
    ImGui::EndTable();
}

void plot(const char* label, const History& history) {
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%.2f ms (mean %.2f)", history.latest(), history.mean());
    ImGui::PlotLines(label, history.data(), static_cast<int>(history.size()), static_cast<int>(history.offset()),
                     overlay, 0.0f, history.max() * 1.25f + 0.01f, ImVec2(0.0f, 42.0f));
}

}  // namespace

std::string drawAdvice(const std::vector<Advice>& advice, ItemRects& rects) {
    const ImVec4 colour{1.0f, 0.8f, 0.35f, 1.0f};
    std::string tune;
    for (const Advice& a : advice) {
        ImGui::PushStyleColor(ImGuiCol_Text, colour);
        ImGui::TextWrapped("Advice: %s", a.text.c_str());
        ImGui::PopStyleColor();
        recordItem(rects, "advice." + a.rule);
        ImGui::PushID(a.rule.c_str());
        if (ImGui::SmallButton("Tune for this")) tune = a.rule;
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open the Tune panel: search for the best settings within the current cost");
        recordItem(rects, "advice." + a.rule + ".tune");
        ImGui::PopID();
    }
    return tune;
}

std::string drawCascadeFigures(const Settings& s, const FrameStats* stats, ItemRects& rects) {
    ImGui::Separator();
    if (!stats) {
        ImGui::TextDisabled("No frame rendered yet: figures appear after the first frame.");
        return "";
    }
    ImGui::TextWrapped("Splits: %s", splitList(*stats).c_str());
    ImGui::TextWrapped("%s", depthBoundsLine(*stats).c_str());
    ImGui::Text("Shadow maps: %s   scene: %zu triangles", formatBytes(stats->shadowMapBytes).c_str(),
                stats->sceneTriangles);
    geometryTable(*stats);
    costTable(*stats);
    return drawAdvice(adviseFromFigures(s, *stats), rects);
}

void drawTimingPlots(const TimingHistory& timing, const FrameStats* stats) {
    if (stats) ImGui::Text("GPU: %s, main %.2f ms", shadowTimeText(*stats, 2).c_str(), stats->gpuMainMs);
    plot("GPU shadow", timing.gpuShadowMs);
    plot("GPU main", timing.gpuMainMs);
    plot("CPU frame", timing.cpuFrameMs);
}

void recordTimings(TimingHistory& timing, const FrameStats* stats, double cpuFrameMs) {
    timing.cpuFrameMs.push(static_cast<float>(cpuFrameMs));
    if (!stats) return;
    timing.gpuShadowMs.push(static_cast<float>(stats->gpuShadowMs));
    timing.gpuMainMs.push(static_cast<float>(stats->gpuMainMs));
}

}  // namespace st::ui
