// Issue 13 item 5: the hover probe reads the frame on screen at one pixel. The measurement pass
// of a real frame of the yard is probed and every figure is checked against its own
// computation from the cascade plan: the cascade by interval selection of the pixel's view
// depth, the cascade's texel size, the slope bias from the normal and the sun. The truth comes
// from the Accuracy panel's per-pixel classes.
#include "app/editor/scene_probe.h"
#include "renderer/csm/cascade_plan.h"
#include "renderer/scene/scene.h"
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

#include <glm/glm.hpp>

#include <cmath>

namespace st::app {
namespace {

class SceneProbeGLTest : public test::GLTest {
protected:
    Settings settings = test::presetAtTestSize("default");
    Scene scene = loadScene(settings.scene, ST_PRESET_DIR);
    Renderer renderer{scene};

    std::vector<float> texelSizes() const {
        std::vector<float> t;
        for (const csm::CascadeFit& c : renderer.plan().cascades) t.push_back(c.texelWorldSize);
        return t;
    }
};

TEST_F(SceneProbeGLTest, ProbedFiguresMatchTheCascadePlanAtEveryCascade) {
    // Cascade c's constant bias and normal offset at 1 + c and 1 + c / 2 times the global ones.
    settings.bias.normalOffset = 0.5f;
    for (int c = 0; c < settings.cascades.count; ++c) {
        settings.bias.constantScale.push_back(1.0f + float(c));
        settings.bias.normalOffsetScale.push_back(1.0f + 0.5f * float(c));
    }
    renderer.render(settings);
    SceneProbe probe;
    probe.update(true, renderer, settings);
    ASSERT_NE(probe.samples(), nullptr);
    const MeasureSamples& m = *probe.samples();
    ASSERT_EQ(m.width, 320);
    const csm::CascadePlan& plan = renderer.plan();
    const glm::vec3 eye = settings.camera.position;
    const glm::vec3 forward = glm::normalize(settings.camera.target - settings.camera.position);
    std::vector<bool> seen(plan.cascades.size(), false);
    int probed = 0;
    for (int y = 0; y < m.height; y += 7)
        for (int x = 0; x < m.width; x += 11) {
            const ui::ProbeView p = readProbe(m, x, y, settings, texelSizes(), nullptr);
            const std::size_t i = std::size_t(y) * std::size_t(m.width) + std::size_t(x);
            if (!m.covered(i)) {
                EXPECT_FALSE(p.valid);
                continue;
            }
            ASSERT_TRUE(p.valid);
            const glm::vec3 ws(m.position[i]);
            const float vsDepth = glm::dot(ws - eye, forward);
            int expected = -1;
            for (std::size_t c = 0; c < plan.cascades.size() && expected < 0; ++c)
                if (vsDepth <= plan.splits[c + 1]) expected = int(c);
            // A pixel on a split line may fall either side: its depth here is the pixel centre's
            // position re-projected, the shader's an interpolated varying (0.5 % covers a pixel).
            bool nearSplit = false;
            for (const float split : plan.splits) nearSplit = nearSplit || std::abs(vsDepth - split) < 5e-3f * split;
            if (nearSplit) continue;
            ASSERT_EQ(p.cascade, expected) << x << "," << y << " at depth " << vsDepth;
            if (expected < 0) continue;
            seen[std::size_t(expected)] = true;
            ++probed;
            EXPECT_FLOAT_EQ(p.texelWorldSize, plan.cascades[std::size_t(expected)].texelWorldSize);
            const float nDotL = glm::dot(glm::vec3(m.normal[i]), -plan.wsLightDir);
            EXPECT_NEAR(p.nDotL, nDotL, 1e-3f);
            if (nDotL > 0.05f) {
                const float tanTheta = std::tan(std::acos(std::min(nDotL, 1.0f)));
                EXPECT_NEAR(p.slopeBias, settings.bias.slope * p.texelWorldSize * std::min(tanTheta, 10.0f),
                            1e-3f * p.texelWorldSize + 1e-6f);
            }
            EXPECT_FLOAT_EQ(p.constantBias, settings.bias.constant * (1.0f + float(expected)));
            EXPECT_FLOAT_EQ(p.normalOffset, settings.bias.normalOffset * (1.0f + 0.5f * float(expected)) * p.texelWorldSize);
            EXPECT_EQ(p.truth, -1) << "no truth before the Accuracy panel computed it";
        }
    EXPECT_GT(probed, 200);
    for (std::size_t c = 0; c < seen.size(); ++c) EXPECT_TRUE(seen[c]) << "no pixel of cascade " << c << " probed";
}

TEST_F(SceneProbeGLTest, TruthFollowsTheAccuracyClasses) {
    renderer.render(settings);
    SceneProbe probe;
    probe.update(true, renderer, settings);
    const MeasureSamples& m = *probe.samples();
    std::size_t i = 0;
    while (i < m.size() && !m.receiver(i)) ++i;
    ASSERT_LT(i, m.size());
    const int x = int(i % std::size_t(m.width)), y = int(i / std::size_t(m.width));
    std::vector<metrics::PixelClass> classes(m.size(), metrics::PixelClass::CorrectLit);
    EXPECT_EQ(readProbe(m, x, y, settings, texelSizes(), &classes).truth, 1);
    classes[i] = metrics::PixelClass::FalseLightGross;  // map said lit, rays say shadowed
    EXPECT_EQ(readProbe(m, x, y, settings, texelSizes(), &classes).truth, 0);
    classes[i] = metrics::PixelClass::FalseShadowEdge;
    EXPECT_EQ(readProbe(m, x, y, settings, texelSizes(), &classes).truth, 1);
    classes.pop_back();  // classes of another frame size: ignored
    EXPECT_EQ(readProbe(m, x, y, settings, texelSizes(), &classes).truth, -1);
    EXPECT_FALSE(readProbe(m, m.width, 0, settings, texelSizes(), nullptr).valid);
}

TEST_F(SceneProbeGLTest, SamplesAreReadOnlyWhenTheFrameChanged) {
    renderer.render(settings);
    SceneProbe probe;
    probe.update(false, renderer, settings);
    EXPECT_EQ(probe.samples(), nullptr) << "not wanted: no read-back";
    probe.update(true, renderer, settings);
    const MeasureSamples* first = probe.samples();
    ASSERT_NE(first, nullptr);
    const std::vector<glm::vec4> shadow = first->shadow;
    Settings moved = settings;
    moved.light.azimuth += 40.0f;
    renderer.render(moved);
    probe.update(true, renderer, moved);
    EXPECT_NE(probe.samples()->shadow, shadow) << "the new frame was read back";
}

}  // namespace
}  // namespace st::app

