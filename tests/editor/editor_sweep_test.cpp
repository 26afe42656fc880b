// The Sweep panel's runs: the product's own `shadowtune sweep` as a child process, polled as the
// editor's frames would. A run ends Done with every point (A's reference measuring what the grid
// point with A's values measures), a cancel stops it early with the points measured so far, a
// refused sweep never starts a child, and a missing binary is an error, not a crash.
#include "app/editor/editor_sweep.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace st::app {
namespace {
using State = ui::SweepView::State;

Settings livePreset() { return loadPreset(std::string(ST_PRESET_DIR) + "/default.json"); }

// Polls like the editor (every 20 ms) until the run ends or `until` says stop waiting.
void pollUntilEnded(EditorSweep& s, const std::function<bool()>& until = {}) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(3);
    while (s.running() && std::chrono::steady_clock::now() < deadline) {
        s.poll();
        if (until && until()) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

ui::SweepRequest countRequest(nlohmann::json values) {
    ui::SweepRequest r;
    r.axes.push_back({"cascades.count", std::move(values), false});
    r.width = 96;
    r.height = 54;
    return r;
}

const ui::SweepPoint* find(const ui::SweepView& v, const std::string& label) {
    for (const ui::SweepPoint& p : v.points)
        if (p.label == label) return &p;
    return nullptr;
}

// A point as the chart shows it: the default error and cost choices of the figure table, in
// their display units, and one hover line per Sweep-panel row.
TEST(EditorSweepChartTest, PointShowsTheTablesChoicesInTheirUnits) {
    metrics::PresetMeasurement m;
    m.accuracy.all.receivers = 400;
    m.accuracy.all.falseShadowEdge = 6;  // 1.5 %
    m.cost = metrics::CostReport{};
    m.cost->gpuShadowMs = 2.0, m.cost->gpuMainMs = 3.0, m.cost->gpuFilterMs = 0.5;
    m.cost->shadowMapBytes = 8u << 20, m.cost->filterMapBytes = 2u << 20;
    m.cost->model = metrics::ModelledCost{{4.0}, 4.0, 3.25, 0.0, 0.0, 7.25};
    sweep::PointResult r{"1", "count=1", false, {"1"}, toOrderedJson(Settings{}), sweep::figuresOf(m)};
    const ui::SweepPoint p = chartPoint(r, {"cascades.count"});
    EXPECT_DOUBLE_EQ(p.error, 1.5);
    EXPECT_DOUBLE_EQ(p.cost, 7.25) << "the chart's cost is the modelled one";
    EXPECT_DOUBLE_EQ(p.memory, 10.0);
    for (const metrics::FigureRow* row : metrics::figuresShown(metrics::InEditorSweep))
        EXPECT_NE(p.figures.find(row->label + " " + metrics::formatValue(row->unit, row->read(m))), std::string::npos)
            << row->key << " in\n" << p.figures;
    EXPECT_NE(p.figures.find("misclassified 1.500 %"), std::string::npos) << p.figures;
}

class EditorSweepTest : public ::testing::Test {
protected:
    void TearDown() override {
        if (!sweep.folder().empty()) std::filesystem::remove_all(sweep.folder());
    }
    EditorSweep sweep{ST_SHADOWTUNE, 1};
};

TEST_F(EditorSweepTest, RunEndsDoneWithEveryPointAndMarkedReferences) {
    Settings a = livePreset();
    a.cascades.count = 2;
    sweep.start(countRequest({1, 2}), livePreset(), a, ST_PRESET_DIR);
    ASSERT_EQ(sweep.view().state, State::Running) << (sweep.view().errors.empty() ? "" : sweep.view().errors[0]);
    EXPECT_EQ(sweep.view().total, 4u);  // two grid points, "current" and "A"
    pollUntilEnded(sweep);
    const ui::SweepView& v = sweep.view();
    ASSERT_EQ(v.state, State::Done) << (v.errors.empty() ? "" : v.errors[0]);
    EXPECT_EQ(v.done, 4u);
    ASSERT_EQ(v.points.size(), 4u);
    const ui::SweepPoint* one = find(v, "count=1");
    const ui::SweepPoint* two = find(v, "count=2");
    const ui::SweepPoint* pa = find(v, "A");
    const ui::SweepPoint* current = find(v, "current");
    ASSERT_TRUE(one && two && pa && current);
    EXPECT_TRUE(pa->reference && current->reference && !one->reference);
    // A is the live settings with count 2: the same frame as the grid's count=2 point.
    EXPECT_DOUBLE_EQ(pa->error, two->error);
    EXPECT_DOUBLE_EQ(pa->memory, two->memory);
    EXPECT_DOUBLE_EQ(one->memory, 4.0);  // one 1024^2 layer of 32-bit depth
    EXPECT_DOUBLE_EQ(current->memory, 16.0);
    EXPECT_EQ(one->assignments, (std::vector<std::pair<std::string, std::string>>{{"cascades.count", "1"}}));
    bool hasCount = false;
    for (const auto& [path, value] : pa->assignments) hasCount |= path == "cascades.count" && value == "2";
    EXPECT_TRUE(hasCount);  // a reference applies its whole method
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(v.folder) / "pareto.png"));
}

