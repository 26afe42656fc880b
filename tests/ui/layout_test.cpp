// Issue 13 item 2: the scene gets its own viewport, the space the docked panels leave, at any
// window size; H hides every panel; the user's column widths come back as LayoutPrefs. Issue 13
// item 10: the status bar's frame rate. Under ImGui's null backend: the rectangles checked are
// the windows ImGui actually placed, not the ones the layout asked for.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"
#include "ui/layout.h"
#include "ui/status_bar.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>

using namespace st;
using namespace st::test;

namespace {

constexpr int kKeyH = 72;

ui::Rect sceneOf(const ui::UiRequests& r) { return {r.scenePos, {r.scenePos.x + r.sceneSize.x, r.scenePos.y + r.sceneSize.y}}; }

// Every docked window drawn in the last frame, by its recorded name.
std::vector<std::pair<std::string, ui::Rect>> windows(UiDriver& d) {
    std::vector<std::pair<std::string, ui::Rect>> out;
    for (const auto& [key, r] : d.ui().itemRects())
        if (key.rfind("window.", 0) == 0) out.emplace_back(key, ui::Rect{r.min, r.max});
    return out;
}

class LayoutAtSize : public ::testing::TestWithParam<std::pair<float, float>> {};

}  // namespace

TEST_P(LayoutAtSize, PanelsNeitherOverlapTheSceneNorEachOtherNorLeaveTheWindow) {
    const auto [w, h] = GetParam();
    UiDriver d({w, h});
    FrameStats stats = fakeFrameStats();
    d.in.stats = &stats;
    d.in.sideView = reinterpret_cast<ImTextureID>(std::uintptr_t{1});  // the null backend draws nothing
    d.frames(3);
    const ui::Rect scene = sceneOf(d.last);
    EXPECT_GE(scene.width(), 0.35f * w) << "the scene keeps a usable share of the width";
    EXPECT_GE(scene.height(), 0.45f * h);
    const auto placed = windows(d);
    ASSERT_EQ(placed.size(), 7u);  // Settings, Presets, Shadow maps, Side view, splits, Accuracy, status
    for (const auto& [name, r] : placed) {
        EXPECT_FALSE(r.overlaps(scene)) << name << " covers the scene at " << w << "x" << h;
        EXPECT_GE(r.min.x, 0.0f) << name;
        EXPECT_GE(r.min.y, 0.0f) << name;
        EXPECT_LE(r.max.x, w) << name;
        EXPECT_LE(r.max.y, h) << name;
        EXPECT_GE(r.width(), 150.0f) << name << " squeezed to a strip";
        for (const auto& [other, o] : placed)
            if (other != name) EXPECT_FALSE(r.overlaps(o)) << name << " overlaps " << other;
    }
}

INSTANTIATE_TEST_SUITE_P(WindowSizes, LayoutAtSize,
                         ::testing::Values(std::pair{1000.0f, 700.0f}, std::pair{1280.0f, 720.0f},
                                           std::pair{1600.0f, 900.0f}, std::pair{1920.0f, 1080.0f},
                                           std::pair{3840.0f, 2160.0f}));

TEST(LayoutTest, ComputedRectanglesTileTheWindowAtEverySize) {
    for (const ImVec2 size : {ImVec2{1000, 700}, ImVec2{1280, 720}, ImVec2{2560, 1440}, ImVec2{3840, 2160}}) {
        const ui::Layout l = ui::computeLayout({0, 0}, size, {}, {}, {});
        const ui::Rect* panels[] = {&l.settings, &l.presets, &l.shadowMaps, &l.sideView, &l.splitBar, &l.accuracy, &l.status};
        float area = l.scene.width() * l.scene.height();
        for (const ui::Rect* p : panels) {
            EXPECT_FALSE(p->overlaps(l.scene));
            area += p->width() * p->height();
        }
        // Menu bar + panels + scene = the window: nothing left over, nothing counted twice.
        EXPECT_NEAR(area + size.x * ui::LayoutMetrics{}.menuBar, size.x * size.y, 1.0f) << size.x;
    }
}

TEST(LayoutTest, BelowTheSupportedSizeTheSceneStillKeepsAThird) {
    for (const ImVec2 size : {ImVec2{640, 480}, ImVec2{320, 240}}) {
        const ui::Layout l = ui::computeLayout({0, 0}, size, {}, {}, {});
        EXPECT_GE(l.scene.width(), size.x / 3.0f) << size.x;
        EXPECT_FALSE(l.settings.overlaps(l.presets));
        EXPECT_FALSE(l.settings.overlaps(l.scene));
        EXPECT_LE(l.presets.max.x, size.x);
    }
}

TEST(LayoutTest, ClosedPanelsGiveTheirSpaceAway) {
    const ui::Layout all = ui::computeLayout({0, 0}, {1280, 720}, {}, {}, {});
    const ui::Layout some = ui::computeLayout({0, 0}, {1280, 720}, {}, {}, {.shadowMaps = false, .sideView = true, .accuracy = false});
    EXPECT_TRUE(some.shadowMaps.empty());
    EXPECT_TRUE(some.accuracy.empty());
    EXPECT_GT(some.presets.height(), all.presets.height());
    EXPECT_FLOAT_EQ(some.presets.height() + some.sideView.height(), all.settings.height());
    EXPECT_GT(some.scene.height(), all.scene.height());
}

