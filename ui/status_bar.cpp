// The status bar along the bottom of the window: the frame rate, the scene viewport's size and
// how to get the panels back when they are hidden. (The app's status line stays in the Presets
// panel, next to the preset it is about.)
#include "ui/status_bar.h"

#include "ui/layout.h"
#include "ui/panels.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace st::ui {

std::string frameRateText(const History& cpuFrameMs) {
    const float medianMs = cpuFrameMs.recentMedian(kFpsFrames);
    if (cpuFrameMs.size() == 0 || medianMs <= 0.0f) return "-- fps";
    char text[48];
    std::snprintf(text, sizeof text, "%.1f fps (%.1f ms)", 1000.0 / double(medianMs), double(medianMs));
    return text;
}

std::string saveSizeText(int outputWidth, int outputHeight, float sceneWidth, float sceneHeight) {
    char text[128];
    if (outputWidth == int(std::lround(sceneWidth)) && outputHeight == int(std::lround(sceneHeight)))
        std::snprintf(text, sizeof text, "saves render at %d x %d, as shown", outputWidth, outputHeight);
    else
        std::snprintf(text, sizeof text, "saves render at %d x %d (the preset's output size; framing differs)", outputWidth,
                      outputHeight);
    return text;
}

std::string sceneRenderText(const SceneRenderFigures& scene) {
    if (scene.ms <= 0.0) return "render --";
    char text[96];
    if (scene.reused) std::snprintf(text, sizeof text, "image reused (rendered in %.0f ms)", scene.ms);
    else if (scene.mapSize > 0)
        std::snprintf(text, sizeof text, "render %.0f ms (interactive: %.0f %%, maps %d, far ones staggered)", scene.ms, 100.0 * scene.scale, scene.mapSize);
    else std::snprintf(text, sizeof text, "render %.0f ms", scene.ms);
    return text;
}

std::string sceneRenderBrief(const SceneRenderFigures& scene) {
    if (scene.ms <= 0.0) return "render --";
    char text[64];
    if (scene.reused) std::snprintf(text, sizeof text, "reused (%.0f ms)", scene.ms);
    else if (scene.mapSize > 0) std::snprintf(text, sizeof text, "render %.0f ms (%.0f %%, maps %d)", scene.ms, 100.0 * scene.scale, scene.mapSize);
    else std::snprintf(text, sizeof text, "render %.0f ms", scene.ms);
    return text;
}

std::string saveSizeBrief(int outputWidth, int outputHeight, float sceneWidth, float sceneHeight) {
    char text[80];
    const bool asShown = outputWidth == int(std::lround(sceneWidth)) && outputHeight == int(std::lround(sceneHeight));
    std::snprintf(text, sizeof text, asShown ? "saves at %d x %d, as shown" : "saves at %d x %d (framing differs)", outputWidth,
                  outputHeight);
    return text;
}

std::vector<std::string> fitStatusItems(const std::vector<StatusItem>& items, float width, float spacing,
                                        const std::function<float(const std::string&)>& textWidth) {
    std::vector<std::string> shown;
    for (const StatusItem& item : items) shown.push_back(item.full);
    const auto lineWidth = [&] {
        float w = 0.0f;
        int n = 0;
        for (const std::string& text : shown)
            if (!text.empty()) w += textWidth(text) + (n++ > 0 ? spacing : 0.0f);
        return w;
    };
    for (std::size_t i = items.size(); i-- > 0 && lineWidth() > width;) shown[i] = items[i].brief;
    for (std::size_t i = items.size(); i-- > 1 && lineWidth() > width;) shown[i].clear();
    return shown;
}

namespace {

enum StatusPiece { Fps, SceneRender, SceneSize, SaveSize, Hint, kPieces };

std::vector<StatusItem> statusItems(const UiFrame& f) {
    const Rect& scene = f.state.layout.scene;
    char size[48];
    std::snprintf(size, sizeof size, "%.0f x %.0f px", double(scene.width()), double(scene.height()));
    const std::string fps = frameRateText(f.state.timing.cpuFrameMs);
    const char* hint = f.state.prefs.panelsHidden ? "H: show panels" : "H: hide panels";
    const int w = f.s.output.width, h = f.s.output.height;
    return {{fps, fps},
            {sceneRenderText(f.in.scene), sceneRenderBrief(f.in.scene)},
            {std::string("scene ") + size, size},
            {saveSizeText(w, h, scene.width(), scene.height()), saveSizeBrief(w, h, scene.width(), scene.height())},
            {hint, hint}};
}

}  // namespace

void drawStatusBar(UiFrame& f) {
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (beginDockedPanel(f, Panel::Status, "##status", nullptr, flags)) {
        static constexpr const char* keys[kPieces] = {"status.fps", "status.sceneRender", "status.sceneSize", "status.saveSize",
                                                      "status.hint"};
        constexpr float spacing = 24.0f;
        const std::vector<StatusItem> items = statusItems(f);
        const std::vector<std::string> shown = fitStatusItems(
            items, ImGui::GetContentRegionAvail().x, spacing, [](const std::string& t) { return ImGui::CalcTextSize(t.c_str()).x; });
        bool shortened = false, first = true, saveHovered = false;
        for (int i = 0; i < kPieces; ++i) {
            shortened = shortened || shown[std::size_t(i)] != items[std::size_t(i)].full;
            if (shown[std::size_t(i)].empty()) continue;
            if (!first) ImGui::SameLine(0.0f, spacing);
            first = false;
            const char* text = shown[std::size_t(i)].c_str();
            if (i == SaveSize || i == Hint) ImGui::TextDisabled("%s", text);
            else ImGui::TextUnformatted(text);
            recordItem(f.state.rects, keys[i]);
            if (i == SaveSize && ImGui::IsItemHovered()) {
                saveHovered = true;
                ImGui::SetTooltip("`shadowtune render` of the saved preset draws Output > width x height, not this view's size.");
            }
        }
        // A narrow window shortens the line: the whole of it is a hover away.
        if (shortened && !saveHovered && ImGui::IsWindowHovered()) {
            ImGui::BeginTooltip();
            for (const StatusItem& item : items) ImGui::TextUnformatted(item.full.c_str());
            ImGui::EndTooltip();
        }
    }
    ImGui::End();
}

}  // namespace st::ui
