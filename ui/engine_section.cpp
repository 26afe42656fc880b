// The Engine section at the top of the Settings panel: which engine the artist ships in, that
// engine's knobs in its own names (each edit runs through the engine's model: one undo step), what
// the current settings use that the engine lacks (with a button that keeps only what it can take),
// and the paste-ready text with Copy and Save. The knob tables are renderer/export/engine_knobs.h.
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "ui/document_actions.h"
#include "ui/item_rects.h"
#include "ui/panels.h"
#include "ui/ui_colours.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace st::ui {
namespace {

using nlohmann::json;

constexpr xport::Engine kEngines[] = {xport::Engine::ThreeJs, xport::Engine::Babylon, xport::Engine::Godot,
                                      xport::Engine::Unity,   xport::Engine::Unreal,  xport::Engine::Bevy,
                                      xport::Engine::Filament};
const char* const kEngineLabels[] = {"shadowtune (every method)", "three.js r187 (CSM addon)", "Babylon.js 9 (CascadedShadowGenerator)",
                                     "Godot 4 (DirectionalLight3D)", "Unity URP (pipeline asset)",
                                     "Unreal 5 (DirectionalLight CSM)", "Bevy 0.20 (CascadeShadowConfig)",
                                     "Filament 1.51 (ShadowOptions)"};
constexpr int kEngineCount = int(std::size(kEngines));
static_assert(std::size(kEngineLabels) == std::size(kEngines) + 1, "a label per engine, after shadowtune's");

void drawEngineChoice(UiFrame& f) {
    EngineUiState& st = f.state.engine;
    int current = 0;
    for (int i = 0; i < kEngineCount; ++i)
        if (st.engine == kEngines[i]) current = i + 1;
    if (ImGui::Combo("Engine", &current, kEngineLabels, kEngineCount + 1)) {
        st.engine = current == 0 ? std::nullopt : std::optional<xport::Engine>(kEngines[current - 1]);
        st.error.clear();
        st.saved.clear();
    }
    recordItem(f.state.rects, "engine.choice");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The engine you ship in: its knobs below, the settings it has no knob for greyed,\n"
                          "and the Tune panel tunes in its knobs only. %s",
                          st.engine && !xport::runsHere(*st.engine)
                              ? "This engine does not run here: its model is a reading of its source, not measured."
                              : "three.js and Babylon.js are measured here (engine-check).");
}

// One knob: a checkbox for a bool, else its JSON text (a bare word is taken as a string).
bool drawKnob(const std::string& key, const std::string& unit, json& value) {
    ImGui::PushID(key.c_str());
    bool changed = false;
    if (value.is_boolean()) {
        bool b = value.get<bool>();
        if (ImGui::Checkbox(key.c_str(), &b)) value = b, changed = true;
    } else {
        // The engine's own name on its own line: Godot's run to 70 characters
        // ("rendering/lights_and_shadows/directional_shadow/size"), cut beside a field at 1000 px.
        const std::string label = unit.empty() ? key : key + " (" + unit + ")";
        ImGui::TextWrapped("%s", label.c_str());
        char text[256];
        std::snprintf(text, sizeof text, "%s", value.is_string() ? value.get<std::string>().c_str() : value.dump().c_str());
        ImGui::SetNextItemWidth(-1.0f);
        if (ImGui::InputText("##value", text, sizeof text, ImGuiInputTextFlags_EnterReturnsTrue)) {
            const json parsed = json::parse(text, nullptr, false);
            value = parsed.is_discarded() ? json(std::string(text)) : parsed;
            changed = true;
        }
    }
    ImGui::PopID();
    return changed;
}

void drawKnobs(UiFrame& f, xport::Engine e, const xport::EngineKnobs& k) {
    EngineUiState& st = f.state.engine;
    for (auto it = k.knobs.begin(); it != k.knobs.end(); ++it) {
        json value = it.value();
        const bool edited = drawKnob(it.key(), xport::knobUnit(e, it.key()), value);
        recordItem(f.state.rects, "engine.knob." + it.key());
        if (!edited) continue;
        json knobs = k.knobs;
        knobs[it.key()] = value;
        try {
            applyEdit(f, xport::engineModel(e, knobs, f.s));
            st.error.clear();
        } catch (const std::invalid_argument& ex) {
            st.error = ex.what();
        }
    }
    recordItem(f.state.rects, "engine.knobs");
    if (!st.error.empty()) ImGui::TextColored(kErrorColour, "%s", st.error.c_str());
}