namespace st::app {
namespace {
// The probe speaks metres whatever the units: a constant bias in depth units is that share of the
// cascade's light-box depth, a normal offset in metres is not scaled by the texel, and one on the
// casters says so.
TEST_F(SceneProbeGLTest, BiasInDepthUnitsAndAnOffsetInMetresReadAsMetres) {
    settings.bias.constant = 7.5e-5f;
    settings.bias.constantUnit = BiasUnit::Depth;
    settings.bias.normalOffset = 0.02f;
    settings.bias.normalOffsetUnit = OffsetUnit::Metres;
    settings.bias.normalOffsetSide = NormalOffsetSide::CasterSin;
    renderer.render(settings);
    SceneProbe probe;
    probe.update(true, renderer, settings);
    ASSERT_NE(probe.samples(), nullptr);
    const MeasureSamples& m = *probe.samples();
    std::vector<float> depthRange;
    for (const csm::CascadeFit& c : renderer.plan().cascades) depthRange.push_back(c.lsBox.max.z - c.lsBox.min.z);
    int probed = 0;
    for (int y = 0; y < m.height; y += 9)
        for (int x = 0; x < m.width; x += 9) {
            const ui::ProbeView p = readProbe(m, x, y, settings, texelSizes(), nullptr, depthRange);
            if (!p.valid || p.cascade < 0) continue;
            ++probed;
            EXPECT_FLOAT_EQ(p.constantBias, 7.5e-5f * depthRange[std::size_t(p.cascade)]);
            EXPECT_FLOAT_EQ(p.normalOffset, 0.02f);
            EXPECT_TRUE(p.offsetOnCasters);
        }
    EXPECT_GT(probed, 100);
}
}  // namespace
}  // namespace st::app
