// Wasted-map and z-extension warnings from given figures.
#include "metrics/map_warnings.h"

#include <gtest/gtest.h>

#include <glm/mat4x4.hpp>

namespace st::metrics {
namespace {

FrameStats frame(float splitEnd, std::vector<float> texels) {
    FrameStats f;
    f.splitBegin = 0.3f;
    f.splitEnd = splitEnd;
    for (float t : texels) {
        CascadeStats c;
        c.texelWorldSize = t;
        f.cascades.push_back(c);
    }
    return f;
}

DensityReport density(std::vector<std::pair<std::size_t, double>> pixelsAndMedian) {
    DensityReport d;
    for (auto [pixels, median] : pixelsAndMedian) {
        DensityStats s;
        s.pixels = pixels;
        s.median = median;
        d.cascades.push_back(s);
    }
    return d;
}

TEST(MapWarningsTest, CoarseCascadeWithSplitsPastTheSceneSuggestsDepthBounds) {
    const Settings s;  // depthBounds off, practical 0.5
    const auto w = wastedMapWarnings(s, frame(1500.0f, {0.11f, 0.5f}), density({{5000, 22.4}, {100, 1.0}}), 310.0f);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "cascade 0: median 22 screen pixels per shadow texel (limit 4); likely fix: cascades.depthBounds "
                    "\"fit\" or cascades.shadowDistance 310 m (the splits run to 1500 m, the farthest surface seen "
                    "is at 310 m)");
}

TEST(MapWarningsTest, FineCascadesAndEmptyOnesWarnNothing) {
    const Settings s;
    EXPECT_TRUE(wastedMapWarnings(s, frame(100.0f, {0.02f, 0.3f}), density({{5000, 1.5}, {800, 3.9}}), 90.0f).empty());
    // A cascade no pixel selects wastes nothing the user sees, whatever its figures.
    EXPECT_TRUE(wastedMapWarnings(s, frame(100.0f, {5.0f}), density({{0, 50.0}}), 90.0f).empty());
}

TEST(MapWarningsTest, LargeTexelWarnsAgainstTheStatedSize) {
    Settings s;
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.lambda = 0.95f;
    MapWarningLimits limits;
    limits.maxTexelMetres = 0.5f;
    const auto w = wastedMapWarnings(s, frame(100.0f, {0.1f, 2.0f}), density({{10, 1.0}, {10, 1.0}}), 90.0f, limits);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "cascade 1: texel 2 m is larger than 0.5 m; likely fix: a shorter cascades.shadowDistance (the last "
                    "cascade ends at 100 m) or a larger cascades.mapSize (2048; it is 1024)");
    // Not the last cascade: more of them, or more texels.
    const auto w3 = wastedMapWarnings(s, frame(100.0f, {2.0f, 0.1f}), density({{10, 1.0}, {10, 1.0}}), 90.0f, limits);
    ASSERT_EQ(w3.size(), 1u);
    EXPECT_EQ(w3[0], "cascade 0: texel 2 m is larger than 0.5 m; likely fix: more cascades (cascades.count 5; it is 4) "
                     "or a larger cascades.mapSize (2048; it is 1024)");
}

TEST(MapWarningsTest, FittedRangeWithLowLambdaSuggestsAHigherLambda) {
    Settings s;
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.lambda = 0.5f;
    const auto w = wastedMapWarnings(s, frame(300.0f, {0.2f}), density({{100, 9.0}}), 290.0f);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("likely fix: a higher lambda (cascades.lambda 0.5"), std::string::npos) << w[0];
}

TEST(MapWarningsTest, FarthestSampleDepthIsTheLargestViewDepthOfCoveredPixels) {
    MeasureSamples m;
    m.width = 3;
    m.height = 1;
    m.position = {{0, 0, -5, 1}, {1, 2, -42, 1}, {0, 0, -900, 0}};  // the last is not covered
    EXPECT_FLOAT_EQ(*farthestSampleDepth(m, glm::mat4(1.0f)), 42.0f);
    m.position = {{0, 0, -5, 0}, {0, 0, -6, 0}, {0, 0, -7, 0}};
    EXPECT_FALSE(farthestSampleDepth(m, glm::mat4(1.0f)));
}

TEST(MapWarningsTest, CutCastersAreReportedPerCascade) {
    FrameStats f = frame(100.0f, {0.1f, 0.2f, 0.4f});
    f.cascades[2].zExtensionUsed = 100.0f;
    f.cascades[2].zExtensionMinimal = 152.0f;
    f.cascades[2].zExtensionCuts = true;
    const auto w = zExtensionWarnings(f);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "cascade 2: z-extension 100 m cuts casters up to 152 m toward the sun; minimal extension 152 m");
}

}  // namespace
}  // namespace st::metrics
