// The Accuracy panel: the ground truth of the frame on screen, computed by the app in the
// background once the camera and settings are still, and the toggle of its error overlay.
#include "ui/figures_panel.h"
#include "ui/ui_colours.h"
#include "ui/layout.h"
#include "ui/legends.h"
#include "ui/panels.h"

#include <imgui.h>

#include <cstdio>
#include <string>
#include <utility>

namespace st::ui {
namespace {

// The overlay's gross colours (metrics/metric_images.cpp): magenta and cyan, which no cascade tint
// (red, green, blue, yellow) nor the texel-density ramp (blue .. green .. red) uses.
const ImVec4 kFalseShadowColour{235 / 255.0f, 60 / 255.0f, 215 / 255.0f, 1.0f};
const ImVec4 kFalseLightColour{0 / 255.0f, 205 / 255.0f, 215 / 255.0f, 1.0f};

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f%%", 100.0 * share);
    return text;
}

void cell(const std::string& text) {
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(text.c_str());
}

// cascade < 0: the row is labelled `label`, else with the cascade's colour swatch.
void countsRow(int cascade, const char* label, const AccuracyCounts& c) {
    ImGui::TableNextRow();
    if (cascade >= 0) {
        ImGui::TableNextColumn();
        cascadeSwatch(cascade);
    } else {
        cell(label);
    }
    cell(std::to_string(c.receivers));
    cell(percent(c.share(c.misclassified())));
    cell(percent(c.share(c.falseShadow())));
    cell(percent(c.share(c.falseLight())));
    cell(std::to_string(c.gross()));
    char filtered[32];
    std::snprintf(filtered, sizeof filtered, "%.4f", c.filteredError);
    cell(filtered);
}

void cascadeTable(UiFrame& f) {
    const AccuracyView& a = f.in.accuracy;
    // Wider than a narrow panel (1000x700 clipped its headers to "fal" and "g f"): it scrolls
    // sideways, which needs its height given: the rows, the header and the scrollbar.
    constexpr ImGuiTableFlags flags =
        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
    const ImGuiStyle& style = ImGui::GetStyle();
    const int rows = static_cast<int>(a.cascades.size()) + (a.beyond.receivers > 0 ? 1 : 0) + 1;
    const float height = float(rows) * (ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y) + style.ScrollbarSize + 2.0f;
    if (!ImGui::BeginTable("accuracyCascades", 7, flags, {0.0f, height})) return;
    for (const char* name : {"", "sun-facing px", "misclass.", "false shadow", "false light", "gross px", "filtered"})
        ImGui::TableSetupColumn(name);
    ImGui::TableSetupScrollFreeze(1, 0);  // the cascade's swatch stays while the figures scroll
    ImGui::TableHeadersRow();
    for (std::size_t i = 0; i < a.cascades.size(); ++i) countsRow(static_cast<int>(i), "", a.cascades[i]);
    if (a.beyond.receivers > 0) countsRow(-1, "beyond", a.beyond);
    ImGui::EndTable();
    recordItem(f.state.rects, "accuracy.cascades");
}

// The artifacts.png colours of `measure` (metrics/metric_images.cpp).
const ImVec4 kAcneColour{235 / 255.0f, 25 / 255.0f, 25 / 255.0f, 1.0f};
const ImVec4 kBleedingColour{1.0f, 150 / 255.0f, 0.0f, 1.0f};
const ImVec4 kPeterPanningColour{225 / 255.0f, 40 / 255.0f, 225 / 255.0f, 1.0f};
const ImVec4 kMissingColour{60 / 255.0f, 110 / 255.0f, 255 / 255.0f, 1.0f};

// The overlay's and artifacts.png's colours name the figures they show.
const ImVec4* colourOf(const std::string& key) {
    if (key == "accuracy.falseShadow") return &kFalseShadowColour;
    if (key == "accuracy.falseLight") return &kFalseLightColour;
    if (key == "soft.acne") return &kAcneColour;
    if (key == "soft.lightBleeding") return &kBleedingColour;
    if (key == "soft.peterPanning") return &kPeterPanningColour;
    if (key == "soft.missingCaster") return &kMissingColour;
    return nullptr;
}

bool isSoft(const FigureLine& l) { return l.key.rfind("soft.", 0) == 0; }

// The table's lines of one group (soft or not); hover: the figure's description.
void figureLines(const AccuracyView& a, bool soft) {
    for (const FigureLine& l : a.figures) {
        if (isSoft(l) != soft) continue;
        const std::string text = l.label + " " + l.value;
        if (const ImVec4* colour = colourOf(l.key)) ImGui::TextColored(*colour, "%s", text.c_str());
        else ImGui::TextUnformatted(text.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", l.description.c_str());
    }
}

void softFigures(UiFrame& f) {
    const SoftAccuracyCounts& k = f.in.accuracy.soft;
    ImGui::Separator();
    ImGui::TextUnformatted("Filtered, against the sun's disc");
    ImGui::Text("%.2f deg sun, %d rays per px", double(k.angularDiameter), k.rays);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The filtered shadow against the visible fraction of the sun's disc (light.angularDiameter).\n"
                          "Acne: too dark where the truth is lit; bleeding: too light inside an umbra, more than k texels\n"
                          "from its edge; peter-panning: too light within k texels of a contact; missing caster: a whole\n"
                          "shadow too light (k = measure.artifactTexels).");
    figureLines(f.in.accuracy, true);
    recordItem(f.state.rects, "accuracy.soft");
}

void figures(UiFrame& f) {
    const AccuracyView& a = f.in.accuracy;
    figureLines(a, false);
    recordItem(f.state.rects, "accuracy.figures");
    if (const std::string rule = drawAdvice(adviseFromAccuracy(f.s, a), f.state.rects); !rule.empty()) openTuneFor(f.state.tune, rule);
    cascadeTable(f);
    // Wrapped: a warning ends with its likely fix, which a narrow panel used to cut (issue 21 #6).
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.55f, 0.2f, 1.0f));
    for (std::size_t i = 0; i < a.warnings.size(); ++i) {
        ImGui::TextWrapped("%s", a.warnings[i].c_str());
        recordItem(f.state.rects, "accuracy.warning." + std::to_string(i));
    }
    ImGui::PopStyleColor();
    if (!a.warnings.empty()) recordItem(f.state.rects, "accuracy.warnings");
    softFigures(f);
}

