#pragma once
// Runs EditorUi frames with scripted input and no window. The base class is ImGui's null backend
// (examples/example_null: fonts built on the CPU, nothing rendered), enough for behaviour tests;
// GlUiDriver (ui_gl_driver.h) also renders every frame into an offscreen framebuffer.
#include "renderer/settings/settings.h"
#include "ui/editor_ui.h"

#include <imgui.h>

#include <memory>
#include <string_view>

namespace st::test {

// GLFW key codes, as imgui_impl_glfw 1.86 writes them into io.KeysDown (ShortcutKeys defaults).
inline constexpr int kKeyTab = 258;
inline constexpr int kKeyEnter = 257;
inline constexpr int kKeyEscape = 256;
inline constexpr int kKeyA = 65;
inline constexpr int kKeyZ = 90;
inline constexpr int kKeyS = 83;
inline constexpr int kKeyF1 = 290;

class UiDriver {
public:
    explicit UiDriver(ImVec2 displaySize = {1280.0f, 720.0f});
    virtual ~UiDriver();
    UiDriver(const UiDriver&) = delete;
    UiDriver& operator=(const UiDriver&) = delete;

    ui::EditorUi& ui() { return *ui_; }
    Settings s;              // what the editor edits
    ui::UiInputs in;         // what the "app" shows it
    ui::UiRequests last;     // requests of the last frame
    ImTextureID overlay = nullptr;  // drawn with ui::drawErrorOverlay when the frame asks for it, as the app does

    // One frame: backend NewFrame, ImGui::NewFrame, ui.draw, ImGui::Render, backend render.
    void frame();
    void frames(int count);

    // Rectangle of a named widget from the last frame; fails the test (and returns an empty
    // rectangle) when it was not drawn.
    ui::ItemRect rect(std::string_view key);
    bool drawn(std::string_view key) const;

    // Scripted input; each call runs the frames it needs.
    void click(ImVec2 pos);
    void click(std::string_view key) { click(rect(key).center()); }
    void ctrlClick(ImVec2 pos);
    void drag(ImVec2 from, ImVec2 to, int steps = 6);
    void pressKey(int key, bool ctrl = false, bool shift = false);
    void typeText(const char* text);
    // A text field's whole content replaced: click it, Ctrl+A, type, Enter, two frames.
    void replaceText(std::string_view key, const char* text);
    // A menu's item chosen: click the menu `menuKey`, then its item `itemKey`, two frames.
    void chooseMenu(std::string_view menuKey, std::string_view itemKey);
    void mouse(ImVec2 pos, bool leftDown);  // input for the following frames
    void scroll(ImVec2 pos, float wheel);   // one frame with the wheel turned over `pos`

protected:
    virtual void beginBackendFrame() {}
    virtual void renderDrawData(ImDrawData*) {}

private:
    ImGuiContext* context_ = nullptr;
    std::unique_ptr<ui::EditorUi> ui_;
};

}  // namespace st::test
