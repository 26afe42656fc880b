// The Settings panel: every row of the field table as a widget, grouped by the first segment of
// its JSON path in collapsing headers (the knobs that only reproduce a bug under a closed "Debug"
// one), with derived figures beside the knobs and the problems validate() finds shown in red
// (under the field, and listed under the panel).
#include "renderer/export/engine_knobs.h"
#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/validation.h"
#include "ui/field_overrides.h"
#include "ui/field_rules.h"
#include "ui/field_widgets.h"
#include "ui/figures_panel.h"
#include "ui/layout.h"
#include "ui/map_cost_confirm.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

namespace st::ui {
namespace {

const ImVec4 kIssueColour{1.0f, 0.35f, 0.3f, 1.0f};

struct FieldGroup {
    std::string key;  // "camera"; fields without a dot ("scene", "notes") form the "scene" group
    std::vector<const FieldInfo*> fields;
};

std::string groupKey(std::string_view path) {
    const auto dot = path.find('.');
    return dot == std::string_view::npos ? "scene" : std::string(path.substr(0, dot));
}

// Groups in the order their first field appears in the table; the rows that exist only to
// reproduce a bug (FieldInfo::debug) form the "debug" group, last.
std::vector<FieldGroup> groupFields() {
    std::vector<FieldGroup> groups;
    FieldGroup debug{"debug", {}};
    for (const FieldInfo& field : fieldTable()) {
        if (field.debug) {
            debug.fields.push_back(&field);
            continue;
        }
        const std::string key = groupKey(field.path);
        auto it = std::find_if(groups.begin(), groups.end(), [&](const FieldGroup& g) { return g.key == key; });
        if (it == groups.end()) it = groups.insert(groups.end(), FieldGroup{key, {}});
        it->fields.push_back(&field);
    }
    if (!debug.fields.empty()) groups.push_back(std::move(debug));
    return groups;
}

std::string titleOf(const std::string& key) {
    std::string title = key;
    if (!title.empty()) title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(title[0])));
    return title;
}

void drawFieldIssues(const UiFrame& f, const FieldInfo& field) {
    for (const SettingsIssue& issue : f.state.issues) {
        const std::string_view path = issue.path;
        if (path.substr(0, path.find('[')) != field.path) continue;
        ImGui::PushStyleColor(ImGuiCol_Text, kIssueColour);
        ImGui::TextWrapped("  %s %s", std::string(path.substr(field.path.size())).c_str(), issue.reason.c_str());
        ImGui::PopStyleColor();
    }
}

void drawField(UiFrame& f, const FieldInfo& field) {
    ImGui::PushID(field.path.data(), field.path.data() + field.path.size());
    const FieldOverride custom = overrideFor(field.path);
    const std::optional<Settings> before = affectsMapCost(field.path) ? std::optional<Settings>(f.s) : std::nullopt;
    const bool greyed = engineLacksField(f, field.path);
    if (greyed) ImGui::BeginDisabled();
    bool changed = custom ? custom(field, f) : drawFieldWidget(field, f.s, f.state.rects, f.state.fieldEdits);
    if (greyed) {
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("%s has no knob for this: it keeps its own value (see the Engine section)",
                              xport::engineName(*f.state.engine.engine).c_str());
    }
    if (changed && before && holdExpensiveEdit(f, field, *before)) changed = false;
    if (changed) keepCascadeListsValid(f.s, field.path);
    f.edited = f.edited || changed;
    drawFieldIssues(f, field);
    ImGui::PopID();
}

// What a group shows after its fields: the sun toggle, the cascade figures.
void drawGroupExtras(UiFrame& f, const std::string& key) {
    if (key == "light") drawSunAnimation(f);
    if (key == "cascades")
        if (const std::string rule = drawCascadeFigures(f.s, f.in.stats, f.state.rects); !rule.empty()) openTuneFor(f.state.tune, rule);
}

// The groups an artist tunes all day start open; output, measurement and new groups start closed.
bool openByDefault(const std::string& key) {
    for (const char* open : {"scene", "camera", "light", "cascades", "filter", "bias"}) {
        if (key == open) return true;
    }
    return false;
}

// "Debug (1 on)" when a debug knob is away from its default, so a closed heading still says
// that a bug is being reproduced; the ID stays "debug" whatever the count.
std::string headerLabel(const UiFrame& f, const FieldGroup& group) {
    if (group.key != "debug") return titleOf(group.key);
    const Settings defaults;
    const auto on = std::count_if(group.fields.begin(), group.fields.end(),
                                  [&](const FieldInfo* field) { return field->get(f.s) != field->get(defaults); });
    return (on > 0 ? "Debug (" + std::to_string(on) + " on)" : std::string("Debug")) + "###debug";
}

void drawGroup(UiFrame& f, const FieldGroup& group) {
    const ImGuiTreeNodeFlags flags = openByDefault(group.key) ? ImGuiTreeNodeFlags_DefaultOpen : 0;
    const bool open = ImGui::CollapsingHeader(headerLabel(f, group).c_str(), flags);
    recordItem(f.state.rects, "group." + group.key);
    if (!open) return;
    for (const FieldInfo* field : group.fields) drawField(f, *field);
    drawGroupExtras(f, group.key);
}

void drawFields(UiFrame& f) {
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    drawEngineSection(f);
    for (const FieldGroup& group : groupFields()) drawGroup(f, group);
    if (ImGui::CollapsingHeader("Performance", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawTimingPlots(f.state.timing, f.in.stats);
    }
    ImGui::PopItemWidth();
}

void drawIssueList(const UiFrame& f) {
    ImGui::PushStyleColor(ImGuiCol_Text, kIssueColour);
    ImGui::TextWrapped("%zu problem%s: the renderer keeps the last valid settings", f.state.issues.size(),
                       f.state.issues.size() == 1 ? "" : "s");
    for (const SettingsIssue& issue : f.state.issues) ImGui::TextWrapped("%s", issue.message().c_str());
    ImGui::PopStyleColor();
}

float issueListHeight(const UiFrame& f) {
    if (f.state.issues.empty()) return 0.0f;
    const auto lines = std::min<std::size_t>(1 + 2 * f.state.issues.size(), 8);
    return ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(lines) + ImGui::GetStyle().ItemSpacing.y * 2.0f;
}

}  // namespace

void drawSettingsPanel(UiFrame& f) {
    f.state.issues = findIssues(f.s);
    if (beginDockedPanel(f, Panel::Settings, "Settings", nullptr)) {
        const float footer = issueListHeight(f);
        if (ImGui::BeginChild("fields", ImVec2(0.0f, -footer))) drawFields(f);
        ImGui::EndChild();
        if (footer > 0.0f) {
            ImGui::Separator();
            if (ImGui::BeginChild("issues")) drawIssueList(f);
            ImGui::EndChild();
        }
    }
    ImGui::End();
}

}  // namespace st::ui
