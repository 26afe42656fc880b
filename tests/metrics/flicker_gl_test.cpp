// The flicker controls of docs/architecture.md#flicker: the cascade camera slides sideways by less
// than a texel per frame while the observer stands still. Without stabilisation the light boxes
// slide with it and shadow edges crawl (F > 0); a bounding sphere snapped to whole texels moves
// only by whole texels, so every fixed point keeps its result (F = 0).
#include "metrics/camera_path.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

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
