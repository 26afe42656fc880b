// Issue 13 item 5: the hover probe asks for the scene pixel under the mouse (from the viewport's
// top left), only while the mouse rests over the scene and no panel, and shows the app's readout
// of exactly that pixel.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"
#include "ui/probe.h"

#include <gtest/gtest.h>

#include <string_view>
#include <utility>

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

// Issue 21: at 1000x700 the tooltip, put right of the cursor as ImGui puts every tooltip, covered
// the Shadow maps panel. It goes right of or below the cursor where there is room in the scene
// viewport, else left of or above it, else as far in as the viewport allows.
TEST(ProbeTest, TheTooltipGoesWhereTheViewportHasRoom) {
    const ui::Rect scene{{340.0f, 19.0f}, {740.0f, 405.0f}};
    const ImVec2 size{300.0f, 150.0f};
    const auto at = [&](ImVec2 mouse, ImVec2 tooltip) {
        const ImVec2 p = ui::placeProbeTooltip(mouse, tooltip, scene);
        return std::pair(p.x, p.y);
    };
    EXPECT_EQ(at({360.0f, 40.0f}, size), std::pair(376.0f, 64.0f)) << "right and below";
    EXPECT_EQ(at({720.0f, 390.0f}, size), std::pair(412.0f, 232.0f)) << "left and above";
    EXPECT_EQ(at({540.0f, 200.0f}, size), std::pair(440.0f, 224.0f)) << "no room either side: against the right edge, below the cursor";
    EXPECT_EQ(at({540.0f, 200.0f}, {500.0f, 150.0f}).first, 340.0f) << "wider than the viewport";
}

TEST(ProbeTest, AtAThousandPixelsTheTooltipStaysInsideTheSceneViewport) {
    UiDriver d({1000.0f, 700.0f});
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.frames(2);
    const ImVec2 origin = d.last.scenePos, size = d.last.sceneSize;
    // Near the viewport's right edge, where the Shadow maps panel begins.
    const int px = int(size.x) - 30, py = int(size.y * 0.35f);
    ui::ProbeView p = readout(px, py);
    p.constantBias = 0.02f, p.slopeBias = 0.5647f, p.normalOffset = 0.0123f;  // the longest lines
    d.in.probe = p;
    d.mouse({origin.x + float(px) + 0.5f, origin.y + float(py) + 0.5f}, false);
    d.frames(4);  // the tooltip takes its size in its first frame and its place after
    ASSERT_TRUE(d.drawn("probe.tooltip"));
    const ui::ItemRect r = d.rect("probe.tooltip");
    EXPECT_GE(r.min.x, origin.x);
    EXPECT_GE(r.min.y, origin.y);
    EXPECT_LE(r.max.x, origin.x + size.x) << "over the right column";
    EXPECT_LE(r.max.y, origin.y + size.y);
    EXPECT_FALSE(ImGui::GetIO().MousePos.x >= r.min.x && ImGui::GetIO().MousePos.x < r.max.x &&
                 ImGui::GetIO().MousePos.y >= r.min.y && ImGui::GetIO().MousePos.y < r.max.y)
        << "the tooltip covers the pixel it describes";
    // What it draws (its frame as well as its lines) lies in that rectangle: a window moved after
    // it began keeps its frame where it was and clips its lines away.
    const ImDrawData* drawn = ImGui::GetDrawData();
    const ImDrawList* tooltip = nullptr;
    for (int i = 0; i < drawn->CmdListsCount; ++i)
        if (std::string_view(drawn->CmdLists[i]->_OwnerName).starts_with("##Tooltip")) tooltip = drawn->CmdLists[i];
    ASSERT_NE(tooltip, nullptr);
    ASSERT_GT(tooltip->VtxBuffer.Size, 100) << "the frame and the lines";
    constexpr float fringe = 1.5f;  // anti-aliased edges reach a pixel out
    for (const ImDrawVert& v : tooltip->VtxBuffer) {
        ASSERT_TRUE(v.pos.x >= r.min.x - fringe && v.pos.x <= r.max.x + fringe && v.pos.y >= r.min.y - fringe &&
                    v.pos.y <= r.max.y + fringe)
            << "drawn at " << v.pos.x << ", " << v.pos.y << " outside " << r.min.x << ", " << r.min.y << " .. " << r.max.x << ", " << r.max.y;
    }
}
