// Short key taps at a low frame rate reach the UI, and Tab does not move widget focus
// (issue 13 #3). ImGui's null backend with the app's key queue between "GLFW" and ImGui.
#include "app/editor/key_queue.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::test;

TEST(KeyQueueTest, APressAndReleaseBetweenTwoFramesShowInTwoFrames) {
    app::KeyQueue q;
    bool keys[512] = {};
    q.push(kKeyF1, true);
    q.push(kKeyF1, false);  // released 10 ms later, long before the next frame
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[kKeyF1]);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_FALSE(keys[kKeyF1]);
}

TEST(KeyQueueTest, DifferentKeysGoTogetherAndRepeatsAndStrayCodesAreDropped) {
    app::KeyQueue q;
    bool keys[512] = {};
    q.push(341, true);      // Ctrl
    q.push(kKeyS, true);    // S
    q.push(kKeyS, true);    // a repeat
    q.push(-1, true);       // GLFW_KEY_UNKNOWN
    q.push(9999, true);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_TRUE(keys[341] && keys[kKeyS]);
    q.push(kKeyS, false);
    q.push(kKeyS, true);
    q.push(kKeyS, false);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_FALSE(keys[kKeyS]);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[kKeyS]);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_FALSE(keys[kKeyS]);
}

TEST(KeyQueueTest, AKeyThatWaitsDoesNotHoldBackTheOthers) {
    app::KeyQueue q;
    bool keys[512] = {};
    for (int key : {83, 83, 70}) {  // "s", "s", "f" typed within one frame
        q.push(key, true);
        q.push(key, false);
    }
    q.push(kKeyEnter, true);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[83] && keys[70] && keys[kKeyEnter]);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_FALSE(keys[83] || keys[70]);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[83]);  // the second s
    EXPECT_FALSE(q.feed(keys));
    EXPECT_FALSE(keys[83]);
}

namespace {

// Frames at 6 fps; `tap` puts a press and its release into the queue between two frames, as
// GLFW's callback does for a 10 ms tap, and counts the frames until the queue is empty.
class SlowFrameTest : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::GetIO().DeltaTime = 1.0f / 6.0f;
        d.in.stats = &stats;
        d.frames(2);
    }
    void frame() {  // as EditorWindow::beginFrame does
        ImGuiIO& io = ImGui::GetIO();
        queue.feed(io.KeysDown);
        const app::Modifiers held = app::modifiersOf(io.KeysDown);
        io.KeyCtrl = held.ctrl, io.KeyShift = held.shift, io.KeyAlt = held.alt, io.KeySuper = held.super;
        d.frame();
    }
    void tap(int key) {
        queue.push(key, true);
        queue.push(key, false);
        do frame(); while (!queue.empty());
        frame();
    }
    FrameStats stats = fakeFrameStats();
    UiDriver d;
    app::KeyQueue queue;
};

}  // namespace

TEST_F(SlowFrameTest, TenTapsOfF1AllToggleHelp) {
    for (int i = 0; i < 10; ++i) {
        tap(kKeyF1);
        EXPECT_EQ(d.drawn("help"), i % 2 == 0) << "tap " << i;
    }
}

TEST_F(SlowFrameTest, WithoutTheQueueATapBetweenFramesIsLost) {
    // What ImGui 1.86's GLFW callback did: both events land in KeysDown before the frame.
    ImGui::GetIO().KeysDown[kKeyF1] = true;
    ImGui::GetIO().KeysDown[kKeyF1] = false;
    d.frames(2);
    EXPECT_FALSE(d.drawn("help"));
}

TEST_F(SlowFrameTest, TabSwapsTheViewsAndDoesNotMoveWidgetFocus) {
    d.click(d.rect("light.elevation").center());  // the Settings panel has the focus
    d.frame();
    ASSERT_FALSE(ImGui::IsAnyItemActive());
    queue.push(kKeyTab, true);
    frame();
    EXPECT_TRUE(d.last.swapSideView);
    queue.push(kKeyTab, false);
    frame();
    frame();
    EXPECT_FALSE(ImGui::IsAnyItemActive()) << "Tab moved the keyboard into a widget";
    EXPECT_FALSE(ImGui::GetIO().WantTextInput);
}

TEST_F(SlowFrameTest, ACtrlChordTappedBetweenTwoFramesIsSeen) {
    queue.push(341, true);  // GLFW_KEY_LEFT_CONTROL
    queue.push(79, true);   // O
    queue.push(79, false);
    queue.push(341, false);
    frame();
    d.frames(3);
    EXPECT_TRUE(d.drawn("open.path")) << "Ctrl+O opens File > Open";
}

// Issue 21 #7: Ctrl+A did not select all. xdotool's "key ctrl+a" sends Ctrl down, A down, Ctrl up,
// A up, a few ms apart: a frame that polled only Ctrl down left the rest to the next frame, which
// applied A down and Ctrl up together and saw a plain A. A quick hand at 5 fps does the same.
TEST(KeyQueueTest, AModifierReleasedAfterAKeyPressWaitsForTheNextFrame) {
    app::KeyQueue q;
    bool keys[512] = {};
    constexpr int kCtrl = 341;  // kKeyA: ui_driver.h
    q.push(kCtrl, true);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_TRUE(keys[kCtrl]);
    q.push(kKeyA, true);
    q.push(kCtrl, false);
    q.push(kKeyA, false);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[kKeyA]);
    EXPECT_TRUE(keys[kCtrl]) << "A was pressed with Ctrl held";
    EXPECT_FALSE(q.feed(keys));
    EXPECT_FALSE(keys[kKeyA] || keys[kCtrl]);
    // A modifier pressed after the key does not reach back to it either; one released before it does.
    q.push(kKeyA, true);
    q.push(kCtrl, true);
    EXPECT_TRUE(q.feed(keys));
    EXPECT_TRUE(keys[kKeyA] && !keys[kCtrl]);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_TRUE(keys[kCtrl]);
    q.push(kKeyA, false);
    q.push(kCtrl, false);
    q.push(kKeyA, true);
    EXPECT_TRUE(q.feed(keys));  // A up and Ctrl up: A's press waits (A changed), so Ctrl may go
    EXPECT_FALSE(keys[kKeyA] || keys[kCtrl]);
    EXPECT_FALSE(q.feed(keys));
    EXPECT_TRUE(keys[kKeyA] && !keys[kCtrl]) << "pressed after Ctrl was released: a plain A";
}

// The same through ImGui: the text field's Ctrl+A selects all, and typing replaces it.
TEST(KeyQueueTest, CtrlAThroughTheQueueSelectsAllOfAField) {
    UiDriver d;
    d.frames(2);
    d.click("presets.saveAsPath");
    ASSERT_TRUE(ImGui::GetIO().WantTextInput) << "the Save-as field has the keyboard";
    app::KeyQueue q;
    ImGuiIO& io = ImGui::GetIO();
    const auto frame = [&] {
        q.feed(io.KeysDown);
        const app::Modifiers held = app::modifiersOf(io.KeysDown);
        io.KeyCtrl = held.ctrl, io.KeyShift = held.shift;
        d.frame();
    };
    q.push(341, true);
    frame();
    q.push(65, true);
    q.push(341, false);
    q.push(65, false);
    frame();
    frame();
    d.typeText("mine");
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.ui().presetFile().filename(), "mine.json") << "Ctrl+A did not select the old path";
}
