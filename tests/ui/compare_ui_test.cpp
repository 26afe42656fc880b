// The A/B split and the Sweep panel under ImGui's null backend: Set as A and the divider, axis
// errors shown (and Run refused), Run's request, a chart point applied as one undo step, and a
// cancelled sweep that leaves the document as it was.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::test;

namespace {


class CompareUiTest : public ::testing::Test {
protected:
    void SetUp() override {
        d.in.stats = &stats;
        d.in.sweepableFields = {"cascades.count", "cascades.mapSize", "cascades.lambda", "cascades.fit"};
        d.frames(2);
    }
    void openSweepPanel() {
        d.chooseMenu("menu.compare", "menu.compare.sweep");
        ASSERT_TRUE(d.drawn("sweep.run"));
    }
    // Three grid points along cascades.count x mapSize and the "current" reference.
    static ui::SweepView doneView() {
        ui::SweepView v;
        v.state = ui::SweepView::State::Done;
        v.total = v.done = 4;
        v.scene = "builtin:yard";
        v.width = 320, v.height = 180;
        auto point = [](std::string label, double ms, double err, int count, int size, bool front) {
            ui::SweepPoint p;
            p.label = std::move(label);
            p.cost = ms, p.error = err, p.memory = count * size * size * 4.0 / (1 << 20);
            p.frontByTime = p.frontByMemory = front;
            p.figures = "misclassified " + std::to_string(err) + " %";
            p.assignments = {{"cascades.count", std::to_string(count)}, {"cascades.mapSize", std::to_string(size)}};
            return p;
        };
        v.points = {point("count=1 mapSize=512", 1.0, 0.9, 1, 512, true), point("count=2 mapSize=2048", 2.0, 0.2, 2, 2048, true),
                    point("count=3 mapSize=1024", 3.0, 0.5, 3, 1024, false), point("current", 2.5, 0.3, 4, 1024, false)};
        v.points[3].reference = true;
        return v;
    }

    FrameStats stats = fakeFrameStats();
    UiDriver d;
};

}  // namespace

TEST_F(CompareUiTest, SetAsASnapshotsTheSettingsAndTurnsTheSplitOn) {
    EXPECT_EQ(d.last.abSettings, nullptr);
    EXPECT_FALSE(d.last.abSplit);
    const Settings before = d.s;
    d.pressKey(kKeyA, true, true);  // Ctrl+Shift+A
    d.frame();
    ASSERT_NE(d.last.abSettings, nullptr);
    EXPECT_TRUE(d.last.abSplit);
    EXPECT_EQ(*d.last.abSettings, before);
    d.s.cascades.count = 1;  // the live settings move on, A stays
    d.frame();
    EXPECT_EQ(d.last.abSettings->cascades.count, before.cascades.count);
    EXPECT_TRUE(d.drawn("ab.labelA"));
    EXPECT_TRUE(d.drawn("ab.labelLive"));
    d.pressKey(66, true, true);  // Ctrl+Shift+B: split off, A kept
    d.frame();
    EXPECT_FALSE(d.last.abSplit);
    EXPECT_NE(d.last.abSettings, nullptr);
    EXPECT_FALSE(d.drawn("ab.divider"));
}

// Issue 21 #10: with the divider near the scene's edge a label ran under the panel ("live: 1.089").
TEST_F(CompareUiTest, TheLabelsStayInsideTheSceneWithTheDividerAtAnEdge) {
    d.chooseMenu("menu.compare", "menu.compare.setA");
    ASSERT_TRUE(d.last.abSplit);
    const float left = d.last.scenePos.x, right = left + d.last.sceneSize.x;
    for (const float to : {right + 50.0f, left - 50.0f}) {
        const ImVec2 grip = d.rect("ab.divider").center();
        d.drag(grip, {to, grip.y});
        d.frames(2);
        const ui::ItemRect a = d.rect("ab.labelA"), live = d.rect("ab.labelLive");
        EXPECT_GE(a.min.x, left) << "divider " << d.last.abDivider;
        EXPECT_LE(live.max.x, right) << "divider " << d.last.abDivider;
        EXPECT_LE(a.max.x, right);
        EXPECT_GE(live.min.x, left);
        const bool apart = a.max.x <= live.min.x || live.max.x <= a.min.x || a.max.y <= live.min.y || live.max.y <= a.min.y;
        EXPECT_TRUE(apart) << "the labels overlap";
    }
}

TEST_F(CompareUiTest, DraggingTheDividerMovesItAndNotTheSettings) {
    d.chooseMenu("menu.compare", "menu.compare.setA");
    ASSERT_TRUE(d.last.abSplit);
    EXPECT_FLOAT_EQ(d.last.abDivider, 0.5f);
    const Settings before = d.s;
    // The divider splits the scene viewport the panels leave, not the window.
    const float left = d.last.scenePos.x, width = d.last.sceneSize.x;
    ASSERT_GT(width, 100.0f);
    const ImVec2 grip = d.rect("ab.divider").center();
    EXPECT_NEAR(grip.x, left + 0.5f * width, 2.0f);
    d.drag(grip, {grip.x - 0.25f * width, grip.y});
    d.frame();
    EXPECT_NEAR(d.last.abDivider, 0.25f, 0.01f);  // a quarter of the viewport to the left
    EXPECT_NEAR(d.rect("ab.divider").center().x, left + 0.25f * width, 2.0f);
    EXPECT_EQ(d.s, before);
}

