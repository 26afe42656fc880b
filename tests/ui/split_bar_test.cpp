// Issue 13 item 6: the split bar under the scene shows each cascade's range and share of the
// shadow distance; dragging a handle switches to manual splits, starting from the splits on
// screen, as one undo step.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"
#include "ui/split_bar.h"

#include <gtest/gtest.h>

#include <cstdint>

using namespace st;
using namespace st::test;

TEST(SplitBarTest, InnerSplitsAreTheManualOnesOnlyWhenTheyMatchTheCount) {
    Settings s;
    const std::vector<float> rendered{0.1f, 6.2f, 24.5f, 92.0f, 400.0f};
    EXPECT_EQ(ui::innerSplits(s, rendered), (std::vector<float>{6.2f, 24.5f, 92.0f}));
    s.cascades.scheme = SplitScheme::Manual;
    s.cascades.manualSplits = {10.0f, 50.0f, 100.0f};
    EXPECT_EQ(ui::innerSplits(s, rendered), s.cascades.manualSplits);
    s.cascades.manualSplits = {10.0f};  // count changed, the list not yet resized
    EXPECT_EQ(ui::innerSplits(s, rendered), (std::vector<float>{6.2f, 24.5f, 92.0f}));
}

TEST(SplitBarTest, DraggedSplitMapsLinearlyAndStaysBetweenItsNeighbours) {
    const std::vector<float> inner{10.0f, 50.0f, 100.0f};
    EXPECT_NEAR(ui::draggedSplit(inner, 1, 0.0f, 400.0f, 0.2f), 80.0f, 1e-3f);   // 20 % of 400 m
    EXPECT_LT(ui::draggedSplit(inner, 1, 0.0f, 400.0f, 0.9f), 100.0f);          // not past split 2
    EXPECT_GT(ui::draggedSplit(inner, 1, 0.0f, 400.0f, 0.0f), 10.0f);           // nor before split 0
    EXPECT_GT(ui::draggedSplit(inner, 0, 0.1f, 400.0f, -1.0f), 0.1f);            // nor before the near end
    EXPECT_LT(ui::draggedSplit(inner, 2, 0.1f, 400.0f, 2.0f), 400.0f);
}

// Issue 21 #12: a drag made "Manual splits 28.6 / 59.5 / 59.7 m", a 0.2 m cascade.
TEST(SplitBarTest, NoHandleMakesACascadeThinnerThanAPercentOfTheRangeOrHalfAMetre) {
    const std::vector<float> inner{28.6f, 59.5f, 90.0f};
    EXPECT_GE(ui::clampedSplit(inner, 2, 0.1f, 150.0f, 59.7f), 59.5f + 1.499f) << "1 % of 150 m";
    EXPECT_LE(ui::clampedSplit(inner, 2, 0.1f, 150.0f, 149.9f), 150.0f - 1.499f) << "the last cascade too";
    EXPECT_GE(ui::clampedSplit({2.0f, 4.0f}, 1, 0.1f, 10.0f, 2.1f), 2.5f - 1e-5f) << "half a metre on a short range";
    // Neighbours already closer than that (typed values): a quarter of their gap, still between them.
    const float tight = ui::clampedSplit({10.0f, 10.4f, 10.8f}, 1, 0.1f, 150.0f, 10.0f);
    EXPECT_GT(tight, 10.0f);
    EXPECT_LT(tight, 10.8f);
}

TEST(SplitBarTest, DraggingAHandleSetsManualSplitsAsOneUndoStep) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();  // splits 0.1 | 6.2 | 24.5 | 92 | 400 m
    d.in.stats = &stats;
    d.frames(2);
    const Settings before = d.s;
    ASSERT_EQ(before.cascades.scheme, SplitScheme::Practical);
    const ui::ItemRect bar = d.rect("splitBar");
    const ui::ItemRect handle = d.rect("splitBar.handle1");  // between cascades 1 and 2, at 24.5 m
    EXPECT_NEAR(handle.center().x, bar.min.x + (bar.max.x - bar.min.x) * (24.5f - 0.1f) / 399.9f, 1.0f);
    const float target = 60.0f;  // metres
    const float x = bar.min.x + (bar.max.x - bar.min.x) * (target - 0.1f) / 399.9f;
    d.drag(handle.center(), {x, handle.center().y});
    EXPECT_EQ(d.s.cascades.scheme, SplitScheme::Manual);
    ASSERT_EQ(d.s.cascades.manualSplits.size(), 3u);
    const float metresPerPixel = 399.9f / (bar.max.x - bar.min.x);
    EXPECT_NEAR(d.s.cascades.manualSplits[0], 6.2f, 1e-4f);
    EXPECT_NEAR(d.s.cascades.manualSplits[1], target, metresPerPixel);
    EXPECT_NEAR(d.s.cascades.manualSplits[2], 92.0f, 1e-4f);
    EXPECT_TRUE(d.ui().dirty());
    d.pressKey(kKeyZ, true);  // the whole drag, scheme switch included, is one step
    EXPECT_EQ(d.s, before);
}

TEST(SplitBarTest, OneHandlePerInnerSplit) {
    UiDriver d({1920.0f, 1080.0f});
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.frames(2);
    EXPECT_TRUE(d.drawn("splitBar.handle0"));
    EXPECT_TRUE(d.drawn("splitBar.handle2"));
    EXPECT_FALSE(d.drawn("splitBar.handle3")) << "4 cascades: 3 inner splits";
}

// Issue 13 item 6, in the side view: a split plane's handle dragged along its own direction moves
// the split by the metres the app's projection says, as one undo step; orbiting is not started.
TEST(SplitBarTest, SplitPlaneDraggedInTheSideViewMovesByItsMetres) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();  // inner splits 6.2 | 24.5 | 92 m
    d.in.stats = &stats;
    d.in.sideView = reinterpret_cast<ImTextureID>(std::uintptr_t{1});
    // Split 1 (24.5 m) at the picture's centre, 1 % of its width to the right per metre.
    d.in.sideSplitHandles = {{{0.2f, 0.5f}, {0.01f, 0.0f}}, {{0.5f, 0.5f}, {0.01f, 0.0f}}, {{0.8f, 0.5f}, {0.01f, 0.0f}}};
    d.frames(2);
    const Settings before = d.s;
    const ui::ItemRect picture = d.rect("sideView");
    const float width = picture.max.x - picture.min.x;
    const ui::ItemRect handle = d.rect("sideView.split1");
    EXPECT_NEAR(handle.center().x, picture.at(0.5f, 0.5f).x, 1.0f);
    d.drag(handle.center(), {handle.center().x + 0.05f * width, handle.center().y});  // 5 m
    EXPECT_EQ(d.s.cascades.scheme, SplitScheme::Manual);
    ASSERT_EQ(d.s.cascades.manualSplits.size(), 3u);
    const float metresPerPixel = 1.0f / (0.01f * width);  // ImGui floors mouse positions: a pixel
    EXPECT_NEAR(d.s.cascades.manualSplits[1], 24.5f + 5.0f, metresPerPixel);
    EXPECT_FLOAT_EQ(d.s.cascades.manualSplits[0], 6.2f);
    EXPECT_EQ(d.last.sideViewOrbit.x, 0.0f) << "the handle took the drag, not the orbit";
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);
}