TEST_F(EditorSweepTest, CancelStopsAfterThePointInHandAndKeepsThoseMeasured) {
    ui::SweepRequest r = countRequest({1, 2, 3, 4});
    r.axes.push_back({"cascades.lambda", {{"from", 0.1}, {"to", 0.9}, {"step", 0.1}}, true});
    sweep.start(r, livePreset(), std::nullopt, ST_PRESET_DIR);
    ASSERT_EQ(sweep.view().state, State::Running);
    EXPECT_EQ(sweep.view().total, 37u);
    pollUntilEnded(sweep, [&] { return sweep.view().done >= 1; });
    sweep.cancel();
    EXPECT_EQ(sweep.view().state, State::Cancelling);
    pollUntilEnded(sweep);
    const ui::SweepView& v = sweep.view();
    EXPECT_FALSE(sweep.running());
    EXPECT_EQ(v.state, State::Cancelled);
    EXPECT_GE(v.done, 1u);
    EXPECT_LT(v.done, v.total);
    EXPECT_EQ(v.points.size(), v.done);
}

// Issue 21 #11: Cancel pressed once every point was in said "Cancelled after 4 of 4 points".
TEST_F(EditorSweepTest, ACancelAfterTheLastPointLeavesTheRunDone) {
    sweep.start(countRequest({1, 2}), livePreset(), std::nullopt, ST_PRESET_DIR);
    ASSERT_EQ(sweep.view().state, State::Running);
    pollUntilEnded(sweep, [&] { return sweep.view().done >= sweep.view().total; });
    sweep.cancel();  // the child writes its charts, or has ended unseen: nothing is left to stop
    pollUntilEnded(sweep);
    const ui::SweepView& v = sweep.view();
    EXPECT_EQ(v.state, State::Done) << (v.errors.empty() ? "" : v.errors[0]);
    EXPECT_EQ(v.done, v.total);
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(v.folder) / "pareto.png"));
}

TEST_F(EditorSweepTest, ARefusedSweepSaysWhyAndStartsNothing) {
    ui::SweepRequest r = countRequest({1, 99});
    sweep.start(r, livePreset(), std::nullopt, ST_PRESET_DIR);
    EXPECT_FALSE(sweep.running());
    ASSERT_EQ(sweep.view().state, State::Failed);
    ASSERT_FALSE(sweep.view().errors.empty());
    EXPECT_NE(sweep.view().errors[0].find("axes[0].values[1]"), std::string::npos) << sweep.view().errors[0];
}

TEST(EditorSweepBinaryTest, AMissingBinaryIsAnError) {
    EditorSweep sweep("/nonexistent/shadowtune", 1);
    sweep.start(countRequest({1}), livePreset(), std::nullopt, ST_PRESET_DIR);
    pollUntilEnded(sweep);
    EXPECT_EQ(sweep.view().state, State::Failed);
    ASSERT_FALSE(sweep.view().errors.empty());
    std::filesystem::remove_all(std::filesystem::path(sweep.view().folder).parent_path());
}

}  // namespace
}  // namespace st::app
