// Cost figures: medians over the timed frames, per-cascade counts and texels.
#include "metrics/cost.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::metrics {
namespace {

FrameStats frame(double shadowMs, double cascade1Ms) {
    FrameStats f;
    f.gpuShadowMs = shadowMs;
    f.gpuMainMs = 2.0;
    f.cpuMs = 0.5;
    f.shadowMapBytes = 2 * 256 * 256 * 4;
    f.cascades = {CascadeStats{.casterDraws = 3, .casterTriangles = 36, .gpuMs = 1.0},
                  CascadeStats{.casterDraws = 1, .casterTriangles = 2, .gpuMs = cascade1Ms}};
    return f;
}

TEST(CostTest, MediansAndCounts) {
    const CostReport c = summariseCost({frame(9.0, 4.0), frame(1.0, 8.0), frame(3.0, 6.0)}, {1000, 65536}, 256);
    EXPECT_EQ(c.frames, 3);
    EXPECT_EQ(c.gpuShadowMs, 3.0);
    EXPECT_EQ(c.cascades[1].gpuMs, 6.0);
    EXPECT_EQ(c.draws, 4);
    EXPECT_EQ(c.triangles, 38u);
    EXPECT_EQ(c.texels, 2u * 65536u);
    EXPECT_EQ(c.texelsCovered, 66536u);
    EXPECT_EQ(c.cascades[0].texelsCovered, 1000u);
    EXPECT_EQ(c.shadowMapBytes, 524288u);
}

TEST(CostTest, MinimumAndMaximumBesideTheMedian) {
    const CostReport c = summariseCost({frame(9.0, 4.0), frame(1.0, 8.0), frame(3.0, 6.0)}, {1000, 65536}, 256);
    EXPECT_EQ(c.gpuShadowRange, (TimeRange{1.0, 9.0}));
    EXPECT_EQ(c.gpuMainRange, (TimeRange{2.0, 2.0}));
}

TEST(CostTest, CarriesTheWorkOfTheTimedFramesWhichMustAgree) {
    std::vector<FrameStats> frames{frame(9.0, 4.0), frame(1.0, 8.0)};
    for (FrameStats& f : frames) f.work.main.fragments = 230400;
    EXPECT_EQ(summariseCost(frames, {}, 256).work.main.fragments, 230400u);
    frames[1].work.main.fragments = 230399;  // a counter that moved between runs of the same settings
    EXPECT_THROW(summariseCost(frames, {}, 256), std::logic_error);
}

TEST(CostTest, MedianOfNothingIsZeroAndNoFramesIsAnError) {
    EXPECT_EQ(median({}), 0.0);
    EXPECT_EQ(median({4.0, 1.0}), 4.0);  // upper median
    EXPECT_THROW(summariseCost({}, {}, 256), std::invalid_argument);
}

}  // namespace
}  // namespace st::metrics