TEST(LayoutTest, HKeyHidesEveryPanelAndTheSceneFillsTheWindow) {
    UiDriver d({1280.0f, 720.0f});
    d.frames(2);
    ASSERT_TRUE(d.drawn("window.Settings"));
    const ui::Rect docked = sceneOf(d.last);
    d.pressKey(kKeyH);
    EXPECT_TRUE(d.ui().layoutPrefs().panelsHidden);
    for (const char* name : {"window.Settings", "window.Presets", "window.Shadow maps", "window.Accuracy", "window.Cascade splits"})
        EXPECT_FALSE(d.drawn(name)) << name;
    const ui::Rect full = sceneOf(d.last);
    EXPECT_FLOAT_EQ(full.min.x, 0.0f);
    EXPECT_FLOAT_EQ(full.width(), 1280.0f);
    EXPECT_GT(full.height(), docked.height());
    EXPECT_TRUE(d.drawn("status.fps")) << "the status bar stays: it says how to get the panels back";
    d.pressKey(kKeyH);
    EXPECT_TRUE(d.drawn("window.Settings"));
    EXPECT_FLOAT_EQ(sceneOf(d.last).width(), docked.width());
}

TEST(LayoutTest, ViewMenuItemHidesThePanelsToo) {
    UiDriver d({1280.0f, 720.0f});
    d.frames(2);
    d.click("menu.view");
    d.click("menu.hidePanels");
    EXPECT_TRUE(d.ui().layoutPrefs().panelsHidden);
    d.frame();
    EXPECT_FALSE(d.drawn("window.Settings"));
    EXPECT_FLOAT_EQ(d.last.sceneSize.x, 1280.0f);
}

TEST(LayoutTest, DraggedColumnWidthIsKeptInThePrefsAndMovesTheScene) {
    UiDriver d({1600.0f, 900.0f});
    d.frames(2);
    const ui::Rect settings{d.rect("window.Settings").min, d.rect("window.Settings").max};
    const float sceneLeft = d.last.scenePos.x;
    // ImGui's resize grip sits in the window's bottom-right corner.
    d.drag({settings.max.x - 3.0f, settings.max.y - 3.0f}, {settings.max.x + 57.0f, settings.max.y - 3.0f});
    d.frames(2);
    EXPECT_NEAR(d.ui().layoutPrefs().leftWidth, settings.width() + 60.0f, 1.0f);
    EXPECT_NEAR(d.last.scenePos.x, sceneLeft + 60.0f, 1.0f);
    EXPECT_FALSE((ui::Rect{d.rect("window.Settings").min, d.rect("window.Settings").max}).overlaps(sceneOf(d.last)));

    // The prefs the app saved come back in the next run.
    UiDriver next({1600.0f, 900.0f});
    next.ui().setLayoutPrefs(d.ui().layoutPrefs());
    next.frames(2);
    EXPECT_NEAR(next.last.scenePos.x, sceneLeft + 60.0f, 1.0f);
}

// Issue 21 #5: after the window was made small, layout.json kept "leftWidth": 238 and the next
// launch was cramped. Shrinking the window changes no kept width; a width dragged in a small
// window is kept no narrower than a column's minimum.
TEST(LayoutTest, ASmallWindowDoesNotNarrowTheKeptColumns) {
    UiDriver d({1600.0f, 900.0f});
    d.frames(2);
    const ui::LayoutPrefs before = d.ui().layoutPrefs();
    const float sceneLeft = d.last.scenePos.x;
    for (const ImVec2 size : {ImVec2{1000.0f, 700.0f}, ImVec2{700.0f, 500.0f}, ImVec2{520.0f, 400.0f}}) {
        ImGui::GetIO().DisplaySize = size;
        d.frames(3);
    }
    EXPECT_EQ(d.ui().layoutPrefs(), before) << "leftWidth " << d.ui().layoutPrefs().leftWidth;
    const ui::Rect settings{d.rect("window.Settings").min, d.rect("window.Settings").max};
    d.drag({settings.max.x - 3.0f, settings.max.y - 3.0f}, {settings.max.x - 80.0f, settings.max.y - 3.0f});
    d.frames(2);
    EXPECT_GE(d.ui().layoutPrefs().leftWidth, 260.0f) << "a column's minimum";
    ImGui::GetIO().DisplaySize = {1600.0f, 900.0f};
    d.ui().setLayoutPrefs(before);
    d.frames(3);
    EXPECT_NEAR(d.last.scenePos.x, sceneLeft, 1.0f);
}

TEST(StatusBarTest, FrameRateIsFramesOverTheirTime) {
    ui::History h(240);
    EXPECT_EQ(ui::frameRateText(h), "-- fps");
    for (int i = 0; i < 10; ++i) h.push(i % 2 ? 40.0f : 60.0f);  // 10 frames in 500 ms
    EXPECT_EQ(ui::frameRateText(h), "20.0 fps (50.0 ms)");
    UiDriver d;
    d.in.cpuFrameMs = 125.0;
    d.frames(3);
    EXPECT_TRUE(d.drawn("status.fps"));
    EXPECT_GE(d.rect("status.fps").min.y, 720.0f - 40.0f) << "along the bottom of the window";
}
