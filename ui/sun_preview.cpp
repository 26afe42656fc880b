// "Animate sun" is a preview (issue 13 #4): stopping it puts the azimuth back where it was, and
// "Keep" stops it where it is, as one undo step.
#include "ui/document_actions.h"
#include "ui/field_widgets.h"
#include "ui/panels.h"

#include <imgui.h>

namespace st::ui {
namespace {

void startPreview(UiFrame& f) {
    f.state.animateSun = true;
    f.state.sunPreviewFrom = f.s.light.azimuth;
}

void stopPreview(UiFrame& f, bool keep) {
    f.state.animateSun = false;
    Settings before = f.s;
    before.light.azimuth = f.state.sunPreviewFrom;
    if (keep) {
        recordStep(f.state, before, f.s);
    } else if (const FieldInfo* azimuth = findField("light.azimuth")) {
        storeField(*azimuth, f.s, f.state.sunPreviewFrom);  // not an edit: no undo step
    }
}

}  // namespace

void drawSunAnimation(UiFrame& f) {
    bool on = f.state.animateSun;
    if (ImGui::Checkbox("Animate sun", &on)) on ? startPreview(f) : stopPreview(f, false);
    recordItem(f.state.rects, "sun.animate");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("A preview: unticked, the azimuth goes back; Keep keeps it.");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    ImGui::DragFloat("##sunSpeed", &f.state.sunDegPerSecond, 0.5f, -180.0f, 180.0f, "%.1f deg/s",
                     ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Azimuth turn rate while the sun is animated (not saved).");
    if (!f.state.animateSun) return;
    ImGui::SameLine();
    if (ImGui::SmallButton("Keep")) stopPreview(f, true);
    recordItem(f.state.rects, "sun.keep");
}

}  // namespace st::ui
