// Flip rate and temporal deviation over synthetic frames.
#include "metrics/flicker.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::metrics {
namespace {

TEST(FlickerTest, StillFramesDoNotFlicker) {
    const MeasureSamples s = test::floorSamples(4, 4);
    FlickerMeter meter(s);
    for (int f = 0; f < 5; ++f) meter.add(s.shadow);
    const FlickerReport r = meter.report();
    EXPECT_EQ(r.frames, 5);
    EXPECT_EQ(r.samplePoints, 16u);
    EXPECT_EQ(r.flipRate, 0.0);
    EXPECT_EQ(r.meanHardStdDev, 0.0);
}

TEST(FlickerTest, OnePointTogglingEveryFrame) {
    MeasureSamples a = test::floorSamples(2, 2);
    MeasureSamples b = a;
    test::setMap(b, 1, 1, 0.0f, 0.25f);
    FlickerMeter meter(a);
    for (const MeasureSamples* f : {&a, &b, &a, &b}) meter.add(f->shadow);
    const FlickerReport r = meter.report();
    EXPECT_DOUBLE_EQ(r.flipRate, 0.25);  // 1 of 4 points in each of the 3 pairs
    EXPECT_DOUBLE_EQ(r.maxFlipShare, 0.25);
    EXPECT_DOUBLE_EQ(r.flickeringShare, 0.25);
    EXPECT_DOUBLE_EQ(r.maxHardStdDev, 0.5);
    EXPECT_DOUBLE_EQ(r.meanHardStdDev, 0.125);
    EXPECT_DOUBLE_EQ(r.meanFilteredStdDev, 0.375 / 4.0);
    EXPECT_FLOAT_EQ(meter.hardStdDev()[3], 0.5f);
}

TEST(FlickerTest, OnlyReceiversOfTheFirstFrameAreSamplePoints) {
    MeasureSamples a = test::floorSamples(2, 1);
    a.normal[0].w = -1.0f;  // faces away: its result never shows
    MeasureSamples b = a;
    test::setMap(b, 0, 0, 0.0f, 0.0f);
    FlickerMeter meter(a);
    meter.add(a.shadow);
    meter.add(b.shadow);
    EXPECT_EQ(meter.report().samplePoints, 1u);
    EXPECT_EQ(meter.report().flipRate, 0.0);
}

TEST(FlickerTest, FramesOfAnotherSizeAreRejected) {
    FlickerMeter meter(test::floorSamples(2, 2));
    EXPECT_THROW(meter.add(test::floorSamples(3, 2).shadow), std::invalid_argument);
}

}  // namespace
}  // namespace st::metrics
