// The flicker controls of docs/architecture.md#flicker: the cascade camera slides sideways by less
// than a texel per frame while the observer stands still. Without stabilisation the light boxes
// slide with it and shadow edges crawl (F > 0); a bounding sphere snapped to whole texels moves
// only by whole texels, so every fixed point keeps its result (F = 0).
#include "metrics/camera_path.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <cstddef>
#include <vector>

namespace st {
namespace {

class FlickerGLTest : public test::GLTest {
protected:
    // The preset's camera and a copy 3.7 cm to its right (perpendicular to the view, so view
    // depths and cascade selection stay put), over 8 frames: 5 mm steps.
    static Settings withSidewaysPath(Settings s) {
        const glm::vec3 right(0.037f, 0.0f, 0.0f);  // default.json looks down -Z
        s.path.frames = 8;
        s.path.keyframes = {{s.camera.position, s.camera.target, s.camera.fovY},
                            {s.camera.position + right, s.camera.target + right, s.camera.fovY}};
        return s;
    }
    metrics::FlickerReport flicker(const Settings& s) {
        auto& e = session_.entryFor(s, ST_PRESET_DIR);
        return metrics::measureFlicker(*e.renderer, session_.pass(), s);
    }
    metrics::MeasureSession session_;
};

TEST_F(FlickerGLTest, UnstableCascadesFlickerUnderSubTexelTranslation) {
    Settings s = withSidewaysPath(test::presetAtTestSize("default"));
    s.cascades.fit = FitMode::Cascade;
    s.cascades.stabilize = false;
    const metrics::FlickerReport r = flicker(s);
    EXPECT_EQ(r.frames, 8);
    EXPECT_GT(r.samplePoints, 30000u);
    EXPECT_GT(r.flipRate, 0.0);
    EXPECT_GT(r.meanHardStdDev, 0.0);
}

TEST_F(FlickerGLTest, SnappedSpheresDoNotFlickerUnderTranslation) {
    Settings s = withSidewaysPath(test::presetAtTestSize("default"));
    ASSERT_EQ(s.cascades.fit, FitMode::Sphere);
    ASSERT_TRUE(s.cascades.stabilize);
    const metrics::FlickerReport r = flicker(s);
    EXPECT_EQ(r.frames, 8);
    EXPECT_EQ(r.flipRate, 0.0);
    EXPECT_EQ(r.maxHardStdDev, 0.0);
}

TEST_F(FlickerGLTest, SphereWithoutSnappingStillFlickers) {
    Settings s = withSidewaysPath(test::presetAtTestSize("default"));
    s.cascades.stabilize = false;  // the sphere keeps the size, but the grid slides
    EXPECT_GT(flicker(s).flipRate, 0.0);
}

// The flip share of each frame pair, counted here from the frames themselves.
std::vector<double> flipSharesOf(const std::vector<MeasureSamples>& frames) {
    std::vector<double> shares;
    for (std::size_t k = 1; k < frames.size(); ++k) {
        std::size_t points = 0, flips = 0;
        for (std::size_t i = 0; i < frames[0].size(); ++i) {
            if (!frames[0].receiver(i)) continue;
            ++points;
            flips += frames[k].shadow[i].x != frames[k - 1].shadow[i].x;
        }
        shares.push_back(double(flips) / double(points));
    }
    return shares;
}

TEST_F(FlickerGLTest, PerFrameFlipSharesAreTheFramePairsAndAverageToF) {
    Settings s = withSidewaysPath(test::presetAtTestSize("default"));
    s.cascades.stabilize = false;
    const metrics::FlickerReport r = flicker(s);
    auto& e = session_.entryFor(s, ST_PRESET_DIR);
    std::vector<MeasureSamples> frames;
    for (int k = 0; k < s.path.frames; ++k)
        frames.push_back(metrics::sampleFrame(*e.renderer, session_.pass(), metrics::atPathFrame(s, k), s));
    const std::vector<double> expected = flipSharesOf(frames);
    ASSERT_EQ(r.flipShareByFrame.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) EXPECT_DOUBLE_EQ(r.flipShareByFrame[k], expected[k]) << k;
    double sum = 0.0;
    for (double v : expected) sum += v;
    EXPECT_GT(r.flipRate, 0.0);
    EXPECT_NEAR(sum / double(expected.size()), r.flipRate, 1e-12);
}

TEST_F(FlickerGLTest, FrameZeroOnTheObserverIsMisclassifiedAsTheStillFrame) {
    Settings s = withSidewaysPath(test::presetAtTestSize("default"));  // keyframe 0 is s.camera
    s.cascades.stabilize = false;
    ASSERT_EQ(metrics::cameraOnPath(s, 0).position, s.camera.position);
    ASSERT_EQ(metrics::cameraOnPath(s, 0).target, s.camera.target);
    metrics::MeasureOptions opt;
    opt.cost = false;
    const metrics::PresetMeasurement m = session_.measure(s, ST_PRESET_DIR, opt);
    ASSERT_TRUE(m.flicker);
    ASSERT_EQ(m.flicker->misclassifiedByFrame.size(), std::size_t(s.path.frames));
    const metrics::ErrorCounts& a = m.accuracy.all;
    EXPECT_EQ(m.flicker->samplePoints, a.receivers);
    EXPECT_GT(a.misclassified(), 0u);
    EXPECT_DOUBLE_EQ(m.flicker->misclassifiedByFrame[0], a.share(a.misclassified()));
}

TEST_F(FlickerGLTest, TheCascadeCameraMovesAndTheObserverDoesNot) {
    const Settings s = withSidewaysPath(test::presetAtTestSize("default"));
    EXPECT_NE(metrics::cameraOnPath(s, 7).position, s.camera.position);
    auto& e = session_.entryFor(s, ST_PRESET_DIR);
    const MeasureSamples first = metrics::sampleFrame(*e.renderer, session_.pass(), metrics::atPathFrame(s, 0), s);
    const MeasureSamples last = metrics::sampleFrame(*e.renderer, session_.pass(), metrics::atPathFrame(s, 7), s);
    EXPECT_EQ(first.position, last.position);  // the same world point behind every pixel
    EXPECT_EQ(e.renderer->plan().camera.wsPosition, metrics::cameraOnPath(s, 7).position);
}

}  // namespace
}  // namespace st
