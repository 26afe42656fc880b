// The tuner on a real frame: its search beats a grid of the same (and of a quarter of the)
// evaluation count within the same modelled budget, on the yard at a small size; and the
// evaluation it scores is the figures `measure` reports.
#include "app/cost_profile_file.h"
#include "metrics/measure_session.h"
#include "renderer/context/egl_context.h"
#include "renderer/gpu/debug_output.h"
#include "renderer/settings/settings_json.h"
#include "tune/tune_eval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace st::tune {
namespace {

class TuneGLTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        context_ = HeadlessContext::create(true);
        gpu::enableDebugOutput();
    }
    static void TearDownTestSuite() { context_.reset(); }
    void TearDown() override { EXPECT_EQ(gpu::seriousDebugMessageCount(), 0); }
    static std::unique_ptr<HeadlessContext> context_;
};
std::unique_ptr<HeadlessContext> TuneGLTest::context_;

Settings smallYard() {
    Settings s = loadPreset(std::filesystem::path(ST_SOURCE_DIR) / "presets/default.json");
    s.output.width = 96;
    s.output.height = 54;
    return s;
}

// The shipped sweeps' axes (count, map size, fit, split weight): every combination.
std::vector<Settings> grid(const Settings& base) {
    std::vector<Settings> out;
    for (int count : {1, 2, 4})
        for (int mapSize : {512, 1024, 2048})
            for (FitMode fit : {FitMode::Cascade, FitMode::Sphere})
                for (float lambda : {0.5f, 0.8f, 0.95f}) {
                    Settings s = base;
                    s.cascades.count = count;
                    s.cascades.mapSize = mapSize;
                    s.cascades.fit = fit;
                    s.cascades.lambda = lambda;
                    out.push_back(s);
                }
    return out;
}

TEST_F(TuneGLTest, TheSearchBeatsAGridOfTheSameEvaluationCountWithinTheBudget) {
    const Settings base = smallYard();
    const metrics::CostProfile profile = app::loadCostProfileOption("");
    metrics::MeasureSession session;
    ViewEvaluator evaluate(session, ST_SOURCE_DIR "/presets", tuneViews(base, 1, 0), profile, {"soft-filtered", {}});
    Budget budget;
    budget.ms = evaluate(base).costMs;  // as cheap as the input preset
    double gridBest = INFINITY;
    const std::vector<Settings> points = grid(base);
    for (const Settings& s : points) {
        const Evaluation e = evaluate(s);
        if (e.valid && budget.fits(e)) gridBest = std::min(gridBest, e.error);
    }
    ASSERT_TRUE(std::isfinite(gridBest)) << "some grid point fits the budget";
    for (const int evaluations : {int(points.size()), int(points.size()) / 4}) {
        SearchOptions opt;
        opt.budget = budget;
        opt.evaluations = evaluations;
        const SearchResult r = search({base}, defaultSpace(base), evaluate, opt);
        ASSERT_TRUE(r.best);
        const Evaluation& best = r.evaluated[*r.best].eval;
        std::printf("budget %.2f ms: grid of %zu points best %.6f, search of %d evaluations best %.6f at %.2f ms\n",
                    *budget.ms, points.size(), gridBest, r.evaluations, best.error, best.costMs);
        EXPECT_LE(best.costMs, *budget.ms);
        EXPECT_LT(best.error, gridBest) << "with " << evaluations << " evaluations";
    }
}

// What the tuner scores is what `measure` reports for the same settings on the same view.
TEST_F(TuneGLTest, AnEvaluationIsMeasuresFigures) {
    Settings s = smallYard();
    s.cascades.count = 3;
    const metrics::CostProfile profile = app::loadCostProfileOption("");
    metrics::MeasureSession session;
    ViewEvaluator evaluate(session, ST_SOURCE_DIR "/presets", tuneViews(s, 1, 0), profile, {"misclassified", {}});
    const Evaluation e = evaluate(s);
    metrics::MeasureOptions mo;
    mo.costFrames = 2;
    mo.costProfile = &profile;
    mo.flicker = false;
    metrics::MeasureSession other;
    const metrics::PresetMeasurement m = other.measure(s, ST_SOURCE_DIR "/presets", mo);
    EXPECT_DOUBLE_EQ(e.error, m.accuracy.all.share(m.accuracy.all.misclassified()));
    ASSERT_TRUE(m.cost && m.cost->model);
    EXPECT_DOUBLE_EQ(e.costMs, m.cost->model->totalMs) << "counted once = timed frames' counted work";
    EXPECT_DOUBLE_EQ(e.mapBytes, double(m.cost->shadowMapBytes + m.cost->filterMapBytes));
}

}  // namespace
}  // namespace st::tune