void drawLacks(UiFrame& f, xport::Engine e, const xport::EngineKnobs& k) {
    if (k.lacks.empty()) {
        ImGui::TextDisabled("Every setting here is one %s can take.", xport::engineName(e).c_str());
        return;
    }
    ImGui::TextColored(kErrorColour, "%s lacks %zu of these settings:", xport::engineName(e).c_str(), k.lacks.size());
    for (const std::string& l : k.lacks) {  // wrapped: Unreal's and Unity's run past a narrow column
        ImGui::Bullet();
        ImGui::TextWrapped("%s", l.c_str());
    }
    recordItem(f.state.rects, "engine.lacks");
    if (ImGui::Button("Keep only what it takes")) applyEdit(f, xport::engineModel(e, k.knobs, f.s));
    recordItem(f.state.rects, "engine.project");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The settings as the engine renders its nearest knobs (one undo step).");
}

// Next to the preset (or in the preset folder when untitled), written whole or not at all.
std::string saveText(const UiFrame& f, const xport::PasteText& t) {
    const std::filesystem::path dir = f.state.doc.file.empty() ? f.state.presetDir : f.state.doc.file.parent_path();
    const std::filesystem::path file = dir / t.file, tmp = dir / (t.file + ".tmp");
    {
        std::ofstream out(tmp, std::ios::binary);
        out << t.text;
        if (!out) return "could not write " + tmp.string();
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    return ec ? "could not write " + file.string() + ": " + ec.message() : "saved " + file.string();
}

void drawPasteText(UiFrame& f, xport::Engine e, const xport::EngineKnobs& k) {
    for (const xport::PasteText& t : xport::engineSnippets(e, k.knobs)) {
        ImGui::PushID(t.file.c_str());
        ImGui::TextUnformatted(t.file.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("Copy")) ImGui::SetClipboardText(t.text.c_str());
        recordItem(f.state.rects, "engine.copy." + t.file);
        ImGui::SameLine();
        if (ImGui::SmallButton("Save")) f.state.engine.saved = saveText(f, t);
        recordItem(f.state.rects, "engine.save." + t.file);
        const auto lines = float(std::count(t.text.begin(), t.text.end(), '\n') + 1);
        std::string text = t.text;  // read-only: ImGui wants a writable buffer
        ImGui::InputTextMultiline("##text", text.data(), text.size() + 1,
                                  ImVec2(-1.0f, ImGui::GetTextLineHeight() * std::min(lines, 14.0f) + 8.0f),
                                  ImGuiInputTextFlags_ReadOnly);
        recordItem(f.state.rects, "engine.text." + t.file);
        ImGui::PopID();
    }
    if (!f.state.engine.saved.empty()) ImGui::TextDisabled("%s", f.state.engine.saved.c_str());
}

}  // namespace

bool engineLacksField(const UiFrame& f, std::string_view path) {
    const std::optional<xport::Engine> e = f.state.engine.engine;
    if (!e) return false;
    const std::string_view group = path.substr(0, path.find('.'));
    if (group != "cascades" && group != "filter" && group != "bias") return false;
    const std::vector<std::string>& paths = xport::engineFieldPaths(*e);
    return std::find(paths.begin(), paths.end(), path) == paths.end();
}

void drawEngineSection(UiFrame& f) {
    const bool chosen = f.state.engine.engine.has_value();
    const std::string title = chosen ? "Engine: " + xport::engineName(*f.state.engine.engine) + "###engine" : "Engine###engine";
    const bool open = ImGui::CollapsingHeader(title.c_str(), chosen ? ImGuiTreeNodeFlags_DefaultOpen : 0);
    recordItem(f.state.rects, "group.engine");
    if (!open) return;
    drawEngineChoice(f);
    if (!f.state.engine.engine) return;
    const xport::Engine e = *f.state.engine.engine;
    xport::EngineKnobs k;
    try {
        k = xport::knobsFor(e, f.s);
    } catch (const std::exception& ex) {  // settings the panel below already marks as invalid
        ImGui::TextColored(kErrorColour, "no knobs for these settings: %s", ex.what());
        return;
    }
    ImGui::Separator();
    ImGui::TextDisabled("Its knobs, in its names (Enter applies; one undo step):");
    drawKnobs(f, e, k);
    drawLacks(f, e, k);
    ImGui::Separator();
    ImGui::TextDisabled("To paste into your project:");
    drawPasteText(f, e, k);
}

std::vector<xport::Engine> engineChoices() { return {std::begin(kEngines), std::end(kEngines)}; }

}  // namespace st::ui
