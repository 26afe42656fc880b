// Issue 13 #10: the status bar keeps the UI's frame rate and the scene's render time apart, as
// a reused or interactive scene image makes them differ.
#include "tests/ui/ui_driver.h"
#include "ui/status_bar.h"

#include <gtest/gtest.h>

using namespace st;
using st::test::UiDriver;

TEST(StatusBarTest, SceneRenderTimeScaleAndReuseAreShownApart) {
    EXPECT_EQ(ui::sceneRenderText({}), "render --");
    EXPECT_EQ(ui::sceneRenderText({.ms = 152.4}), "render 152 ms");
    EXPECT_EQ(ui::sceneRenderText({.ms = 152.4, .reused = true}), "image reused (rendered in 152 ms)");
    EXPECT_EQ(ui::sceneRenderText({.ms = 61.0, .scale = 0.35, .mapSize = 1024}),
              "render 61 ms (interactive: 35 %, maps 1024, far ones staggered)");
    UiDriver d;
    d.in.cpuFrameMs = 25.0;
    d.in.scene = {.ms = 150.0, .reused = true};
    d.frames(3);
    ASSERT_TRUE(d.drawn("status.sceneRender"));
    EXPECT_GT(d.rect("status.sceneRender").min.x, d.rect("status.fps").max.x) << "beside the frame rate";
    EXPECT_EQ(d.rect("status.sceneRender").min.y, d.rect("status.fps").min.y);
}
