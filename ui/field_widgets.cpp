#include "ui/field_widgets.h"

#include "renderer/settings/number_text.h"
#include "ui/field_rules.h"

#include <imgui.h>
#include <imgui_internal.h>
#include <imgui_stdlib.h>

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace st::ui {
namespace {

std::string labelOf(const FieldInfo& field) { return std::string(field.label); }

float lowOf(const FieldInfo& field) { return static_cast<float>(field.min); }
float highOf(const FieldInfo& field) { return static_cast<float>(field.max); }
float speedOf(const FieldInfo& field) { return field.step > 0.0 ? static_cast<float>(field.step) : 0.1f; }

bool showUnsupported(const FieldInfo& field) {
    ImGui::TextDisabled("%s: set in the preset file", labelOf(field).c_str());
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s (%s): the editor has no widget for this kind of field yet.",
                          std::string(field.path).c_str(), std::string(fieldKindName(field.kind)).c_str());
    }
    return false;
}

// Whether the widget just drawn has the keyboard: a drag or slider in its text mode, an input box.
bool typing() { return ImGui::IsItemActive() && ImGui::GetInputTextState(ImGui::GetItemID()) != nullptr; }

// The value a numeric widget settles on this frame, if any. While typing, the text is held in
// `edits.pending` and nothing is applied; when the widget lets the keyboard go (Enter, a click
// elsewhere) the last typed value is. `typed` tells which values came from the keyboard.
std::optional<FieldValue> settle(FieldEdits& edits, const std::string& key, bool changed, const FieldValue& value,
                                 bool& typed) {
    typed = false;
    if (typing()) {
        if (changed) edits.pending[key] = value;
        return std::nullopt;
    }
    if (const auto it = edits.pending.find(key); it != edits.pending.end()) {
        FieldValue held = changed ? value : it->second;
        edits.pending.erase(it);
        typed = true;
        return held;
    }
    if (changed) return value;
    return std::nullopt;
}

// A typed number outside the rules is refused, never clamped; the reason stays on screen.
bool refuse(FieldEdits& edits, const std::string& key, const FieldInfo& field, double value) {
    std::string problem = typedValueProblem(field, value);
    if (problem.empty()) {
        edits.refused.clear();  // a value taken: every refusal on screen is stale (issue 39 #10)
        return false;
    }
    edits.refused[key] = std::move(problem);
    return true;
}

void drawRefusal(const FieldEdits& edits, const std::string& key, ItemRects& rects) {
    const auto it = edits.refused.find(key);
    if (it == edits.refused.end()) return;
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
    ImGui::TextWrapped("  %s: not applied", it->second.c_str());
    ImGui::PopStyleColor();
    recordItem(rects, key + "#refused");
}

bool editFloat(const FieldInfo& field, Settings& s, FieldEdits& edits) {
    const FieldValue current = field.get(s);
    const float* stored = std::get_if<float>(&current);
    if (!stored) return showUnsupported(field);
    float value = *stored;
    const std::string format = floatFormatFor(field, *stored);
    const bool changed = prefersSlider(field)
        ? ImGui::SliderFloat(labelOf(field).c_str(), &value, lowOf(field), highOf(field), format.c_str())
        : ImGui::DragFloat(labelOf(field).c_str(), &value, speedOf(field), lowOf(field), highOf(field), format.c_str());
    const std::string key(field.path);
    bool typed = false;
    const auto settled = settle(edits, key, changed, value, typed);
    if (!settled) return false;
    const float v = std::get<float>(*settled);
    if (typed && refuse(edits, key, field, v)) return false;
    if (!typed) edits.refused.clear();  // a value taken: every refusal on screen is stale
    return storeField(field, s, static_cast<float>(clampToField(field, v)));
}

bool editInt(const FieldInfo& field, Settings& s, FieldEdits& edits) {
    if (field.powerOfTwo) return editPowerOfTwo(field, s, nullptr);
    const FieldValue current = field.get(s);
    const int* stored = std::get_if<int>(&current);
    if (!stored) return showUnsupported(field);
    int value = *stored;
    const int step = field.step >= 1.0 ? static_cast<int>(field.step) : 1;
    const bool changed = (prefersSlider(field) && !field.odd)
        ? ImGui::SliderInt(labelOf(field).c_str(), &value, static_cast<int>(field.min),
                           static_cast<int>(field.max), intFormat(field).c_str())
        : ImGui::InputInt(labelOf(field).c_str(), &value, step, step * 10);
    const std::string key(field.path);
    bool typed = false;
    const auto settled = settle(edits, key, changed, value, typed);
    if (!settled) return false;
    const int v = std::get<int>(*settled);
    if (typed && refuse(edits, key, field, v)) return false;
    if (!typed) edits.refused.clear();  // a value taken: every refusal on screen is stale
    return storeField(field, s, legalInt(field, v, *stored));
}

