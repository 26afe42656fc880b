// The Tune panel's runs: the product's own `shadowtune tune` as a child process, polled as the
// editor's frames would. progress.json reads into the panel's counts and chart (errors in the
// figure table's display unit, the front of the feasible points only); a run ends Done with its
// explanation, whose changes applied to the live settings give exactly the tuned preset's method;
// a cancel stops it with what was measured; a missing binary is an error, not a crash.
#include "app/editor/editor_tune.h"
#include "renderer/settings/settings_json.h"
#include "ui/document_actions.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <chrono>
#include <functional>
#include <thread>

namespace st::app {
namespace {
using State = ui::TuneView::State;
using Json = nlohmann::json;

Settings livePreset() {
    Settings s = loadPreset(std::string(ST_PRESET_DIR) + "/default.json");
    s.path.frames = 0;  // a still frame: no flicker constraint to measure
    return s;
}

void pollUntilEnded(EditorTune& t, const std::function<bool()>& until = {}) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (t.running() && std::chrono::steady_clock::now() < deadline) {
        t.poll();
        if (until && until()) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

const ui::SweepPoint* find(const ui::TuneView& v, const std::string& label) {
    for (const ui::SweepPoint& p : v.chart.points)
        if (p.label == label) return &p;
    return nullptr;
}

TEST(EditorTuneReadTest, ProgressBecomesCountsBestAndAChartOfTheFeasibleFront) {
    const Json progress = Json::parse(R"({
      "version": 1, "stage": "searching", "evaluations": 3, "limit": 10, "objective": "misclassified",
      "budgetMs": 4.0, "budgetBytes": 4194304,
      "input": {"error": 0.009, "costMs": 3.5, "mapBytes": 4194304},
      "references": {"current": {"error": 0.009, "costMs": 3.5, "mapBytes": 4194304, "budget": true},
                     "A": {"error": 0.002, "costMs": 9.0, "mapBytes": 16777216, "budget": false}},
      "best": {"error": 0.004, "costMs": 3.0, "mapBytes": 2097152},
      "points": [{"error": 0.009, "costMs": 3.5, "mapBytes": 4194304, "feasible": true},
                 {"error": 0.004, "costMs": 3.0, "mapBytes": 2097152, "feasible": true},
                 {"error": 0.001, "costMs": 8.0, "mapBytes": 4194304, "feasible": false}]})");
    ui::TuneView v;
    v.chart.width = 320, v.chart.height = 180;  // the tune's size (EditorTune::start)
    readTuneProgress(progress, v);
    EXPECT_EQ(v.done, 3);
    EXPECT_EQ(v.total, 10);
    EXPECT_EQ(v.best, "best 0.4 % at 3.0 ms");
    EXPECT_EQ(v.budget, "budget: 4.0 ms modelled at 320x180 and 4.0 MiB of maps") << "the size the cost is priced at";
    ASSERT_EQ(v.chart.points.size(), 5u);  // three evaluations, current and A
    EXPECT_DOUBLE_EQ(v.chart.points[1].error, 0.4) << "percent, as the figure table shows misclassified";
    EXPECT_DOUBLE_EQ(v.chart.points[1].memory, 2.0);
    EXPECT_FALSE(v.chart.points[0].frontByTime) << "dominated by evaluation 2";
    EXPECT_TRUE(v.chart.points[1].frontByTime);
    EXPECT_FALSE(v.chart.points[2].frontByTime) << "over the budget: never on the front";
    const ui::SweepPoint* a = find(v, "A");
    const ui::SweepPoint* current = find(v, "current");
    ASSERT_TRUE(a && current);
    EXPECT_TRUE(a->reference && current->reference);
    EXPECT_DOUBLE_EQ(a->cost, 9.0);
    EXPECT_FALSE(a->frontByTime);
}

TEST(EditorTuneReadTest, ExplanationLinesCarryTheFieldAndItsTunedValue) {
    const Json explain = Json::parse(R"({"changes": [
      {"field": "cascades.count", "from": 4, "to": 2, "text": "Cascades 4 -> 2: alone ..."},
      {"field": "filter.kind", "from": "pcf2x2", "to": "hard", "text": "Filter pcf2x2 -> hard: ..."},
      {"field": "cascades.manualSplits", "from": [], "to": [20.0, 50.0], "with": {"cascades.count": 3, "cascades.scheme": "manual"},
       "text": "Manual splits ..."}]})");
    const std::vector<ui::TuneChange> c = readExplanation(explain);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_TRUE(c[0].with.empty());
    ASSERT_EQ(c[2].with.size(), 2u);
    EXPECT_EQ(c[2].with[0], (std::pair<std::string, std::string>{"cascades.count", "3"}));
    EXPECT_EQ(c[2].with[1], (std::pair<std::string, std::string>{"cascades.scheme", "\"manual\""}));
    EXPECT_EQ(c[0].path, "cascades.count");
    EXPECT_EQ(c[0].valueJson, "2");
    EXPECT_EQ(c[1].valueJson, "\"hard\"");
    EXPECT_EQ(c[1].line, "Filter pcf2x2 -> hard: ...");
}

