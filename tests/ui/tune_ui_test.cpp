// The Tune panel under ImGui's null backend: Go sends the panel's budget and objective, a bad
// budget refuses Go, the tuned settings and each explanation line apply as one undo step each,
// a cancel leaves the document alone, and advice's "Tune for this" opens the panel on its figure.
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"
#include "ui/tune_view.h"

#include <gtest/gtest.h>

using namespace st;
using namespace st::test;

namespace {


class TuneUiTest : public ::testing::Test {
protected:
    void SetUp() override {
        d.in.stats = &stats;
        d.in.tuneObjectives = {{"misclassified", "misclassified"}, {"soft-filtered", "filtered error vs the sun's disc"},
                               {"acne", "acne"}};
        d.frames(2);
    }
    void openTunePanel() {
        d.chooseMenu("menu.compare", "menu.compare.tune");
        ASSERT_TRUE(d.drawn("tune.go"));
    }
    // A finished tune that changed the count and the slope bias.
    static ui::TuneView doneView() {
        ui::TuneView v;
        v.state = ui::TuneView::State::Done;
        v.stage = "done";
        v.done = v.total = 8;
        v.best = "best 0.4 % at 3.0 ms";
        auto point = [](std::string label, double ms, double err, bool reference, bool front) {
            ui::SweepPoint p;
            p.label = std::move(label);
            p.cost = ms, p.error = err, p.memory = 4.0, p.reference = reference;
            p.frontByTime = p.frontByMemory = front;
            return p;
        };
        v.chart.points = {point("evaluation 1", 3.5, 0.9, false, false), point("evaluation 2", 3.0, 0.4, false, true),
                          point("current", 3.5, 0.9, true, false)};
        v.changes = {{"Cascades 4 -> 2: alone -0.3 pp", "cascades.count", "2"},
                     {"Slope bias 1 -> 0.5: alone -0.2 pp", "bias.slope", "0.5"}};
        v.result = "Tuned: misclassified 0.4 % at 3.0 ms (current 0.9 % at 3.5 ms), on the tuned views.";
        return v;
    }

    FrameStats stats = fakeFrameStats();
    UiDriver d;
};

}  // namespace

TEST_F(TuneUiTest, GoSendsTheBudgetAndObjectiveThePanelShows) {
    openTunePanel();
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_EQ(d.last.tuneStart->budget, ui::TuneRequest::Budget::AsNow);
    EXPECT_EQ(d.last.tuneStart->objective, "soft-filtered");
    d.frames(2);
    d.click("tune.budget.ms");
    d.frames(2);
    d.replaceText("tune.ms", "30");
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_EQ(d.last.tuneStart->budget, ui::TuneRequest::Budget::Ms);
    EXPECT_DOUBLE_EQ(d.last.tuneStart->ms, 30.0);
    EXPECT_FALSE(d.last.tuneStart->front);
    d.frames(2);
    d.click("tune.front");
    d.frames(2);
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_TRUE(d.last.tuneStart->front) << "the front checkbox asks for tune --front";
}

TEST_F(TuneUiTest, ABudgetOfNothingRefusesGo) {
    openTunePanel();
    d.click("tune.budget.mib");
    d.frames(2);
    d.replaceText("tune.mib", "0");
    d.click("tune.go");
    EXPECT_FALSE(d.last.tuneStart.has_value());
    d.replaceText("tune.mib", "8");
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_DOUBLE_EQ(d.last.tuneStart->mib, 8.0);
}

TEST_F(TuneUiTest, ApplyTunedIsOneUndoStep) {
    openTunePanel();
    const ui::TuneView v = doneView();
    d.in.tune = &v;
    d.frames(2);
    EXPECT_TRUE(d.drawn("tune.plot"));
    EXPECT_TRUE(d.drawn("tune.result"));
    const Settings before = d.s;
    ASSERT_NE(before.cascades.count, 2);
    d.click("tune.apply");
    EXPECT_EQ(d.s.cascades.count, 2);
    EXPECT_FLOAT_EQ(d.s.bias.slope, 0.5f);
    Settings expected = before;
    expected.cascades.count = 2;
    expected.bias.slope = 0.5f;
    EXPECT_EQ(d.s, expected);  // nothing else changed
    d.frames(2);
    EXPECT_TRUE(d.drawn("tune.applied"));
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);  // there was no other step
}