bool editBool(const FieldInfo& field, Settings& s) {
    const FieldValue current = field.get(s);
    const bool* stored = std::get_if<bool>(&current);
    if (!stored) return showUnsupported(field);
    bool value = *stored;
    return ImGui::Checkbox(labelOf(field).c_str(), &value) && storeField(field, s, value);
}

bool editEnum(const FieldInfo& field, Settings& s) {
    const FieldValue current = field.get(s);
    const int* stored = std::get_if<int>(&current);
    if (!stored || field.enumNames.empty()) return showUnsupported(field);
    const auto count = static_cast<int>(field.enumNames.size());
    const std::string preview = (*stored >= 0 && *stored < count)
        ? std::string(field.enumNames[static_cast<std::size_t>(*stored)]) : "<invalid>";
    int chosen = *stored;
    if (ImGui::BeginCombo(labelOf(field).c_str(), preview.c_str())) {
        for (int i = 0; i < count; ++i) {
            const std::string name(field.enumNames[static_cast<std::size_t>(i)]);
            if (ImGui::Selectable(name.c_str(), i == *stored)) chosen = i;
        }
        ImGui::EndCombo();
    }
    return chosen != *stored && storeField(field, s, chosen);
}

bool editString(const FieldInfo& field, Settings& s) {
    const FieldValue current = field.get(s);
    const std::string* stored = std::get_if<std::string>(&current);
    if (!stored) return showUnsupported(field);
    std::string value = *stored;
    return ImGui::InputText(labelOf(field).c_str(), &value) && storeField(field, s, value);
}

bool editVec3(const FieldInfo& field, Settings& s, FieldEdits& edits) {
    const FieldValue current = field.get(s);
    const glm::vec3* stored = std::get_if<glm::vec3>(&current);
    if (!stored) return showUnsupported(field);
    glm::vec3 value = *stored;
    const bool changed = ImGui::DragFloat3(labelOf(field).c_str(), &value.x, speedOf(field), lowOf(field), highOf(field),
                                           floatFormat(field).c_str());
    const std::string key(field.path);
    bool typed = false;
    const auto settled = settle(edits, key, changed, value, typed);
    if (!settled) return false;
    glm::vec3 v = std::get<glm::vec3>(*settled);
    for (int i = 0; i < 3; ++i) {
        if (typed && refuse(edits, key, field, v[i])) return false;
        v[i] = static_cast<float>(clampToField(field, v[i]));
    }
    if (!typed) edits.refused.clear();  // a value taken: every refusal on screen is stale
    return storeField(field, s, v);
}

// The list editors' "Add" (a copy of the last element, or `first` into an empty list) and
// "Remove last" buttons; true if either changed `values`.
template <class T>
bool addOrRemoveLast(std::vector<T>& values, T first) {
    bool changed = false;
    if (ImGui::SmallButton("Add")) {
        values.push_back(values.empty() ? first : values.back());
        changed = true;
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("Remove last") && !values.empty()) {
        values.pop_back();
        changed = true;
    }
    return changed;
}

bool editFloatList(const FieldInfo& field, Settings& s, ItemRects& rects, FieldEdits& edits) {
    const FieldValue current = field.get(s);
    const auto* stored = std::get_if<std::vector<float>>(&current);
    if (!stored) return showUnsupported(field);
    std::vector<float> values = *stored;
    bool changed = editFloatElements(field, values, rects, edits);
    changed = addOrRemoveLast(values, static_cast<float>(field.min)) || changed;
    return changed && storeField(field, s, values);
}

// One combo of the legal values per element (cascades.mapSizes: 256..8192), then Add / Remove.
bool editIntList(const FieldInfo& field, Settings& s) {
    const FieldValue current = field.get(s);
    const auto* stored = std::get_if<std::vector<int>>(&current);
    if (!stored) return showUnsupported(field);
    std::vector<int> values = *stored;
    const std::vector<int> choices = powerOfTwoChoices(field);
    bool changed = false;
    ImGui::TextUnformatted(labelOf(field).c_str());
    for (std::size_t i = 0; i < values.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string label = "[" + std::to_string(i) + "]";
        if (field.powerOfTwo && ImGui::BeginCombo(label.c_str(), std::to_string(values[i]).c_str())) {
            for (int choice : choices)
                if (ImGui::Selectable(std::to_string(choice).c_str(), choice == values[i])) {
                    changed = changed || choice != values[i];
                    values[i] = choice;
                }
            ImGui::EndCombo();
        } else if (!field.powerOfTwo && ImGui::InputInt(label.c_str(), &values[i])) {
            values[i] = legalInt(field, values[i], (*stored)[i]);
            changed = true;
        }
        ImGui::PopID();
    }
    changed = addOrRemoveLast(values, static_cast<int>(field.max > 1024 ? 1024 : field.min)) || changed;
    return changed && storeField(field, s, values);
}

