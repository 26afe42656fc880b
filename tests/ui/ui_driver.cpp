#include "tests/ui/ui_driver.h"

#include <gtest/gtest.h>

namespace st::test {
namespace {

// io.KeyMap as the GLFW backend fills it, so ImGuiKey_* lookups see GLFW codes.
void mapKeysLikeGlfw(ImGuiIO& io) {
    io.KeyMap[ImGuiKey_Tab] = kKeyTab;
    io.KeyMap[ImGuiKey_LeftArrow] = 263;
    io.KeyMap[ImGuiKey_RightArrow] = 262;
    io.KeyMap[ImGuiKey_UpArrow] = 265;
    io.KeyMap[ImGuiKey_DownArrow] = 264;
    io.KeyMap[ImGuiKey_Home] = 268;
    io.KeyMap[ImGuiKey_End] = 269;
    io.KeyMap[ImGuiKey_Delete] = 261;
    io.KeyMap[ImGuiKey_Backspace] = 259;
    io.KeyMap[ImGuiKey_Enter] = kKeyEnter;
    io.KeyMap[ImGuiKey_Escape] = kKeyEscape;
    io.KeyMap[ImGuiKey_A] = 65;
    io.KeyMap[ImGuiKey_C] = 67;
    io.KeyMap[ImGuiKey_V] = 86;
    io.KeyMap[ImGuiKey_X] = 88;
    io.KeyMap[ImGuiKey_Y] = 89;
    io.KeyMap[ImGuiKey_Z] = kKeyZ;
}

}  // namespace

UiDriver::UiDriver(ImVec2 displaySize) : ui_(std::make_unique<ui::EditorUi>(testing::TempDir())) {
    IMGUI_CHECKVERSION();
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // layout from layout.cpp, not from a previous run
    io.DisplaySize = displaySize;
    io.DeltaTime = 1.0f / 60.0f;
    mapKeysLikeGlfw(io);
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // the null backend: built, not uploaded
}

UiDriver::~UiDriver() { ImGui::DestroyContext(context_); }

void UiDriver::frame() {
    beginBackendFrame();
    ImGui::NewFrame();
    last = ui_->draw(s, in);
    if (overlay && last.errorOverlay) ui::drawErrorOverlay(overlay);
    ImGui::Render();
    renderDrawData(ImGui::GetDrawData());
}

void UiDriver::frames(int count) {
    for (int i = 0; i < count; ++i) frame();
}

ui::ItemRect UiDriver::rect(std::string_view key) {
    const auto& rects = ui_->itemRects();
    const auto it = rects.find(key);
    EXPECT_NE(it, rects.end()) << "widget \"" << key << "\" was not drawn in the last frame";
    return it == rects.end() ? ui::ItemRect{} : it->second;
}

bool UiDriver::drawn(std::string_view key) const { return ui_->itemRects().contains(key); }

void UiDriver::mouse(ImVec2 pos, bool leftDown) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = pos;
    io.MouseDown[0] = leftDown;
}

void UiDriver::scroll(ImVec2 pos, float wheel) {
    mouse(pos, false);
    frame();
    ImGui::GetIO().MouseWheel = wheel;
    frame();
    frame();
}

void UiDriver::click(ImVec2 pos) {
    mouse(pos, false);
    frame();
    mouse(pos, true);
    frame();
    mouse(pos, false);
    frame();
}

void UiDriver::ctrlClick(ImVec2 pos) {
    ImGui::GetIO().KeyCtrl = true;
    click(pos);
    ImGui::GetIO().KeyCtrl = false;
}

void UiDriver::drag(ImVec2 from, ImVec2 to, int steps) {
    mouse(from, false);
    frame();
    mouse(from, true);
    frame();
    for (int i = 1; i <= steps; ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(steps);
        mouse({from.x + (to.x - from.x) * t, from.y + (to.y - from.y) * t}, true);
        frame();
    }
    mouse(to, false);
    frame();
}

void UiDriver::pressKey(int key, bool ctrl, bool shift) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeysDown[key] = true;
    frame();
    io.KeysDown[key] = false;
    frame();
    io.KeyCtrl = false;
    io.KeyShift = false;
}

void UiDriver::typeText(const char* text) {
    ImGui::GetIO().AddInputCharactersUTF8(text);
    frame();
}

void UiDriver::replaceText(std::string_view key, const char* text) {
    click(key);
    pressKey(kKeyA, true);  // select all
    typeText(text);
    pressKey(kKeyEnter);
    frames(2);
}

void UiDriver::chooseMenu(std::string_view menuKey, std::string_view itemKey) {
    click(menuKey);
    frame();
    click(itemKey);
    frames(2);
}

}  // namespace st::test
