// Texel density figures: nearest-rank quantiles and the aliasing / wasted shares.
#include "metrics/texel_density.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace st::metrics {
namespace {

TEST(TexelDensityTest, NearestRankQuantiles) {
    std::vector<float> values;
    for (int i = 1; i <= 100; ++i) values.push_back(float(i) / 10.0f);  // 0.1 .. 10, shuffled below
    std::swap(values[3], values[97]);
    const DensityStats d = densityStats(values);
    EXPECT_EQ(d.pixels, 100u);
    EXPECT_FLOAT_EQ(d.median, 5.0f);
    EXPECT_FLOAT_EQ(d.p90, 9.0f);
    EXPECT_FLOAT_EQ(d.p95, 9.5f);
    EXPECT_FLOAT_EQ(d.max, 10.0f);
    EXPECT_DOUBLE_EQ(d.aliasingShare, 0.9);  // 1.1 .. 10
    EXPECT_DOUBLE_EQ(d.wastedShare, 0.02);   // 0.1, 0.2
}

// The selection of the three ranks gives what a full sort gives, on shuffled values with ties.
TEST(TexelDensityTest, QuantilesMatchASortedCopy) {
    std::mt19937 rng(7);
    for (std::size_t n : {1u, 2u, 19u, 20u, 1000u, 4097u}) {
        std::vector<float> values(n);
        for (float& v : values) v = float(std::uniform_int_distribution<int>(0, 300)(rng)) / 16.0f;
        std::vector<float> sorted = values;
        std::sort(sorted.begin(), sorted.end());
        const auto rank = [&](double q) { return sorted[std::clamp<std::size_t>(std::size_t(std::ceil(q * double(n))), 1, n) - 1]; };
        const DensityStats d = densityStats(values);
        EXPECT_EQ(d.median, rank(0.5)) << n;
        EXPECT_EQ(d.p90, rank(0.9)) << n;
        EXPECT_EQ(d.p95, rank(0.95)) << n;
        EXPECT_EQ(d.max, sorted.back()) << n;
    }
}

TEST(TexelDensityTest, EmptyIsZero) { EXPECT_EQ(densityStats({}).pixels, 0u); }

TEST(TexelDensityTest, OnlySurfacePixelsInRangeCountPerCascade) {
    MeasureSamples s = test::floorSamples(4, 1);
    s.shadow[0].w = 2.0f;
    s.shadow[1] = {1.0f, 1.0f, 1.0f, 0.5f};  // cascade 1
    s.shadow[2].z = -1.0f;                    // beyond the range: no texel at all
    s.position[3].w = 0.0f;                   // no surface
    const DensityReport r = texelDensity(s, 2);
    EXPECT_EQ(r.all.pixels, 2u);
    EXPECT_FLOAT_EQ(r.all.max, 2.0f);
    ASSERT_EQ(r.cascades.size(), 2u);
    EXPECT_FLOAT_EQ(r.cascades[1].median, 0.5f);
    EXPECT_DOUBLE_EQ(r.cascades[0].aliasingShare, 1.0);
}

}  // namespace
}  // namespace st::metrics
