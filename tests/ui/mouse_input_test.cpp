// Quick clicks and drags at a low frame rate reach the widget they were made on (issue 13 #3).
// ImGui's null backend with the app's mouse queue between "GLFW" and ImGui, against what ImGui
// 1.86's GLFW backend did: latch a press, take the position from the cursor at NewFrame.
#include "app/editor/mouse_queue.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace st;
using namespace st::test;
using Pos = app::MouseQueue::Position;

TEST(MouseQueueTest, AClickBetweenTwoFramesShowsOverTwoFramesWhereItHappened) {
    app::MouseQueue q;
    q.move(10, 20);
    q.button(0, true);
    q.button(0, false);  // 10 ms later, long before the next frame
    q.move(300, 400);    // and the hand moves on
    EXPECT_EQ(q.feed(), (Pos{10, 20}));
    EXPECT_TRUE(q.down()[0]);
    EXPECT_FALSE(q.empty());
    EXPECT_EQ(q.feed(), (Pos{10, 20}));
    EXPECT_FALSE(q.down()[0]);
    EXPECT_EQ(q.feed(), (Pos{300, 400}));
    EXPECT_TRUE(q.empty());
    EXPECT_EQ(q.feed(), std::nullopt) << "nothing queued: the window's cursor position stands";
    EXPECT_FALSE(q.down()[0]);
}

TEST(MouseQueueTest, ADragStartsWhereThePressWasAndMovesMerge) {
    app::MouseQueue q;
    q.move(5, 5);
    q.move(50, 60);
    q.button(1, true);
    for (int i = 1; i <= 100; ++i) q.move(50 + i, 60);  // a drag within one slow frame
    q.button(1, false);
    EXPECT_EQ(q.feed(), (Pos{50, 60})) << "moves before the press merge into it";
    EXPECT_TRUE(q.down()[1]);
    EXPECT_EQ(q.feed(), (Pos{150, 60})) << "the drag's moves show as one, with the release at its end";
    EXPECT_FALSE(q.down()[1]);
    EXPECT_TRUE(q.empty());
}

TEST(MouseQueueTest, OneButtonChangePerFrameInTheOrderTheyCame) {
    app::MouseQueue q;
    q.move(1, 1);
    q.button(0, true);
    q.move(2, 2);
    q.button(1, true);
    q.button(0, false);
    q.button(1, false);
    const std::array<std::array<bool, 2>, 4> expected{{{true, false}, {true, true}, {false, true}, {false, false}}};
    const std::array<Pos, 4> at{Pos{1, 1}, Pos{2, 2}, Pos{2, 2}, Pos{2, 2}};
    for (std::size_t f = 0; f < 4; ++f) {
        ASSERT_FALSE(q.empty()) << "frame " << f;
        EXPECT_EQ(q.feed(), at[f]) << "frame " << f;
        EXPECT_EQ(q.down()[0], expected[f][0]) << "frame " << f;
        EXPECT_EQ(q.down()[1], expected[f][1]) << "frame " << f;
    }
    EXPECT_TRUE(q.empty());
}

TEST(MouseQueueTest, RepeatsStrayReleasesAndHighButtonsAreDropped) {
    app::MouseQueue q;
    q.button(0, false);  // the release of a press made outside the window
    q.button(7, true);   // GLFW_MOUSE_BUTTON_8: ImGui 1.86 has five
    q.button(-1, true);
    q.place(30, 40);  // the window opened under the cursor
    EXPECT_TRUE(q.empty());
    EXPECT_EQ(q.feed(), std::nullopt);
    q.button(2, true);
    q.button(2, true);
    EXPECT_EQ(q.feed(), (Pos{30, 40}));
    EXPECT_TRUE(q.down()[2]);
    EXPECT_TRUE(q.empty());
}