namespace st::tune {
namespace {

// presets/tuned/<scene>-at-<reference>-budget.json (docs/tuning.md, scripts/tune_all.sh): each loads, is
// the tune of a shipped scene preset at a shipped reference's budget, and keeps that scene's file
// and output size's aspect.
TEST(TunedPresetsTest, EachLoadsAndNamesItsSceneAndReference) {
    namespace fs = std::filesystem;
    const fs::path root = ST_SOURCE_DIR "/presets";
    int count = 0;
    for (const auto& e : fs::directory_iterator(root / "tuned")) {
        if (e.path().extension() != ".json") continue;
        SCOPED_TRACE(e.path().string());
        ++count;
        const std::string stem = e.path().stem().string();
        const std::size_t at = stem.find("-at-");
        const std::string suffix = "-budget";
        ASSERT_NE(at, std::string::npos) << "named <scene>-at-<reference>-budget";
        ASSERT_TRUE(stem.size() > suffix.size() && stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
            << "named <scene>-at-<reference>-budget";
        const std::string scene = stem.substr(0, at), ref = stem.substr(at + 4, stem.size() - suffix.size() - at - 4);
        const fs::path scenePreset = scene == "yard" ? root / "default.json" : root / "scenes" / (scene + ".json");
        EXPECT_TRUE(fs::exists(root / (ref + ".json")) || fs::exists(root / "engines" / (ref + ".json"))) << ref;
        ASSERT_TRUE(fs::exists(scenePreset)) << scenePreset;
        const Settings tuned = loadPreset(e.path());
        const Settings input = loadPreset(scenePreset);
        EXPECT_EQ(fs::path(tuned.scene).filename(), fs::path(input.scene).filename());
        EXPECT_EQ(tuned.output.width * input.output.height, tuned.output.height * input.output.width);
        EXPECT_EQ(tuned.light.azimuth, input.light.azimuth);
    }
    EXPECT_GE(count, 14) << "the yard and six scenes, each against ogldev-49 and Unreal's default";
}

}  // namespace
}  // namespace st::tune

namespace st::tune {
namespace {

// A renderer per view keeps each view's maps across candidates that change only the filter or
// the bias, and scores them exactly as one renderer redrawing every map at each view does.
TEST_F(TuneGLTest, KeptMapsPerViewScoreExactlyAsRedrawnMaps) {
    const Settings base = smallYard();
    std::vector<Settings> candidates(5, base);
    candidates[1].bias.slope += 0.5f;
    candidates[2].filter.kind = FilterKind::PcfNxN;
    candidates[3].bias.normalOffset = 0.5f;
    candidates[4].cascades.lambda = 0.5f;  // new splits: every map is redrawn
    const metrics::CostProfile profile = app::loadCostProfileOption("");
    metrics::MeasureSession a, b;
    ViewEvaluator perView(a, ST_SOURCE_DIR "/presets", tuneViews(base, 3, 0), profile, {"misclassified", {}});
    ViewEvaluator shared(b, ST_SOURCE_DIR "/presets", tuneViews(base, 3, 0), profile, {"misclassified", {}});
    shared.setRendererPerView(false);
    int keptBefore = 0, drawnBefore = 0, sharedDrawnBefore = 0;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const Evaluation kept = perView(candidates[i]), redrawn = shared(candidates[i]);
        EXPECT_EQ(kept.figures, redrawn.figures) << "candidate " << i;
        if (i == 0) keptBefore = perView.mapsKept(), drawnBefore = perView.mapsDrawn(), sharedDrawnBefore = shared.mapsDrawn();
        if (i == 3) {  // the three filter and bias candidates: every view kept every map
            EXPECT_EQ(perView.mapsKept() - keptBefore, 3 * 3 * base.cascades.count);
            EXPECT_EQ(perView.mapsDrawn(), drawnBefore);
            EXPECT_GT(shared.mapsDrawn() - sharedDrawnBefore, 3 * base.cascades.count) << "one renderer alternating views redraws";
        }
    }
    EXPECT_GT(perView.mapsDrawn(), drawnBefore) << "new splits redraw";
}

}  // namespace
}  // namespace st::tune
