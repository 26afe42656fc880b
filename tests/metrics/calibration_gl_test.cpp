// Calibration timings (metrics/calibration.h) on a real render: every timed frame redraws every
// map whatever the renderer's cache setting, the setting is restored, and each pass's sample is
// the minimum and median of that pass's timer over the frames.
#include "metrics/calibration.h"
#include "metrics/cost.h"
#include "renderer/render/scene_cache.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <algorithm>

namespace st::metrics {
namespace {

class CalibrationGLTest : public test::GLTest {};

// calibrate keeps one scene in the context at a time: on llvmpipe another scene's renderer left
// alive slowed truck-town's frames by 25-45 % (docs/cost-model.md).
TEST_F(CalibrationGLTest, AKeepOneCacheDropsTheOtherSceneAndItsRenderer) {
    const Settings yard = test::presetAtTestSize("default", 160, 90);
    Settings box = yard;
    box.scene = "builtin:box-over-plane";
    SceneCache<> keepAll, keepOne(true);
    for (SceneCache<>* cache : {&keepAll, &keepOne}) {
        cache->rendererFor(yard, ST_PRESET_DIR);
        cache->rendererFor(yard, ST_PRESET_DIR);  // the same scene: kept
        EXPECT_EQ(cache->size(), 1u);
        cache->rendererFor(box, ST_PRESET_DIR);
    }
    EXPECT_EQ(keepAll.size(), 2u);
    EXPECT_EQ(keepOne.size(), 1u);
    keepOne.rendererFor(box, ST_PRESET_DIR).render(box);  // the kept one still draws
}

TEST_F(CalibrationGLTest, TimedFramesRedrawEveryMapAndSamplesArePerPass) {
    const Settings s = test::presetAtTestSize("default", 160, 90);
    SceneCache<> scenes;
    Renderer& r = scenes.rendererFor(s, ST_PRESET_DIR);
    ASSERT_TRUE(r.options().cacheMaps);
    r.render(s);  // a frame whose maps the timed frames would keep if the cache were on
    const TimedFrames t = timeFrames(r, s, 3);
    EXPECT_TRUE(r.options().cacheMaps) << "options restored";
    ASSERT_EQ(t.frames.size(), 3u);
    for (const FrameStats& f : t.frames) {
        ASSERT_EQ(f.cascades.size(), std::size_t(s.cascades.count));
        for (const CascadeStats& c : f.cascades) EXPECT_TRUE(c.redrawn) << c.mapReason;
    }
    EXPECT_TRUE(t.workStable);
    const std::vector<CalibrationSample> samples = passSamples("default", t);
    // Every redrawn map and the main pass counted work: one sample each, no filter or bounds.
    ASSERT_EQ(samples.size(), std::size_t(s.cascades.count) + 1);
    for (int i = 0; i < s.cascades.count; ++i) {
        EXPECT_EQ(samples[std::size_t(i)].kind, PassKind::Cascade);
        EXPECT_EQ(samples[std::size_t(i)].pass, "cascade " + std::to_string(i));
        const auto side = std::uint64_t(s.cascades.mapSize);
        EXPECT_EQ(samples[std::size_t(i)].work.texelsCleared, side * side);
    }
    EXPECT_EQ(samples.back().kind, PassKind::Main);
    EXPECT_GT(samples.back().work.fragments, 0u);
    for (const CalibrationSample& sample : samples) {
        std::vector<double> times;
        for (const FrameStats& f : t.frames) {
            if (sample.kind == PassKind::Main) times.push_back(f.gpuMainMs);
            else if (sample.kind == PassKind::Cascade) times.push_back(f.cascades[std::stoul(sample.pass.substr(8))].gpuMs);
        }
        if (times.empty()) continue;
        EXPECT_EQ(sample.minMs, *std::min_element(times.begin(), times.end())) << sample.pass;
        EXPECT_EQ(sample.medianMs, median(times)) << sample.pass;
        EXPECT_LE(sample.minMs, sample.medianMs);
    }
    const std::vector<double> totals = frameTotalsMs(t);
    ASSERT_EQ(totals.size(), 3u);
    EXPECT_NEAR(totals[0], t.frames[0].gpuShadowMs + t.frames[0].gpuMainMs + t.frames[0].gpuFilterMs, 1e-9);
}

}  // namespace
}  // namespace st::metrics
