// The soft truth of the sun's disc on CPU scenes (Embree, no GL): the penumbra of the floating
// box against its analytic width, the fixed seed, the disc pattern's strata, the adaptive trace
// against every ray, and the point sun.
#include "metrics/ground_truth.h"
#include "metrics/soft_accuracy.h"
#include "metrics/sun_disc.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include <cmath>
#include <set>

namespace st::metrics {
namespace {

const glm::vec3 kOverhead(0.0f, 1.0f, 0.0f);
const glm::vec3 kEye(0.0f, 5.0f, 10.0f);

// A top view of the ground across the box's +x side (box (-1,2,-1)..(1,4,1)): pixel (x, y) at
// ws (x0 + x * pitch, 0, y * pitch - 0.2), rows along the edge.
MeasureSamples edgeStrip(int width, int height, float x0, float pitch) {
    MeasureSamples s = test::floorSamples(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            s.position[std::size_t(y) * std::size_t(width) + std::size_t(x)] = {x0 + float(x) * pitch, 0.0f,
                                                                                float(y) * pitch - 0.2f, 1.0f};
    return s;
}

// Under an overhead sun of angular diameter a, the penumbra beside the box's side x = 1 runs
// from the umbra, where the bottom edge (2 m up) starts to let the disc's rim through, at
// x = 1 - 2 tan(a/2), to full light, where the top edge (4 m up) stops hiding it, at
// x = 1 + 4 tan(a/2): distance x tan(angular diameter) for each edge's half of the disc, 6 tan(a/2)
// in all. At a = 5 deg, 0.262 m; at 2 cm per pixel (a 64 x 16 strip), 13.1 px.
TEST(SoftTruthTest, BoxPenumbraHasTheAnalyticWidth) {
    const Scene scene = makeBuiltinScene("box-over-plane");
    const GroundTruth truth(scene);
    const float pitch = 0.02f, a = 5.0f;
    const MeasureSamples s = edgeStrip(64, 16, 0.5f, pitch);
    const SoftTruth t = truth.traceDisc(s, kOverhead, {.angularDiameter = a, .rays = 256}, kEye);
    const double analyticPx = 6.0 * std::tan(glm::radians(double(a) / 2.0)) / double(pitch);
    for (int y = 0; y < s.height; ++y) {
        int penumbra = 0;
        for (int x = 0; x < s.width; ++x) {
            const float v = t.visible[std::size_t(y) * 64 + std::size_t(x)];
            penumbra += v > 0.0f && v < 1.0f;
            EXPECT_GE(v, x > 0 ? t.visible[std::size_t(y) * 64 + std::size_t(x) - 1] - 0.1f : 0.0f)
                << "light should grow away from the box, row " << y << " col " << x;
        }
        EXPECT_NEAR(penumbra, analyticPx, 1.0) << "row " << y;
    }
    // The report's figure, pixels over contour length, is the same width.
    double width = 0.0;
    std::size_t pixels = 0, contour = 0;
    penumbraWidth(s, t.visible, {}, 0.0f, width, pixels, contour);
    EXPECT_EQ(contour, 16u);
    EXPECT_NEAR(width, analyticPx, 1.0);
    // Under the box's middle, umbra; 0.5 m out, full light.
    EXPECT_EQ(t.visible[0], 0.0f);
    EXPECT_EQ(t.visible[63], 1.0f);
    // A point sun has no penumbra: the hard edge under the box's side.
    const SoftTruth hard = truth.traceDisc(s, kOverhead, {.angularDiameter = 0.0f, .rays = 64}, kEye);
    for (int x = 0; x < 64; ++x)
        if (x != 25)  // x = 1 m exactly: the ray grazes the box's side
            EXPECT_EQ(hard.visible[std::size_t(x)], 0.5f + float(x) * pitch < 1.0f ? 0.0f : 1.0f) << x;
    EXPECT_EQ(truth.trace(s, kOverhead, kEye)[10], 0);
}

TEST(SoftTruthTest, BlockerDistanceIsTheCentreRaysFirstHit) {
    const Scene scene = makeBuiltinScene("box-over-plane");
    const GroundTruth truth(scene);
    const MeasureSamples s = edgeStrip(64, 1, 0.5f, 0.02f);
    const SoftTruth t = truth.traceDisc(s, kOverhead, {}, kEye);
    EXPECT_NEAR(t.blocker[0], 2.0f, 1e-3f);  // the box's bottom, 2 m up
    EXPECT_TRUE(std::isinf(t.blocker[63]));
}

TEST(SoftTruthTest, RaysRepeatWithTheFixedSeed) {
    const Scene scene = makeBuiltinScene("box-over-plane");
    const GroundTruth truth(scene);
    const MeasureSamples s = edgeStrip(64, 8, 0.5f, 0.02f);
    const SunDisc disc{.angularDiameter = 5.0f, .rays = 16};
    const SoftTruth a = truth.traceDisc(s, kOverhead, disc, kEye);
    EXPECT_EQ(a.visible, truth.traceDisc(s, kOverhead, disc, kEye, {}, {.threads = 1}).visible);
    SunDisc other = disc;
    other.seed = disc.seed + 1;
    EXPECT_NE(a.visible, truth.traceDisc(s, kOverhead, other, kEye).visible) << "another seed, other rays";
}

// The adaptive trace skips pixels whose block is unanimous: on the box's edge it must give what
// every ray gives.
TEST(SoftTruthTest, AdaptiveTraceEqualsEveryRay) {
    const Scene scene = makeBuiltinScene("box-over-plane");
    const GroundTruth truth(scene);
    const MeasureSamples s = edgeStrip(64, 8, 0.5f, 0.02f);
    SunDisc disc{.angularDiameter = 5.0f, .rays = 64};
    const SoftTruth adaptive = truth.traceDisc(s, kOverhead, disc, kEye);
    disc.exhaustive = true;
    EXPECT_EQ(adaptive.visible, truth.traceDisc(s, kOverhead, disc, kEye).visible);
}

// Every prefix of 2^m samples is a (0,m,2)-net: 16 samples put one point in each cell of the
// 4x4, 16x1 and 1x16 grids, whatever the pixel's scramble.
TEST(SoftTruthTest, DiscPatternIsStratified) {
    for (std::size_t pixel : {0u, 1u, 977u}) {
        const DiscScramble sc = discScramble(kSunDiscSeed, pixel);
        std::set<int> grid, columns, rows;
        for (std::uint32_t k = 0; k < 16; ++k) {
            const glm::vec2 p = squareSample(k, sc);
            ASSERT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f);
            grid.insert(int(p.x * 4.0f) * 4 + int(p.y * 4.0f));
            columns.insert(int(p.x * 16.0f));
            rows.insert(int(p.y * 16.0f));
            EXPECT_LE(glm::length(concentricDisc(p)), 1.0f + 1e-6f);
        }
        EXPECT_EQ(grid.size(), 16u);
        EXPECT_EQ(columns.size(), 16u);
        EXPECT_EQ(rows.size(), 16u);
    }
    // The concentric map keeps areas: the square's left half is the disc's left half.
    EXPECT_LT(concentricDisc({0.25f, 0.5f}).x, 0.0f);
    EXPECT_NEAR(glm::length(concentricDisc({1.0f, 0.5f})), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(concentricDisc({0.75f, 0.5f})), 0.5f, 1e-6f);
}

TEST(SoftTruthTest, DiscFrameSpansTheSunsAngularRadius) {
    const DiscFrame f = discFrame(glm::vec3(0.3f, 0.8f, 0.2f), 0.53f);
    const float rim = glm::degrees(std::acos(glm::dot(f.direction({1.0f, 0.0f}), f.toSun)));
    EXPECT_NEAR(rim, 0.265f, 1e-3f);
    EXPECT_NEAR(glm::dot(f.u, f.toSun), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::dot(f.v, f.u), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace st::metrics
