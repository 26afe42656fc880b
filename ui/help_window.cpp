// The help window (F1): every shortcut of the editor, the app's camera keys included.
#include "ui/field_rules.h"
#include "ui/layout.h"
#include "ui/panels.h"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cfloat>

namespace st::ui {
namespace {

struct Shortcut {
    const char* keys;
    const char* action;
};

constexpr std::array<Shortcut, 16> kShortcuts{{
    {"Right mouse + W A S D", "fly the camera"},
    {"Right mouse + Q / E", "fly down / up"},
    {"Mouse wheel", "fly speed"},
    {"Middle mouse drag", "pan the camera"},
    {"Alt + left drag", "orbit around the point under the cursor"},
    {"F", "frame the scene (near/far kept)"},
    {"Tab", "swap the side view with the main view"},
    {"1 .. 6", "view: shaded, cascades, shadow, texel density, side, texel grid"},
    {"Drag / wheel on side view", "orbit / zoom the side camera"},
    {"Ctrl+Z", "undo a settings change"},
    {"Ctrl+Shift+Z", "redo"},
    {"Ctrl+S", "save the preset"},
    {"Ctrl+O", "open a preset by path"},
    {"F1", "show or hide this help"},
    {"H", "hide or show every panel (the scene fills the window)"},
    {"Rest the mouse on the scene", "probe: cascade, texel, shadow, bias, truth"},
}};

void drawTable() {
    if (!ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) return;
    for (const Shortcut& s : kShortcuts) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.action);
    }
    ImGui::EndTable();
}

// Issue 39 #10: where the memory goes, each GL object's bytes from its size and format; the rest
// of the resident set is the CPU side (the scene's copy, the ray caster's BVH, the driver).
void drawMemory(UiFrame& f) {
    const MemoryView& m = f.in.memory;
    if (m.lines.empty()) return;
    const bool open = ImGui::CollapsingHeader("Memory");
    recordItem(f.state.rects, "help.memoryHeader");
    if (!open) return;
    if (ImGui::BeginTable("memory", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
        auto row = [](const std::string& what, const std::string& shape, const std::string& size) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(what.c_str());
            // The size before the shape: in a narrow window the shape is what scrolls out of view.
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(size.c_str());
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", shape.c_str());
        };
        for (const MemoryLine& l : m.lines) row(l.what, l.shape, formatBytes(l.bytes));
        row("Textures and buffers", "", formatBytes(m.total()));
        if (m.residentBytes > 0) {
            row("Process resident", "", formatBytes(m.residentBytes));
            if (m.residentBytes > m.total())
                row("The rest", "scene copy, ray caster's BVH, driver, UI", formatBytes(m.residentBytes - m.total()));
        }
        ImGui::EndTable();
        recordItem(f.state.rects, "help.memory");
    }
}

// Never past the window's bottom or right edge: the Memory table opened at 1000x700 ran off both,
// an auto-resized window growing with its content. Cut to fit, it scrolls.
void fitAboveBottom(ImGuiSizeCallbackData* d) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    d->DesiredSize.x = std::min(d->DesiredSize.x, std::max(display.x - d->Pos.x - 4.0f, 200.0f));
    d->DesiredSize.y = std::min(d->DesiredSize.y, std::max(display.y - d->Pos.y - 4.0f, 120.0f));
}

}  // namespace

void drawHelpWindow(UiFrame& f) {
    if (!f.state.showHelp) return;
    placeNextWindow(Panel::Help);
    ImGui::SetNextWindowSizeConstraints({0.0f, 0.0f}, {FLT_MAX, FLT_MAX}, fitAboveBottom);
    // Sized to its text: a fixed size cut the longest line ("orbit around the point under the c").
    if (ImGui::Begin("Help", &f.state.showHelp, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_HorizontalScrollbar)) {
        drawTable();
        ImGui::Spacing();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 34.0f);
        ImGui::TextWrapped("Hover (?) next to a setting for what it does, its range and what a change costs. "
                           "Camera keys work when no panel has the mouse or keyboard.");
        ImGui::PopTextWrapPos();
        recordItem(f.state.rects, "help");
        drawMemory(f);
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        f.state.rects["window.Help"] = {pos, {pos.x + size.x, pos.y + size.y}};
    }
    ImGui::End();
}

}  // namespace st::ui