bool dispatch(const FieldInfo& field, Settings& s, ItemRects& rects, FieldEdits& edits) {
    switch (field.kind) {
        case FieldKind::Float: return editFloat(field, s, edits);
        case FieldKind::Int: return editInt(field, s, edits);
        case FieldKind::Bool: return editBool(field, s);
        case FieldKind::Enum: return editEnum(field, s);
        case FieldKind::String: return editString(field, s);
        case FieldKind::Vec3: return editVec3(field, s, edits);
        case FieldKind::FloatList: return editFloatList(field, s, rects, edits);
        case FieldKind::IntList: return editIntList(field, s);
        default: return showUnsupported(field);  // a kind added to the table after this code
    }
}

std::string rangeText(const FieldInfo& field) {
    if (field.kind == FieldKind::Bool || field.kind == FieldKind::Enum || field.kind == FieldKind::String) return {};
    std::string text = "Range " + formatNumber(field.min) + " .. " + formatNumber(field.max);
    if (!field.unit.empty()) text += " " + std::string(field.unit);
    if (field.powerOfTwo) text += ", powers of two";
    if (field.odd) text += ", odd";
    return text;
}

}  // namespace

bool storeField(const FieldInfo& field, Settings& s, const FieldValue& value) {
    if (!field.set || field.get(s) == value) return false;
    field.set(s, value);
    return true;
}

bool drawFieldWidget(const FieldInfo& field, Settings& s, ItemRects& rects, FieldEdits& edits) {
    if (!field.get || !field.set) return showUnsupported(field);
    // Greyed, still editable: the value is kept for when the mode that reads it comes back.
    const std::string unused = notApplicableReason(field, s);
    if (!unused.empty()) ImGui::PushStyleVar(ImGuiStyleVar_Alpha, ImGui::GetStyle().Alpha * 0.45f);
    const bool changed = dispatch(field, s, rects, edits);
    if (!unused.empty()) {
        ImGui::PopStyleVar();
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", unused.c_str());
    }
    if (field.kind == FieldKind::FloatList) return changed;  // elements and marker drawn by the list
    recordItem(rects, std::string(field.path) + (unused.empty() ? "" : "#unused"));
    recordItem(rects, std::string(field.path));
    drawHelpMarker(field);
    drawRefusal(edits, std::string(field.path), rects);
    return changed;
}

void drawHelpMarker(const FieldInfo& field) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(field.help.data(), field.help.data() + field.help.size());
    const std::string range = rangeText(field);
    if (!range.empty()) ImGui::TextDisabled("%s", range.c_str());
    ImGui::TextDisabled("%s  (a change: %s)", std::string(field.path).c_str(),
                        std::string(changeClassName(field.change)).c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

bool editPowerOfTwo(const FieldInfo& field, Settings& s, const std::function<std::string(int)>& note,
                    ItemRects* rects) {
    const FieldValue current = field.get(s);
    const int* stored = std::get_if<int>(&current);
    if (!stored) return showUnsupported(field);
    const auto text = [&](int size) {
        std::string t = std::to_string(size) + (field.unit.empty() ? "" : " " + std::string(field.unit));
        return note ? t + "   " + note(size) : t;
    };
    int chosen = *stored;
    if (ImGui::BeginCombo(labelOf(field).c_str(), text(*stored).c_str())) {
        for (const int size : powerOfTwoChoices(field)) {
            if (ImGui::Selectable(text(size).c_str(), size == *stored)) chosen = size;
            if (rects) recordItem(*rects, std::string(field.path) + ":" + std::to_string(size));
        }
        ImGui::EndCombo();
    }
    return chosen != *stored && storeField(field, s, chosen);
}

bool editFloatElements(const FieldInfo& field, std::vector<float>& values, ItemRects& rects, FieldEdits& edits) {
    ImGui::TextUnformatted(field.label.data(), field.label.data() + field.label.size());
    drawHelpMarker(field);
    bool changed = false;
    for (std::size_t i = 0; i < values.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        const std::string label = elementLabel(field, i);
        const std::string key = std::string(field.path) + "[" + std::to_string(i) + "]";
        float value = values[i];
        const bool moved = ImGui::DragFloat(label.c_str(), &value, speedOf(field), lowOf(field), highOf(field),
                                            floatFormatFor(field, values[i]).c_str());
        recordItem(rects, key);
        bool typed = false;
        if (const auto settled = settle(edits, key, moved, value, typed)) {
            const float v = std::get<float>(*settled);
            if (!typed || !refuse(edits, key, field, v)) {
                if (!typed) edits.refused.clear();  // a value taken: every refusal on screen is stale
                values[i] = static_cast<float>(clampToField(field, v));
                changed = true;
            }
        }
        drawRefusal(edits, key, rects);
        ImGui::PopID();
    }
    return changed;
}

}  // namespace st::ui
