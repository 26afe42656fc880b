// The shadow-map viewer: one tile per cascade (textures from the app, depth already remapped for
// display) and a bigger window for the one clicked; with the atlas storage, the atlas itself.
#include "ui/field_rules.h"
#include "ui/layout.h"
#include "ui/legends.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace st::ui {
namespace {

// GL textures have texel row 0 at the bottom; ImGui's uv (0, 0) is the top left of the quad.
const ImVec2 kUvTopLeft{0.0f, 1.0f};
const ImVec2 kUvBottomRight{1.0f, 0.0f};

std::string tileTooltip(const UiFrame& f, int layer) {
    std::string text = "Cascade " + std::to_string(layer);
    const auto i = static_cast<std::size_t>(layer);
    if (i < f.in.shadowMapSizes.size()) text += ", " + std::to_string(f.in.shadowMapSizes[i]) + " texels per side";
    const FrameStats* stats = f.in.stats;
    if (stats && static_cast<std::size_t>(layer) < stats->cascades.size()) {
        const CascadeStats& c = stats->cascades[static_cast<std::size_t>(layer)];
        text += "\nview depth " + formatLength(c.vsNear) + " - " + formatLength(c.vsFar) + ", texel " +
                formatLength(c.texelWorldSize);
    }
    return text + "\nClick to zoom";
}

void drawTile(UiFrame& f, int layer, float size) {
    ImGui::PushID(layer);
    ImGui::BeginGroup();
    ImGui::Image(f.in.shadowLayers[static_cast<std::size_t>(layer)], ImVec2(size, size), kUvTopLeft,
                 kUvBottomRight, ImVec4(1, 1, 1, 1), ImVec4(0.5f, 0.5f, 0.5f, 1.0f));
    recordItem(f.state.rects, "shadow.tile" + std::to_string(layer));
    if (ImGui::IsItemClicked()) f.state.zoomLayer = layer;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tileTooltip(f, layer).c_str());
    const auto l = static_cast<std::size_t>(layer);
    const bool moments = l < f.in.shadowVariance.size();
    if (moments) {
        // A moment filter's tile shows the first moment as depth; its spread sits beside it.
        ImGui::SameLine();
        ImGui::Image(f.in.shadowVariance[l], ImVec2(size, size), kUvTopLeft, kUvBottomRight, ImVec4(1, 1, 1, 1),
                     ImVec4(0.5f, 0.5f, 0.5f, 1.0f));
        recordItem(f.state.rects, "shadow.variance" + std::to_string(layer));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Cascade %d: spread of the moments (standard deviation)", layer);
    }
    cascadeSwatch(layer);
    if (moments) {
        ImGui::SameLine(0.0f, 0.0f);
        ImGui::TextUnformatted(": mean depth | spread");
    }
    ImGui::EndGroup();
    ImGui::PopID();
}

// The largest square tile for which all `count` tiles (each with a caption line) fit in `avail`.
struct TileGrid {
    int columns = 1;
    float size = 0.0f;
};

TileGrid fitTiles(int count, ImVec2 avail) {
    const ImVec2 spacing = ImGui::GetStyle().ItemSpacing;
    const float caption = ImGui::GetTextLineHeightWithSpacing();
    TileGrid best;
    for (int columns = 1; columns <= count; ++columns) {
        const int rows = (count + columns - 1) / columns;
        const float byWidth = (avail.x - spacing.x * float(columns - 1)) / float(columns);
        const float byHeight = (avail.y - float(rows) * (caption + spacing.y)) / float(rows);
        const float size = std::min(byWidth, byHeight);
        if (size > best.size) best = {columns, size};
    }
    best.size = std::clamp(best.size, 24.0f, 512.0f);
    return best;
}

// The atlas as one image of its aspect, each tile outlined where it lies in the texture.
void drawAtlas(UiFrame& f) {
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float aspect = float(f.in.shadowAtlasHeight) / float(std::max(f.in.shadowAtlasWidth, 1));
    const float width = std::max(24.0f, std::min(avail.x, avail.y / std::max(aspect, 1e-3f)));
    ImGui::Image(f.in.shadowAtlas, ImVec2(width, width * aspect), kUvTopLeft, kUvBottomRight);
    recordItem(f.state.rects, "shadow.atlas");
    if (ImGui::IsItemHovered()) {
        std::string text = "Atlas " + std::to_string(f.in.shadowAtlasWidth) + "x" +
                           std::to_string(f.in.shadowAtlasHeight) + " texels, one tile per cascade:";
        for (std::size_t i = 0; i < f.in.shadowMapSizes.size(); ++i)
            text += (i == 0 ? " " : ", ") + std::to_string(f.in.shadowMapSizes[i]);
        ImGui::SetTooltip("%s", text.c_str());
    }
}

void drawTiles(UiFrame& f) {
    if (f.in.shadowAtlas) return drawAtlas(f);
    const int count = static_cast<int>(f.in.shadowLayers.size());
    if (count == 0) {
        ImGui::TextDisabled("No shadow maps yet.");
        return;
    }
    // A moment filter's layer is two images wide (mean depth and spread).
    const int wide = f.in.shadowVariance.empty() ? 1 : 2;
    TileGrid grid = fitTiles(count * wide, ImGui::GetContentRegionAvail());
    grid.columns = std::max(1, grid.columns / wide);
    for (int layer = 0; layer < count; ++layer) {
        if (layer % grid.columns != 0) ImGui::SameLine();
        drawTile(f, layer, grid.size);
    }
}

void drawZoomWindow(UiFrame& f) {
    const int layer = f.state.zoomLayer;
    if (layer < 0 || layer >= static_cast<int>(f.in.shadowLayers.size())) {
        f.state.zoomLayer = -1;
        return;
    }
    placeNextWindow(Panel::ShadowZoom);
    bool open = true;
    const std::string title = "Cascade " + std::to_string(layer) + "###shadowZoom";
    if (ImGui::Begin(title.c_str(), &open)) {
        const ImVec2 avail = ImGui::GetContentRegionAvail();
        const float side = std::max(16.0f, std::min(avail.x, avail.y));
        ImGui::Image(f.in.shadowLayers[static_cast<std::size_t>(layer)], ImVec2(side, side), kUvTopLeft, kUvBottomRight);
        recordItem(f.state.rects, "shadow.zoom");
    }
    ImGui::End();
    if (!open) f.state.zoomLayer = -1;
}

}  // namespace

void drawShadowViewer(UiFrame& f) {
    if (f.state.showShadowMaps) {
        if (beginDockedPanel(f, Panel::ShadowMaps, "Shadow maps", &f.state.showShadowMaps)) drawTiles(f);
        ImGui::End();
    }
    drawZoomWindow(f);
}

}  // namespace st::ui