TEST(EditorTuneReadTest, TheBudgetChoiceBecomesTheTunesOptions) {
    ui::TuneRequest r;
    r.views = 3;
    auto has = [](const std::vector<std::string>& args, const std::string& option, const std::string& value) {
        for (std::size_t i = 0; i + 1 < args.size(); ++i)
            if (args[i] == option && args[i + 1] == value) return true;
        return false;
    };
    auto args = tuneArguments(r, "/d", false);
    EXPECT_TRUE(has(args, "--budget-from", "/d/current.json"));
    EXPECT_TRUE(has(args, "--hold-out-every", "2")) << "one held-out view of three: the last";
    EXPECT_TRUE(has(args, "--size", "320x180"));
    r.budget = ui::TuneRequest::Budget::Ms;
    r.ms = 12.5;
    args = tuneArguments(r, "/d", true);
    EXPECT_TRUE(has(args, "--budget-ms", "12.500"));
    EXPECT_TRUE(has(args, "--compare-with", "/d/A.json"));
    for (const std::string& a : args) EXPECT_NE(a, "--budget-from") << "a budget in ms is not the current one";
    EXPECT_EQ(std::count(args.begin(), args.end(), "--front"), 0);
    r.front = true;
    args = tuneArguments(r, "/d", false);
    EXPECT_EQ(std::count(args.begin(), args.end(), "--front"), 1);
}

// A --front tune's descent points break the input's constraints but are on its front.
TEST(EditorTuneReadTest, AFrontTunesPointsWithinTheBudgetAreOnItsFront) {
    const Json progress = Json::parse(R"({
      "version": 1, "stage": "done", "evaluations": 3, "limit": 3, "objective": "soft-filtered", "budgetMs": 4.0,
      "input": {"error": 0.009, "costMs": 3.5, "mapBytes": 4194304},
      "points": [{"error": 0.004, "costMs": 3.0, "mapBytes": 2097152, "feasible": true, "onFront": true},
                 {"error": 0.008, "costMs": 1.0, "mapBytes": 1048576, "feasible": false, "onFront": true},
                 {"error": 0.001, "costMs": 8.0, "mapBytes": 4194304, "feasible": false, "onFront": false}]})");
    ui::TuneView v;
    readTuneProgress(progress, v);
    ASSERT_EQ(v.chart.points.size(), 4u);
    EXPECT_TRUE(v.chart.points[0].frontByTime);
    EXPECT_TRUE(v.chart.points[1].frontByTime) << "cheaper, a constraint broken: on a --front tune's front";
    EXPECT_FALSE(v.chart.points[2].frontByTime) << "over the budget";
}

class EditorTuneTest : public ::testing::Test {
protected:
    void TearDown() override {
        if (!tune.view().folder.empty()) std::filesystem::remove_all(std::filesystem::path(tune.view().folder).parent_path());
    }
    static ui::TuneRequest small(int evaluations) {
        ui::TuneRequest r;
        r.objective = "misclassified";
        r.evaluations = evaluations;
        r.views = 1;
        r.width = 96;
        r.height = 54;
        return r;
    }
    EditorTune tune{ST_SHADOWTUNE};
};

TEST_F(EditorTuneTest, ARunEndsDoneAndItsChangesMakeTheTunedPreset) {
    Settings live = livePreset();
    live.bias.constant = 1.5f;  // a bias that detaches every shadow: the tune has something to fix
    live.bias.slope = 3.0f;
    Settings a = live;
    a.cascades.count = 1;
    tune.start(small(6), live, a, ST_PRESET_DIR);
    ASSERT_EQ(tune.view().state, State::Running) << (tune.view().errors.empty() ? "" : tune.view().errors[0]);
    pollUntilEnded(tune);
    const ui::TuneView& v = tune.view();
    ASSERT_EQ(v.state, State::Done) << (v.errors.empty() ? "" : v.errors.back());
    EXPECT_EQ(v.stage, "done");
    EXPECT_GE(v.done, 1);
    ASSERT_TRUE(find(v, "current") && find(v, "A"));
    EXPECT_NE(v.result.find("Tuned: misclassified"), std::string::npos) << v.result;
    ASSERT_FALSE(v.changes.empty()) << "a 1.5 m bias leaves room to improve";
    // Every change applied to the live settings gives the tuned preset's method.
    std::vector<std::pair<std::string, std::string>> all;
    for (const ui::TuneChange& c : v.changes) all.emplace_back(c.path, c.valueJson);
    const Settings applied = ui::withAssignments(live, all);
    const Settings tuned = loadPreset(std::filesystem::path(v.folder) / "tuned.json");
    EXPECT_EQ(applied.cascades, tuned.cascades);
    EXPECT_EQ(applied.filter, tuned.filter);
    EXPECT_EQ(applied.bias, tuned.bias);
}

TEST_F(EditorTuneTest, CancelStopsWithWhatWasMeasured) {
    tune.start(small(200), livePreset(), std::nullopt, ST_PRESET_DIR);
    ASSERT_EQ(tune.view().state, State::Running);
    pollUntilEnded(tune, [&] { return tune.view().done >= 1; });
    tune.cancel();
    EXPECT_EQ(tune.view().state, State::Cancelling);
    pollUntilEnded(tune);
    const ui::TuneView& v = tune.view();
    EXPECT_FALSE(tune.running());
    EXPECT_EQ(v.state, State::Cancelled) << (v.errors.empty() ? "" : v.errors.back());
    EXPECT_GE(v.done, 1);
    EXPECT_LT(v.done, 200);
    EXPECT_FALSE(v.chart.points.empty());
}

TEST(EditorTuneBinaryTest, AMissingBinaryIsAnError) {
    EditorTune t("/nonexistent/shadowtune");
    t.start(ui::TuneRequest{}, livePreset(), std::nullopt, ST_PRESET_DIR);
    EXPECT_FALSE(t.running());
    ASSERT_EQ(t.view().state, State::Failed);
    EXPECT_NE(t.view().errors[0].find("/nonexistent/shadowtune"), std::string::npos) << t.view().errors[0];
}

}  // namespace
}  // namespace st::app
