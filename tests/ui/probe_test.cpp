// Issue 13 item 5: the hover probe asks for the scene pixel under the mouse (from the viewport's
// top left), only while the mouse rests over the scene and no panel, and shows the app's readout
// of exactly that pixel.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::test;

namespace {

ui::ProbeView readout(int x, int y) {
    ui::ProbeView p;
    p.valid = true;
    p.x = x;
    p.y = y;
    p.cascade = 1;
    p.texelWorldSize = 0.03f;
    p.pixelsPerTexel = 2.5f;
    p.sunFacing = true;
    return p;
}

}  // namespace

TEST(ProbeTest, AsksForThePixelUnderTheMouseAndShowsItsReadout) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.frames(2);
    const ImVec2 origin = d.last.scenePos;
    d.mouse({origin.x + 100.5f, origin.y + 40.25f}, false);
    d.frames(2);
    ASSERT_TRUE(d.last.probeWanted);
    EXPECT_EQ(d.last.probePixel.x, 100.0f);
    EXPECT_EQ(d.last.probePixel.y, 40.0f);
    EXPECT_FALSE(d.drawn("probe")) << "no readout from the app yet";
    d.in.probe = readout(99, 40);  // another pixel: stale, not shown
    d.frame();
    EXPECT_FALSE(d.drawn("probe"));
    d.in.probe = readout(100, 40);
    d.frame();
    EXPECT_TRUE(d.drawn("probe"));
}

TEST(ProbeTest, NothingIsAskedOverAPanelOrWhileAButtonIsDown) {
    UiDriver d;
    d.frames(2);
    d.mouse(d.rect("window.Settings").center(), false);
    d.frames(2);
    EXPECT_FALSE(d.last.probeWanted);
    const ImVec2 origin = d.last.scenePos;
    d.mouse({origin.x + 50.0f, origin.y + 50.0f}, true);  // flying the camera, or dragging
    d.frames(2);
    EXPECT_FALSE(d.last.probeWanted);
    d.mouse({origin.x + 50.0f, origin.y + 50.0f}, false);
    d.frames(2);
    EXPECT_TRUE(d.last.probeWanted);
}

// Issue 21 #3: the probe's tooltip was drawn over the Sweep panel's field list and over the
// Unsaved-changes question.
TEST(ProbeTest, NoReadoutWhileAPopupOrAModalIsOpen) {
    UiDriver d;
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.frames(2);
    const ImVec2 origin = d.last.scenePos;
    const ImVec2 over{origin.x + 100.0f, origin.y + 40.0f};
    d.in.probe = readout(100, 40);
    d.mouse(over, false);
    d.frames(2);
    ASSERT_TRUE(d.drawn("probe"));
    d.s.light.elevation += 5.0f;  // unsaved: closing asks first
    d.frame();
    d.ui().requestQuit();
    d.frames(2);
    ASSERT_TRUE(d.drawn("confirm.discard")) << "the Unsaved-changes question is up";
    d.mouse(over, false);
    d.frames(2);
    EXPECT_FALSE(d.last.probeWanted);
    EXPECT_FALSE(d.drawn("probe"));
}