namespace {

// Frames at 4 fps. `frame` is EditorWindow::beginFrame's mouse part; `latchedFrame` is what
// imgui_impl_glfw 1.86 did instead: a press that came since the last frame shows as held for
// this one, at the cursor's position now.
class SlowClickTest : public ::testing::Test {
protected:
    void SetUp() override {
        ImGui::GetIO().DeltaTime = 1.0f / 4.0f;
        d.in.stats = &stats;
        d.frames(2);
    }
    void frame() {
        ImGuiIO& io = ImGui::GetIO();
        const auto shown = queue.feed();
        std::copy(queue.down().begin(), queue.down().end(), io.MouseDown);
        if (shown) io.MousePos = {shown->x, shown->y};
        d.frame();
    }
    void drain() {
        do frame(); while (!queue.empty());
        frame();
    }
    void latchedFrame(bool justPressed, ImVec2 cursor, bool held) {
        ImGui::GetIO().MouseDown[0] = justPressed || held;
        ImGui::GetIO().MousePos = cursor;
        d.frame();
    }
    // A checkbox's square: a widget 13 px wide at ImGui's default font.
    ImVec2 boxOf(std::string_view key) {
        const ui::ItemRect r = d.rect(key);
        const float h = r.max.y - r.min.y;
        return {r.min.x + h * 0.5f, r.min.y + h * 0.5f};
    }
    FrameStats stats = fakeFrameStats();
    UiDriver d;
    app::MouseQueue queue;
    const ImVec2 away{640.0f, 700.0f};  // the status bar: nothing there takes a click
};

}  // namespace

TEST_F(SlowClickTest, AQuickClickThatMovesOnTicksTheBoxItWasMadeOn) {
    const bool before = d.s.ground;
    const ImVec2 box = boxOf("ground");
    queue.move(away.x, away.y);
    frame();
    for (int i = 0; i < 3; ++i) {
        queue.move(box.x, box.y);  // the cursor reaches the box, clicks 10 ms and moves on in one frame
        queue.button(0, true);
        queue.button(0, false);
        queue.move(away.x, away.y);
        drain();
        EXPECT_EQ(d.s.ground, i % 2 == 0 ? !before : before) << "click " << i;
    }
}

TEST_F(SlowClickTest, WithTheBackendsLatchTheSameClickIsLost) {
    const bool before = d.s.ground;
    latchedFrame(false, away, false);
    latchedFrame(true, away, false);  // pressed and released on the box; the cursor is away by NewFrame
    latchedFrame(false, away, false);
    EXPECT_EQ(d.s.ground, before);
}

TEST_F(SlowClickTest, ADragMadeWithinOneFrameMovesTheSliderItStartedOn) {
    const Settings before = d.s;
    const ui::ItemRect r = d.rect("light.elevation");
    const ImVec2 grab{r.min.x + (r.max.x - r.min.x) * 0.1f, (r.min.y + r.max.y) * 0.5f};
    queue.move(grab.x, grab.y);
    frame();
    queue.button(0, true);
    queue.move(grab.x, grab.y + 23.0f);  // pressed, then the hand drifts down to the ambient slider
    queue.move(grab.x, grab.y + 46.0f);
    frame();
    EXPECT_NE(d.s.light.elevation, before.light.elevation) << "the press landed on the slider";
    const float dragged = d.s.light.elevation;
    queue.button(0, false);
    drain();
    Settings expected = before;
    expected.light.elevation = dragged;
    EXPECT_EQ(d.s, expected) << "the ambient slider under the later position did not change";
}

TEST_F(SlowClickTest, WithTheBackendsLatchTheSameDragMovesTheFieldBelow) {
    const Settings before = d.s;
    const ui::ItemRect r = d.rect("light.elevation");
    const ImVec2 grab{r.min.x + (r.max.x - r.min.x) * 0.1f, (r.min.y + r.max.y) * 0.5f};
    latchedFrame(false, grab, false);
    const ui::ItemRect ambient = d.rect("light.ambient");
    ASSERT_TRUE(ambient.min.y < grab.y + 46.0f && grab.y + 46.0f < ambient.max.y);
    latchedFrame(true, {grab.x, grab.y + 46.0f}, true);
    latchedFrame(false, {grab.x, grab.y + 46.0f}, false);
    EXPECT_EQ(d.s.light.elevation, before.light.elevation) << "the press was seen two fields below";
    EXPECT_NE(d.s.light.ambient, before.light.ambient) << "and moved the ambient slider instead";
}
