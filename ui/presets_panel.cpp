// The Presets panel: the file being edited (with the dirty marker), Save / Save as, undo/redo,
// the presets to load, and what went wrong with the last load or save.
#include "ui/document_actions.h"
#include "ui/ui_colours.h"
#include "ui/layout.h"
#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

namespace st::ui {
namespace {

const ImVec4 kOkColour{0.45f, 0.85f, 0.45f, 1.0f};

bool button(UiFrame& f, const char* label, const char* key, bool enabled = true) {
    ImGui::BeginDisabled(!enabled);
    const bool pressed = ImGui::Button(label);
    ImGui::EndDisabled();
    recordItem(f.state.rects, key);
    return pressed && enabled;
}

void drawDocumentLine(UiFrame& f) {
    const bool dirty = isDirty(f.state.doc, f.s);
    const auto& file = f.state.doc.file;
    ImGui::Text("%s%s", file.empty() ? "untitled" : file.filename().string().c_str(), dirty ? " *" : "");
    if (!file.empty() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", file.string().c_str());
}

void drawEditButtons(UiFrame& f) {
    if (button(f, "Save", "presets.save")) saveCurrent(f);
    ImGui::SameLine();
    const std::string undo = "Undo (" + std::to_string(f.state.undo.undoCount()) + ")";
    if (button(f, undo.c_str(), "presets.undo", f.state.undo.canUndo())) undoEdit(f);
    ImGui::SameLine();
    const std::string redo = "Redo (" + std::to_string(f.state.undo.redoCount()) + ")";
    if (button(f, redo.c_str(), "presets.redo", f.state.undo.canRedo())) redoEdit(f);
}

void drawSaveAs(UiFrame& f) {
    ImGui::SetNextItemWidth(-70.0f);
    const bool entered = ImGui::InputTextWithHint("##saveAs", "name.json or a path", &f.state.saveAsText,
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    recordItem(f.state.rects, "presets.saveAsPath");
    ImGui::SameLine();
    if (button(f, "Save as", "presets.saveAs") || entered) {
        saveAs(f, resolveSavePath(f.state.presetDir, f.state.saveAsText));
    }
}

// A heading for each sub-folder of the preset folder ("scenes/"), the files indented under it.
void drawFolderHeading(const UiFrame& f, const std::filesystem::path& folder) {
    const std::filesystem::path rel = folder.lexically_relative(f.state.presetDir);
    const bool sub = !rel.empty() && rel != "." && *rel.begin() != "..";
    ImGui::TextDisabled("%s/", (sub ? rel : folder).string().c_str());
}

void drawPresetEntries(UiFrame& f) {
    std::filesystem::path folder;
    for (const auto& file : f.in.presetFiles) {
        if (file.parent_path() != folder) {
            folder = file.parent_path();
            if (folder.lexically_normal() != f.state.presetDir.lexically_normal()) drawFolderHeading(f, folder);
        }
        const std::string name = file.filename().string();
        const bool current = file == f.state.doc.file;
        if (ImGui::Selectable(name.c_str(), current)) requestLoad(f, file);
        recordItem(f.state.rects, "preset:" + name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", file.string().c_str());
    }
    if (f.in.presetFiles.empty()) ImGui::TextDisabled("(no presets found)");
}

void drawPresetList(UiFrame& f) {
    ImGui::TextDisabled("Load a preset:");
    const float height = ImGui::GetTextLineHeightWithSpacing() * 8.0f;
    if (ImGui::BeginChild("presetList", ImVec2(0.0f, height), true)) drawPresetEntries(f);
    ImGui::EndChild();
}

void drawMessages(UiFrame& f) {
    const Document& doc = f.state.doc;
    if (!doc.errors.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColour);
        ImGui::TextWrapped("%s", doc.errors.size() == 1 ? "Problem:" : "Problems:");
        for (const auto& message : doc.errors) ImGui::TextWrapped("%s", message.c_str());
        ImGui::PopStyleColor();
    } else if (!doc.status.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kOkColour);
        ImGui::TextWrapped("%s", doc.status.c_str());
        ImGui::PopStyleColor();
    }
    if (!f.in.statusLine.empty()) ImGui::TextWrapped("%s", f.in.statusLine.c_str());
}

}  // namespace

void drawPresetsPanel(UiFrame& f) {
    if (beginDockedPanel(f, Panel::Presets, "Presets", nullptr)) {
        drawDocumentLine(f);
        drawEditButtons(f);
        drawSaveAs(f);
        drawMessages(f);  // above the list, so a failed load or save is seen without scrolling
        ImGui::Separator();
        drawPresetList(f);
    }
    ImGui::End();
}

}  // namespace st::ui
