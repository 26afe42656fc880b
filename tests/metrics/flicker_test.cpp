// Flip rate and temporal deviation over synthetic frames.
#include "metrics/flicker.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

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

TEST(FlickerTest, PerFrameFlipSharesAverageToTheFlipRate) {
    MeasureSamples a = test::floorSamples(2, 2);
    MeasureSamples b = a, c = a;
    test::setMap(b, 1, 1, 0.0f, 0.25f);
    test::setMap(c, 0, 0, 0.0f, 0.25f);
    test::setMap(c, 1, 0, 0.0f, 0.25f);
    FlickerMeter meter(a);
    for (const MeasureSamples* f : {&a, &b, &b, &c}) meter.add(f->shadow);
    const FlickerReport r = meter.report();
    ASSERT_EQ(r.flipShareByFrame.size(), 3u);  // frame 0 has no predecessor
    EXPECT_DOUBLE_EQ(r.flipShareByFrame[0], 0.25);
    EXPECT_DOUBLE_EQ(r.flipShareByFrame[1], 0.0);
    EXPECT_DOUBLE_EQ(r.flipShareByFrame[2], 0.75);  // (1,1) back to lit, (0,0) and (1,0) to shadow
    EXPECT_DOUBLE_EQ(r.flipRate, (0.25 + 0.0 + 0.75) / 3.0);
    EXPECT_TRUE(r.misclassifiedByFrame.empty());  // no truth given
}

TEST(FlickerTest, MisclassifiedByFrameCountsReceiversAgainstTheStillTruth) {
    MeasureSamples a = test::floorSamples(2, 2);
    a.normal[3].w = -1.0f;  // faces away: not a sample point, whatever the truth says
    MeasureSamples b = a;
    test::setMap(b, 0, 0, 0.0f, 0.0f);
    std::vector<std::uint8_t> truth(4, 1);
    truth[1] = 0;  // the map says lit there in both frames
    truth[3] = 0;
    FlickerMeter meter(a, truth);
    meter.add(a.shadow);
    meter.add(b.shadow);
    const FlickerReport r = meter.report();
    ASSERT_EQ(r.misclassifiedByFrame.size(), 2u);
    EXPECT_DOUBLE_EQ(r.misclassifiedByFrame[0], 1.0 / 3.0);
    EXPECT_DOUBLE_EQ(r.misclassifiedByFrame[1], 2.0 / 3.0);
    EXPECT_THROW(FlickerMeter(a, std::vector<std::uint8_t>(3, 1)), std::invalid_argument);
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

// The saccade tool's unit on a built sequence of four frames, one pixel per case: each row of
// `filtered` is a pixel's factor per frame (N.L 1 unless set), the count is known by hand.
TEST(FlickerTest, AlternatingPixelsCountUpDownStepsOfAtLeastTwoHundredthsOverThreeFrames) {
    const std::vector<std::vector<float>> filtered = {
        {0.0f, 1.0f, 0.0f, 1.0f},      // (0,0) alternates by 1: counts
        {0.0f, 0.25f, 0.5f, 0.75f},    // (1,0) monotonic: no
        {0.5f, 0.51f, 0.5f, 0.51f},    // (2,0) alternates by 0.01, under the step: no
        {0.0f, 1.0f, 1.0f, 0.0f},      // (3,0) up, still, down: the steps are not consecutive: no
        {1.0f, 0.5f, 1.0f, 1.0f},      // (0,1) down then up over 3 frames, then still: counts
        {0.0f, 1.0f, 0.0f, 1.0f},      // (1,1) N.L 0.01 below: luminance moves by 0.01: no
        {0.0f, 1.0f, 0.0f, 1.0f},      // (2,1) faces away from the sun: not a sample point: no
        {0.5f, 0.53f, 0.5f, 0.53f},    // (3,1) alternates by 0.03: counts
    };
    MeasureSamples first = test::floorSamples(4, 2);
    first.normal[5].w = 0.01f;
    first.normal[6].w = -1.0f;
    FlickerMeter meter(first);
    for (std::size_t f = 0; f < 4; ++f) {
        MeasureSamples frame = first;
        for (std::size_t i = 0; i < filtered.size(); ++i) test::setMap(frame, int(i % 4), int(i / 4), 1.0f, filtered[i][f]);
        meter.add(frame.shadow);
    }
    const FlickerReport r = meter.report();
    EXPECT_EQ(r.alternatingPixels, 3u);
    EXPECT_EQ(r.flipRate, 0.0) << "the hard result never changed";

    // The light's intensity scales the luminance: at 0.01 the unit swing of (0,0) is a 0.01 step.
    FlickerMeter dim(first, {}, 0.01f);
    for (std::size_t f = 0; f < 4; ++f) {
        MeasureSamples frame = first;
        for (std::size_t i = 0; i < filtered.size(); ++i) test::setMap(frame, int(i % 4), int(i / 4), 1.0f, filtered[i][f]);
        dim.add(frame.shadow);
    }
    EXPECT_EQ(dim.report().alternatingPixels, 0u);
}

TEST(FlickerTest, TwoFramesCannotAlternate) {
    MeasureSamples a = test::floorSamples(1, 1);
    MeasureSamples b = a;
    test::setMap(b, 0, 0, 0.0f, 0.0f);
    FlickerMeter meter(a);
    meter.add(a.shadow);
    meter.add(b.shadow);
    EXPECT_EQ(meter.report().alternatingPixels, 0u);
    meter.add(a.shadow);  // the third frame goes back up: one alternation
    EXPECT_EQ(meter.report().alternatingPixels, 1u);
}

TEST(FlickerTest, FramesOfAnotherSizeAreRejected) {
    FlickerMeter meter(test::floorSamples(2, 2));
    EXPECT_THROW(meter.add(test::floorSamples(3, 2).shadow), std::invalid_argument);
}

}  // namespace
}  // namespace st::metrics
