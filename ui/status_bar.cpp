// The status bar along the bottom of the window: the frame rate, the scene viewport's size and
// how to get the panels back when they are hidden. (The app's status line stays in the Presets
// panel, next to the preset it is about.)
#include "ui/status_bar.h"

#include "ui/layout.h"
#include "ui/panels.h"

#include <imgui.h>

#include <cmath>
#include <cstdio>

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

void drawStatusBar(UiFrame& f) {
    constexpr ImGuiWindowFlags flags = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                       ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoFocusOnAppearing |
                                       ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (beginDockedPanel(f, Panel::Status, "##status", nullptr, flags)) {
        ImGui::TextUnformatted(frameRateText(f.state.timing.cpuFrameMs).c_str());
        recordItem(f.state.rects, "status.fps");
        ImGui::SameLine(0.0f, 24.0f);
        ImGui::TextUnformatted(sceneRenderText(f.in.scene).c_str());
        recordItem(f.state.rects, "status.sceneRender");
        const Rect& scene = f.state.layout.scene;
        ImGui::SameLine(0.0f, 24.0f);
        ImGui::Text("scene %.0f x %.0f px", double(scene.width()), double(scene.height()));
        ImGui::SameLine(0.0f, 24.0f);
        ImGui::TextDisabled("%s", saveSizeText(f.s.output.width, f.s.output.height, scene.width(), scene.height()).c_str());
        recordItem(f.state.rects, "status.saveSize");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("`shadowtune render` of the saved preset draws Output > width x height, not this view's size.");
        ImGui::SameLine(0.0f, 24.0f);
        ImGui::TextDisabled(f.state.prefs.panelsHidden ? "H: show panels" : "H: hide panels");
    }
    ImGui::End();
}

}  // namespace st::ui
