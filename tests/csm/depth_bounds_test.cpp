// SDSM math: the range the splits are placed in, splits inside it, and the samples fit.
#include "renderer/csm/cascade_plan.h"
#include "renderer/csm/depth_bounds.h"
#include "renderer/csm/frustum.h"
#include "renderer/csm/light_fit.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace st::csm {
namespace {

TEST(DepthBoundsTest, NothingSeenKeepsNearToEnd) {
    const SplitRange r = fittedSplitRange(0.1f, 1500.0f, std::nullopt);
    EXPECT_EQ(r.begin, 0.1f);
    EXPECT_EQ(r.end, 1500.0f);
}

TEST(DepthBoundsTest, SeenRangeIsKeptWithinItsPad) {
    const SplitRange r = fittedSplitRange(0.1f, 1500.0f, DepthRange{12.0f, 80.0f});
    EXPECT_NEAR(r.begin, 12.0f, 12.0f * 2e-4f);
    EXPECT_NEAR(r.end, 80.0f, 80.0f * 2e-4f);
    EXPECT_LE(r.begin, 12.0f);  // the pad widens, never cuts
    EXPECT_GE(r.end, 80.0f);
}

TEST(DepthBoundsTest, SeenRangeIsClampedIntoNearAndEnd) {
    const SplitRange r = fittedSplitRange(0.5f, 200.0f, DepthRange{0.3f, 900.0f});
    EXPECT_EQ(r.begin, 0.5f);
    EXPECT_EQ(r.end, 200.0f);
}

TEST(DepthBoundsTest, OneDepthSeenStillGivesARange) {
    const SplitRange r = fittedSplitRange(0.1f, 400.0f, DepthRange{50.0f, 50.0f});
    EXPECT_LT(r.begin, r.end);
    EXPECT_LE(r.begin, 50.0f);
    EXPECT_GE(r.end, 50.0f);
    EXPECT_LT(r.end - r.begin, 0.2f);
}

TEST(DepthBoundsTest, EverythingBeyondTheShadowDistanceKeepsTheFullRange) {
    const SplitRange r = fittedSplitRange(0.1f, 100.0f, DepthRange{150.0f, 300.0f});
    EXPECT_EQ(r.begin, 0.1f);
    EXPECT_EQ(r.end, 100.0f);
}

Settings fitSettings() {
    Settings s;
    s.camera.nearPlane = 0.3f;
    s.camera.farPlane = 1500.0f;
    s.cascades.count = 4;
    s.cascades.lambda = 0.75f;
    s.cascades.depthBounds = DepthBounds::Fit;
    return s;
}

TEST(DepthBoundsTest, PracticalSplitsAreTheSchemeOverTheFittedRange) {
    const Settings s = fitSettings();
    SplitRange range;
    const std::vector<float> z = planSplits(s, DepthRange{5.0f, 120.0f}, &range);
    ASSERT_EQ(z.size(), 5u);
    EXPECT_EQ(z.front(), range.begin);
    EXPECT_EQ(z.back(), range.end);
    // Seed 000, z_i = lambda n (f/n)^(i/N) + (1 - lambda)(n + (i/N)(f - n)), over the fitted n, f.
    const double n = range.begin, f = range.end, l = 0.75;
    for (int i = 1; i < 4; ++i) {
        const double t = i / 4.0;
        const double expected = l * n * std::pow(f / n, t) + (1.0 - l) * (n + t * (f - n));
        EXPECT_NEAR(z[std::size_t(i)], expected, 1e-4 * expected) << i;
        EXPECT_GT(z[std::size_t(i)], 5.0f * 0.999f);
        EXPECT_LT(z[std::size_t(i)], 120.0f);
    }
}

TEST(DepthBoundsTest, OffIgnoresTheSeenRangeAndManualSplitsStay) {
    Settings s = fitSettings();
    s.cascades.depthBounds = DepthBounds::Off;
    EXPECT_EQ(planSplits(s, DepthRange{5.0f, 120.0f}).back(), 1500.0f);
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.scheme = SplitScheme::Manual;
    s.cascades.manualSplits = {10.0f, 40.0f, 200.0f};
    const std::vector<float> z = planSplits(s, DepthRange{5.0f, 120.0f});
    EXPECT_EQ(z, (std::vector<float>{0.3f, 10.0f, 40.0f, 200.0f, 1500.0f}));
}

TEST(DepthBoundsTest, ShadowDistanceBoundsTheFittedRange) {
    Settings s = fitSettings();
    s.cascades.shadowDistance = 60.0f;
    EXPECT_EQ(planSplits(s, DepthRange{5.0f, 120.0f}).back(), 60.0f);
}

// Samples spread over part of the slice of cascade `index`; their ls bounds as the GPU reduces them.
struct SampleSet {
    std::vector<glm::vec3> ls;
    Aabb bounds;
};

SampleSet samplesIn(const CameraParams& cam, float n, float f, const glm::mat4& lsView, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::mat4 inv = inverseViewMatrix(cam);
    const float ty = std::tan(0.5f * cam.fovY), tx = ty * cam.aspect;
    SampleSet out;
    for (int k = 0; k < 500; ++k) {
        const float d = n + (f - n) * u(rng);
        // Lower-left quarter of the view only: the samples fit must be tighter than the slice's.
        const glm::vec3 vs(-tx * d * u(rng), -ty * d * u(rng), -d);
        const glm::vec3 ls(lsView * inv * glm::vec4(vs, 1.0f));
        out.ls.push_back(ls);
        if (k == 0) out.bounds = {ls, ls};
        out.bounds.min = glm::min(out.bounds.min, ls);
        out.bounds.max = glm::max(out.bounds.max, ls);
    }
    return out;
}

class SamplesFitTest : public ::testing::TestWithParam<bool> {};

TEST_P(SamplesFitTest, BoxHoldsEverySampleAndIsTighterThanTheSlice) {
    CameraParams cam;
    cam.wsPosition = {3, 12, 40};
    cam.wsTarget = {-5, 0, 0};
    cam.nearPlane = 0.5f;
    cam.farPlane = 300.0f;
    const std::vector<float> splits{0.5f, 20.0f, 80.0f, 300.0f};
    const glm::vec3 dir = lightDirection(35.0f, 40.0f);
    FitParams p;
    p.mapSize = 1024;
    p.stabilize = GetParam();
    p.zExtension = ZExtension::None;
    for (int i = 0; i < 3; ++i) {
        const CascadeFit slice = fitCascade(cam, splits, i, dir, p);
        const SampleSet samples = samplesIn(cam, splits[std::size_t(i)], splits[std::size_t(i) + 1], slice.lsView, 7u + unsigned(i));
        FitParams sp = p;
        sp.fit = FitMode::Samples;
        sp.lsSamples = samples.bounds;
        const CascadeFit fit = fitCascade(cam, splits, i, dir, sp);
        for (const glm::vec3& q : samples.ls) ASSERT_TRUE(fit.lsBox.contains(q)) << i;
        // At least the pad: 2 texels of margin on each side in x and y.
        EXPECT_LE(fit.lsBox.min.x, samples.bounds.min.x - 1.9f * fit.texelWorldSize);
        EXPECT_GE(fit.lsBox.max.x, samples.bounds.max.x + 1.9f * fit.texelWorldSize);
        EXPECT_LT(fit.lsBox.extent().x * fit.lsBox.extent().y, 0.6f * slice.lsBox.extent().x * slice.lsBox.extent().y) << i;
        EXPECT_LT(fit.texelWorldSize, slice.texelWorldSize);
        if (p.stabilize) {
            const float texel = fit.lsBox.extent().x / float(p.mapSize);
            EXPECT_NEAR(std::remainder(fit.lsBox.min.x, texel), 0.0f, 1e-3f * texel + 1e-5f * std::abs(fit.lsBox.min.x));
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Stabilize, SamplesFitTest, ::testing::Bool());

TEST(SamplesFitTest, NoSamplesFallsBackToTheSliceBox) {
    CameraParams cam;
    const std::vector<float> splits{0.1f, 400.0f};
    FitParams p;
    const CascadeFit a = fitCascade(cam, splits, 0, lightDirection(10, 50), p);
    p.fit = FitMode::Samples;
    const CascadeFit b = fitCascade(cam, splits, 0, lightDirection(10, 50), p);
    EXPECT_EQ(a.lsBox.min, b.lsBox.min);
    EXPECT_EQ(a.lsBox.max, b.lsBox.max);
}

// The reduction's bounds are in the rotation-only light frame of scene coordinates; fitted in a
// camera-relative frame 50 km out (or in world light space at the origin), the box still holds
// every sample, checked through the matrix the shaders use on the samples' scene positions.
TEST(SamplesFitTest, BoxHoldsEverySampleInACameraRelativeFrameFarOut) {
    CameraParams cam;
    cam.wsPosition = {3, 12, 40};
    cam.wsTarget = {-5, 0, 0};
    cam.nearPlane = 0.5f;
    cam.farPlane = 300.0f;
    const std::vector<float> splits{0.5f, 20.0f, 80.0f, 300.0f};
    const glm::vec3 dir = lightDirection(35.0f, 40.0f);
    const glm::mat4 rotation = lightViewMatrix(dir);
    for (const bool relative : {false, true}) {
        FitParams p;
        p.stabilize = true;
        p.zExtension = ZExtension::None;
        p.fit = FitMode::Samples;
        p.cameraRelative = relative;
        p.wsOrigin = relative ? glm::vec3(50000.0f, 0.0f, 0.0f) : glm::vec3(0.0f);
        for (int i = 0; i < 3; ++i) {
            const SampleSet samples = samplesIn(cam, splits[std::size_t(i)], splits[std::size_t(i) + 1], rotation, 3u + unsigned(i));
            p.lsSamples = samples.bounds;
            const CascadeFit fit = fitCascade(cam, splits, i, dir, p);
            for (const glm::vec3& q : samples.ls) {
                const glm::vec4 scene = glm::inverse(rotation) * glm::vec4(q, 1.0f);
                const glm::vec4 clip = fit.viewProj * scene;
                ASSERT_LE(std::max({std::abs(clip.x), std::abs(clip.y), std::abs(clip.z)}), 1.0f + 1e-4f)
                    << "cascade " << i << (relative ? ", camera-relative" : "");
            }
        }
    }
}

}  // namespace
}  // namespace st::csm
