// Sample distribution shadow maps on the GPU: the depth reduction against scenes whose seen
// depths are known, the samples fit, and the far-edge fade.
#include "renderer/csm/depth_bounds.h"
#include "renderer/render/renderer.h"
#include "renderer/scene/scene.h"
#include "tests/render/render_test_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace st;

namespace {
class DepthBoundsGLTest : public test::GLTest {};

// Two quads facing the camera (which looks down -Z from the origin) at view depths 12 and 45,
// each over part of the screen, sky elsewhere: the seen range is exactly [12, 45].
Scene twoQuads() {
    Scene s;
    s.materials.push_back({});
    addBox(s, {-3.0f, -1.0f, -12.0f}, {-1.0f, 1.0f, -12.0f}, 0);  // zero thickness: one depth
    addBox(s, {1.0f, -2.0f, -45.0f}, {6.0f, 2.0f, -45.0f}, 0);
    finalizeBounds(s);
    return s;
}

Settings quadSettings() {
    Settings s;
    s.camera.position = {0, 0, 0};
    s.camera.target = {0, 0, -1};
    s.camera.nearPlane = 0.5f;
    s.camera.farPlane = 1000.0f;
    s.cascades.count = 2;
    s.cascades.mapSize = 512;
    s.cascades.depthBounds = DepthBounds::Fit;
    s.light.elevation = 60.0f;
    s.output = {160, 90, View::Shadow};
    return s;
}
}  // namespace

TEST_F(DepthBoundsGLTest, ReducedRangeIsTheTrueNearestAndFarthestDepth) {
    const Scene scene = twoQuads();
    Renderer r(scene);
    const FrameStats stats = r.render(quadSettings());
    ASSERT_TRUE(stats.depthBounds.reduced);
    ASSERT_TRUE(stats.depthBounds.seen);
    EXPECT_NEAR(stats.depthBounds.vsMin, 12.0f, 12.0f * 1e-4f);
    EXPECT_NEAR(stats.depthBounds.vsMax, 45.0f, 45.0f * 1e-4f);
    // The splits divide the fitted range, not [0.5, 1000].
    EXPECT_NEAR(stats.splits.front(), 12.0f, 0.01f);
    EXPECT_NEAR(stats.splits.back(), 45.0f, 0.01f);
    EXPECT_GT(stats.splits[1], 12.0f);
    EXPECT_LT(stats.splits[1], 45.0f);
    EXPECT_EQ(stats.splitBegin, stats.splits.front());
    EXPECT_EQ(stats.depthBounds.source, "depth prepass, same frame");
}

TEST_F(DepthBoundsGLTest, OffRunsNoReductionAndSkyOnlyKeepsTheFullRange) {
    const Scene scene = twoQuads();
    Renderer r(scene);
    Settings s = quadSettings();
    s.cascades.depthBounds = DepthBounds::Off;
    FrameStats stats = r.render(s);
    EXPECT_FALSE(stats.depthBounds.reduced);
    EXPECT_EQ(stats.splits.back(), 1000.0f);
    s.cascades.depthBounds = DepthBounds::Fit;
    s.camera.target = {0, 0, 1};  // looking away: nothing but sky
    stats = r.render(s);
    EXPECT_TRUE(stats.depthBounds.reduced);
    EXPECT_FALSE(stats.depthBounds.seen);
    EXPECT_EQ(stats.splits.front(), 0.5f);
    EXPECT_EQ(stats.splits.back(), 1000.0f);
}