TEST_F(CompareUiTest, ThePanelsButtonsSetAAndToggleTheSplit) {
    openSweepPanel();
    d.click("sweep.setA");
    d.frame();
    ASSERT_NE(d.last.abSettings, nullptr);
    EXPECT_TRUE(d.last.abSplit);
    d.click("sweep.split");
    d.frame();
    EXPECT_FALSE(d.last.abSplit);
}

TEST_F(CompareUiTest, RunSendsTheAxesAsTheSweepFileSpellsThem) {
    openSweepPanel();
    d.replaceText("sweep.axis1.values", "1, 3");
    d.click("sweep.run");
    ASSERT_TRUE(d.last.sweepStart.has_value());
    const ui::SweepRequest& r = *d.last.sweepStart;
    ASSERT_EQ(r.axes.size(), 2u);
    EXPECT_EQ(r.axes[0].field, "cascades.count");
    EXPECT_EQ(r.axes[0].values, nlohmann::json::parse("[1, 3]"));
    EXPECT_EQ(r.axes[1].field, "cascades.mapSize");
    EXPECT_EQ(r.axes[1].values, nlohmann::json::parse("[512, 1024, 2048]"));
    EXPECT_EQ(r.width, 320);
    EXPECT_EQ(r.height, 180);
}

TEST_F(CompareUiTest, BadAxisValuesAreShownAndRunIsRefused) {
    openSweepPanel();
    EXPECT_FALSE(d.drawn("sweep.errors"));
    d.replaceText("sweep.axis1.values", "1, 9");  // cascades.count is 1..8
    EXPECT_TRUE(d.drawn("sweep.errors"));
    d.click("sweep.run");
    EXPECT_FALSE(d.last.sweepStart.has_value());
    d.replaceText("sweep.axis1.values", "2");
    EXPECT_FALSE(d.drawn("sweep.errors"));
    d.click("sweep.run");
    EXPECT_TRUE(d.last.sweepStart.has_value());
}

TEST_F(CompareUiTest, ClickingAChartPointAppliesItsValuesAsOneUndoStep) {
    openSweepPanel();
    const ui::SweepView v = doneView();
    d.in.sweep = &v;
    d.frames(2);
    const Settings before = d.s;
    ASSERT_NE(before.cascades.count, 2);
    d.click("sweep.point.1");
    EXPECT_EQ(d.s.cascades.count, 2);
    EXPECT_EQ(d.s.cascades.mapSize, 2048);
    Settings expected = before;
    expected.cascades.count = 2;
    expected.cascades.mapSize = 2048;
    EXPECT_EQ(d.s, expected);  // nothing else changed
    d.frames(2);
    d.pressKey(kKeyZ, true);  // one Ctrl+Z undoes both fields
    EXPECT_EQ(d.s, before);
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);  // and there was no other step
}

// Issue 21 #11: "applied lambda=0.95" and the chart stayed after the camera moved.
TEST_F(CompareUiTest, TheChartAndTheAppliedNoteGoStaleWhenTheViewMoves) {
    openSweepPanel();
    ui::SweepView v = doneView();
    v.measuredFrom = d.s;
    d.in.sweep = &v;
    d.frames(2);
    EXPECT_FALSE(d.drawn("sweep.stale"));
    d.click("sweep.point.1");
    d.frames(2);
    EXPECT_TRUE(d.drawn("sweep.applied"));
    EXPECT_FALSE(d.drawn("sweep.stale")) << "applying a point changes no camera";
    d.s.bias.slope += 0.5f;  // another edit: the note no longer describes the settings
    d.frames(2);
    EXPECT_FALSE(d.drawn("sweep.applied"));
    d.s.camera.position.x += 3.0f;  // the app's fly gesture
    d.frames(2);
    EXPECT_TRUE(d.drawn("sweep.stale"));
    EXPECT_TRUE(d.drawn("sweep.point.1")) << "still there to read, greyed";
}

TEST_F(CompareUiTest, ACancelledSweepLeavesTheDocumentAsItWas) {
    openSweepPanel();
    ui::SweepView v = doneView();
    v.state = ui::SweepView::State::Running;
    v.done = 2;
    v.points.resize(2);
    d.in.sweep = &v;
    d.frames(2);
    const Settings before = d.s;
    d.click("sweep.cancel");
    EXPECT_TRUE(d.last.sweepCancel);
    v.state = ui::SweepView::State::Cancelled;  // the app's answer once the child has stopped
    d.frames(3);
    EXPECT_EQ(d.s, before);
    EXPECT_FALSE(d.ui().dirty());
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);  // no undo step was recorded
    EXPECT_TRUE(d.drawn("sweep.run"));  // and another run can start
}