TEST_F(TuneUiTest, EachExplanationLineAppliesAloneAsOneUndoStep) {
    openTunePanel();
    const ui::TuneView v = doneView();
    d.in.tune = &v;
    d.frames(2);
    const Settings before = d.s;
    d.click("tune.change.1");
    Settings expected = before;
    expected.bias.slope = 0.5f;
    EXPECT_EQ(d.s, expected) << "only the slope bias";
    d.frames(2);
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);
}

// A line that needs other fields (manual splits: the count and the manual scheme) sets them with
// it, in one undo step.
TEST_F(TuneUiTest, ALineWithTheFieldsItNeedsAppliesThemTogether) {
    openTunePanel();
    ui::TuneView v = doneView();
    v.changes = {{"Manual splits [] -> 20, 50 m (with 3 cascades and the manual scheme): ...", "cascades.manualSplits",
                  "[20.0, 50.0]", {{"cascades.count", "3"}, {"cascades.scheme", "\"manual\""}}}};
    d.in.tune = &v;
    d.frames(2);
    const Settings before = d.s;
    ASSERT_NE(before.cascades.count, 3);
    d.click("tune.change.0");
    EXPECT_EQ(d.s.cascades.count, 3);
    EXPECT_EQ(d.s.cascades.scheme, SplitScheme::Manual);
    EXPECT_EQ(d.s.cascades.manualSplits, (std::vector<float>{20.0f, 50.0f}));
    d.frames(2);
    d.pressKey(kKeyZ, true);
    EXPECT_EQ(d.s, before);
}

TEST_F(TuneUiTest, ACancelledTuneLeavesTheDocumentAsItWas) {
    openTunePanel();
    ui::TuneView v = doneView();
    v.state = ui::TuneView::State::Running;
    v.done = 3;
    v.changes.clear();
    d.in.tune = &v;
    d.frames(2);
    EXPECT_FALSE(d.drawn("tune.go")) << "no second run while one runs";
    const Settings before = d.s;
    d.click("tune.cancel");
    EXPECT_TRUE(d.last.tuneCancel);
    v.state = ui::TuneView::State::Cancelled;
    d.frames(3);
    EXPECT_EQ(d.s, before);
    EXPECT_FALSE(d.ui().dirty());
    EXPECT_TRUE(d.drawn("tune.go"));
}

TEST_F(TuneUiTest, AdviceOpensThePanelOnItsFigure) {
    stats.cascades[3].texelWorldSize = 1.7f;  // truck_town's far cascade: coarse-texel advice
    d.in.accuracy.state = ui::AccuracyView::State::Done;
    d.in.accuracy.all.receivers = 1000;
    d.in.accuracy.all.falseLightGross = 40;  // peter-panning advice
    d.frames(2);
    EXPECT_FALSE(d.drawn("tune.go"));
    d.click("advice.peter-panning.tune");
    d.frames(2);
    ASSERT_TRUE(d.drawn("tune.go"));
    d.click("tune.go");
    ASSERT_TRUE(d.last.tuneStart.has_value());
    EXPECT_EQ(d.last.tuneStart->objective, "peter-panning");
    EXPECT_EQ(ui::tuneObjectiveFor("coarse-texel"), "misclassified");
    EXPECT_EQ(ui::tuneObjectiveFor("acne"), "acne");
}

// Issue 39 #8: the Tune window opens over the right column, not over the scene's left half (an
// A/B split's A) where it opened before.
TEST_F(TuneUiTest, TheTuneWindowOpensOverTheRightColumn) {
    openTunePanel();
    d.frame();
    const ui::ItemRect w = d.rect("window.Tune");
    const float sceneMid = d.last.scenePos.x + 0.5f * d.last.sceneSize.x;
    EXPECT_GT(w.min.x, sceneMid) << "the scene's left half stays in view";
    EXPECT_NEAR(w.max.x, ImGui::GetIO().DisplaySize.x, 1.0f) << "against the window's right edge";
}
