// The modal asked before a map-size change that costs more than kAskAboveShadowBytes or
// kAskAboveRedrawMs (ui/map_cost.h), the pattern of confirm_modal.cpp: the settings panel holds
// the edit instead of applying it, this modal applies it as one undo step or drops it.
#include "ui/document_actions.h"
#include "ui/layout.h"
#include "ui/map_cost_confirm.h"
#include "ui/panels.h"

#include <imgui.h>

namespace st::ui {
namespace {

constexpr const char* kTitle = "Large shadow maps";

bool modalButton(UiFrame& f, const char* label, const char* key) {
    const bool pressed = ImGui::Button(label, ImVec2(110.0f, 0.0f));
    recordItem(f.state.rects, key);
    return pressed;
}

// `rendered`: the settings of the last frame (f.s already holds the edit being judged).
// A measured rate replaces a modelled one and is kept; the model stands in until one is measured.
std::optional<double> msPerTexel(UiFrame& f, const CascadeSettings& rendered) {
    MapCostAsk& ask = f.state.mapAsk;
    if (f.in.stats) {
        if (const auto measured = measuredMsPerTexel(*f.in.stats, rendered)) {
            ask.msPerTexel = measured;
            ask.modelled = false;
        } else if (const auto modelled = modelledMsPerTexel(*f.in.stats, rendered); modelled && (!ask.msPerTexel || ask.modelled)) {
            ask.msPerTexel = modelled;
            ask.modelled = true;
        }
    }
    return ask.msPerTexel;
}

// The last full-quality frame (not an interactive preview; the held image keeps its time): the
// whole-frame redraw is scaled from it.
std::optional<FrameBase> frameBase(UiFrame& f, const CascadeSettings& rendered) {
    MapCostAsk& ask = f.state.mapAsk;
    const SceneRenderFigures& scene = f.in.scene;
    if (scene.ms > 0.0 && scene.scale >= 1.0 && scene.mapSize == 0)
        ask.base = FrameBase{scene.ms, cascadeTexels(rendered)};
    return ask.base;
}

}  // namespace

bool holdExpensiveEdit(UiFrame& f, const FieldInfo& field, const Settings& before) {
    if (!affectsMapCost(field.path)) return false;
    const std::optional<double> rate = msPerTexel(f, before.cascades);
    const std::optional<FrameBase> base = frameBase(f, before.cascades);
    const MapCost after = mapCost(f.s.cascades, rate, f.state.mapAsk.modelled, base);
    if (!asksFirst(mapCost(before.cascades, rate, f.state.mapAsk.modelled, base), after)) return false;
    f.state.mapAsk.field = &field;
    f.state.mapAsk.value = field.get(f.s);
    f.state.mapAsk.question = costQuestion(f.s.cascades, after);
    f.state.mapAsk.open = true;
    f.s = before;
    return true;
}

void drawConfirmMapCost(UiFrame& f) {
    MapCostAsk& ask = f.state.mapAsk;
    if (ask.open) {
        ImGui::OpenPopup(kTitle);
        ask.open = false;
    }
    placeNextWindow(Panel::Confirm);
    if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    // Wrapped: with the first frame's cost the question runs to ~140 characters, wider than a
    // 1000 px window's scene.
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 32.0f);
    ImGui::TextUnformatted(ask.question.c_str());
    ImGui::PopTextWrapPos();
    recordItem(f.state.rects, "mapcost.question");
    ImGui::Spacing();
    if (modalButton(f, "Apply", "mapcost.apply") && ask.field) {
        // Applied to the settings as they are now (the sun may have moved meanwhile), not a snapshot.
        Settings after = f.s;
        ask.field->set(after, ask.value);
        applyEdit(f, std::move(after));
        ask.field = nullptr;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (modalButton(f, "Cancel", "mapcost.cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        ask.field = nullptr;
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

}  // namespace st::ui