TEST_F(DepthBoundsGLTest, SamplesFitBoxesHoldTheQuadEachCascadeSees) {
    const Scene scene = twoQuads();
    Renderer r(scene);
    Settings s = quadSettings();
    s.cascades.fit = FitMode::Samples;
    s.cascades.zExtension = ZExtension::None;
    const FrameStats stats = r.render(s);
    // Cascade 0 holds the near quad (depth 12), cascade 1 the far one (45): each box is the
    // quad's light-space bounds (pixel centres fall inside it) plus the pad, far smaller than
    // the slice's own box.
    for (int i = 0; i < 2; ++i) {
        const csm::CascadeFit& fit = r.plan().cascades[std::size_t(i)];
        ASSERT_TRUE(stats.cascades[std::size_t(i)].samplesFitted) << i;
        const csm::Aabb quad = csm::transformAabb(fit.lsView, scene.draws[std::size_t(i)].wsBounds);
        const glm::vec3 e = quad.extent();
        // Samples are pixel centres: inside the quad by up to one pixel's diagonal at its depth
        // (the light view only rotates, so no longer in ls).
        const float depth = i == 0 ? 12.0f : 45.0f;
        const float pixel = 2.0f * depth * std::tan(glm::radians(30.0f)) / float(s.output.height) * std::sqrt(2.0f);
        for (int k = 0; k < 2; ++k) {
            EXPECT_LE(fit.lsBox.min[k], quad.min[k] + pixel) << i << " axis " << k;
            EXPECT_GE(fit.lsBox.max[k], quad.max[k] - pixel) << i << " axis " << k;
            EXPECT_GE(fit.lsBox.min[k], quad.min[k] - 0.05f * e[k]) << i << " axis " << k;
            EXPECT_LE(fit.lsBox.max[k], quad.max[k] + 0.05f * e[k]) << i << " axis " << k;
        }
    }
}

namespace {
// A long roof at 5 m over x 2..8 with the sun overhead: its shadow is a strip along -Z on the
// ground, seen from beside it.
Scene roofScene() {
    Scene s;
    s.materials.push_back({});
    addBox(s, {-100.0f, -0.1f, -150.0f}, {100.0f, 0.0f, 20.0f}, 0);
    addBox(s, {2.0f, 5.0f, -150.0f}, {8.0f, 5.2f, 10.0f}, 0);
    finalizeBounds(s);
    return s;
}

Settings roofSettings(float fadeBand) {
    Settings s;
    s.camera.position = {-2, 2, 5};
    s.camera.target = {-2, 1.5f, -40};
    s.camera.farPlane = 200.0f;
    s.light.elevation = 90.0f;
    s.cascades.count = 1;
    s.cascades.shadowDistance = 40.0f;
    s.cascades.mapSize = 1024;
    s.cascades.fadeBand = fadeBand;
    s.filter.kind = FilterKind::Hard;
    s.output = {320, 180, View::Shadow};
    return s;
}
}  // namespace

TEST_F(DepthBoundsGLTest, FadeBandGoesToLitAtTheFarEnd) {
    const Scene scene = roofScene();
    Renderer r(scene);
    const float band = 0.5f;
    const Rgba8Image faded = test::renderImage(r, roofSettings(band));
    const Rgba8Image hard = test::renderImage(r, roofSettings(0.0f));
    const float n = r.plan().splits.front(), f = r.plan().splits.back();
    int checked = 0;
    for (float z = -5.0f; z > -45.0f; z -= 2.5f) {
        const glm::vec3 p(5.0f, 0.0f, z);  // under the roof's middle: in its shadow
        const float depth = -(r.plan().vsView * glm::vec4(p, 1.0f)).z;
        const auto px = test::projectToPixel(r, p);
        if (!px || depth > f - 0.5f) continue;
        // The shadow view writes the factor through encodeSrgb, pow(factor, 1/2.2): compared
        // linear. At this grazing view one pixel row spans about 1 m of depth near 20 m, 0.05 of
        // the 20 m band, hence the tolerance.
        const float w = std::clamp((depth - (f - band * (f - n))) / (band * (f - n)), 0.0f, 1.0f);
        const float factor = std::pow(float(test::pixelAt(faded, *px).r) / 255.0f, 2.2f);
        EXPECT_NEAR(factor, w, 0.08f) << "depth " << depth;
        EXPECT_LT(test::pixelAt(hard, *px).r, 10) << "depth " << depth;  // no fade: shadowed to the end
        ++checked;
    }
    EXPECT_GE(checked, 10);
    // Near the far end the fade has (almost) reached lit.
    const auto end = test::projectToPixel(r, {5.0f, 0.0f, -(f - 6.0f)});
    ASSERT_TRUE(end);
    EXPECT_GT(test::pixelAt(faded, *end).r, 200);
}