void stateLine(UiFrame& f) {
    const AccuracyView& a = f.in.accuracy;
    switch (a.state) {
    case AccuracyView::State::Off:
    case AccuracyView::State::Settling:
        ImGui::TextDisabled("Waiting for the camera to settle...");
        break;
    case AccuracyView::State::Computing: {
        char overlay[96];
        std::snprintf(overlay, sizeof overlay, "computing... %.0f %% (%s)", 100.0 * a.progress, a.phase.c_str());
        ImGui::ProgressBar(a.progress, ImVec2(-1.0f, 0.0f), overlay);
        break;
    }
    case AccuracyView::State::Done:
        ImGui::Text("Done in %.2f s (%d x %d px)", a.seconds, a.width, a.height);
        recordItem(f.state.rects, "accuracy.state");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", a.timing.c_str());
        return;
    case AccuracyView::State::Failed:
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
        ImGui::TextWrapped("Failed: %s", a.error.c_str());
        ImGui::PopStyleColor();
        break;
    }
    recordItem(f.state.rects, "accuracy.state");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Exact ray-cast shadows of the frame on screen against the shadow map's unfiltered test.\n"
                          "Computed in the background once the camera and settings stay still; any change "
                          "cancels it.");
}

void overlayToggle(UiFrame& f) {
    ImGui::Checkbox(kErrorOverlayLabel, &f.state.errorOverlay);
    recordItem(f.state.rects, "accuracy.overlay");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kErrorOverlayTooltip);
    // The key beside the toggle, in the overlay's own colours, so the words and hues are learnt
    // together; a piece that would run past the panel's edge (1000x700) goes to the next line.
    for (const auto& [colour, text] : {std::pair{kFalseShadowColour, "magenta: false shadow"},
                                       std::pair{kFalseLightColour, "cyan: false light"}}) {
        ImGui::SameLine();
        if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize(text).x) ImGui::NewLine();
        ImGui::TextColored(colour, "%s", text);
    }
}

}  // namespace

void drawAccuracyPanel(UiFrame& f) {
    if (!f.state.showAccuracy) return;
    if (beginDockedPanel(f, Panel::Accuracy, "Accuracy", &f.state.showAccuracy)) {
        stateLine(f);
        overlayToggle(f);
        if (f.in.accuracy.state == AccuracyView::State::Done) figures(f);
    }
    ImGui::End();
}

void drawErrorOverlay(ImTextureID overlay) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    drawErrorOverlay(overlay, viewport->Pos, viewport->Size);
}

void drawErrorOverlay(ImTextureID overlay, ImVec2 pos, ImVec2 size) {
    const ImVec2 max{pos.x + size.x, pos.y + size.y};
    ImGui::GetBackgroundDrawList()->AddImage(overlay, pos, max);  // row 0 is the top: no flip
}

}  // namespace st::ui
