// The artifact classes of the filtered result (soft_accuracy.h) on shadow factor images made by
// hand over a flat floor: one screen pixel per texel, texels 1 m, k = 2 texels.
#include "metrics/soft_accuracy.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <limits>

namespace st::metrics {
namespace {

constexpr int kSize = 40;
const std::vector<float> kTexel{1.0f};  // cascade 0's texel, metres

std::size_t at(int x, int y) { return std::size_t(y) * kSize + std::size_t(x); }

// Lit everywhere, no caster on any ray.
SoftTruth litTruth() {
    return {std::vector<float>(kSize * kSize, 1.0f),
            std::vector<float>(kSize * kSize, std::numeric_limits<float>::infinity())};
}

// An umbra over [x0, x1) x [y0, y1), its caster `blocker` metres up the ray; the map agrees.
void addShadow(SoftTruth& t, MeasureSamples& s, int x0, int x1, int y0, int y1, float blocker) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            t.visible[at(x, y)] = 0.0f;
            t.blocker[at(x, y)] = blocker;
            test::setMap(s, x, y, 0.0f, 0.0f);
        }
}

void light(MeasureSamples& s, int x0, int x1, int y0, int y1, float f) {
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) test::setMap(s, x, y, f, f);
}

TEST(SoftAccuracyTest, AgreementIsCorrectEverywhere) {
    MeasureSamples s = test::floorSamples(kSize, kSize);
    SoftTruth t = litTruth();
    addShadow(t, s, 10, 30, 10, 30, 5.0f);
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.all.receivers, std::size_t(kSize * kSize));
    EXPECT_EQ(r.all.artifacts() + r.all.edge, 0u);
    EXPECT_EQ(r.all.filteredError(), 0.0);
    EXPECT_EQ(r.classes[at(20, 20)], ArtifactClass::Correct);
}

// Light in the middle of a 20 x 20 umbra whose caster is 5 m up: the 4 x 4 block more than two
// texels from the umbra's edge is bleeding; the same light next to the edge is an edge error.
TEST(SoftAccuracyTest, LightInsideAnUmbraIsBleeding) {
    MeasureSamples s = test::floorSamples(kSize, kSize);
    SoftTruth t = litTruth();
    addShadow(t, s, 10, 30, 10, 30, 5.0f);
    light(s, 18, 22, 18, 22, 0.8f);  // well inside
    light(s, 10, 11, 12, 14, 1.0f);  // on the umbra's first column
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.all.lightBleeding, 16u);
    EXPECT_EQ(r.all.edge, 2u);
    EXPECT_EQ(r.all.peterPanning + r.all.missingCaster + r.all.acne, 0u);
    EXPECT_EQ(r.classes[at(19, 19)], ArtifactClass::LightBleeding);
    EXPECT_NEAR(r.all.filteredError(), (16 * 0.8 + 2.0) / double(kSize * kSize), 1e-9);
    EXPECT_EQ(r.cascades.at(0).lightBleeding, 16u);
    // A larger k takes the bleeding for an edge error: the block is 8 texels from the edge.
    EXPECT_EQ(scoreSoftAccuracy(s, t, kTexel, {.k = 9.0f}).all.lightBleeding, 0u);
}

// A box standing on the floor: its shadow's caster is under k texels (2 m) up the ray in the
// columns next to its foot. Light there is peter-panning; the same light where the caster is
// 5 m up is bleeding.
TEST(SoftAccuracyTest, LightNextToAContactIsPeterPanning) {
    MeasureSamples s = test::floorSamples(kSize, kSize);
    SoftTruth t = litTruth();
    addShadow(t, s, 10, 30, 10, 30, 5.0f);
    for (int y = 10; y < 30; ++y)
        for (int x = 10; x < 13; ++x) t.blocker[at(x, y)] = 0.5f * float(x - 9);  // 0.5, 1, 1.5 m: the foot
    light(s, 10, 13, 10, 30, 1.0f);  // the bias lifted the shadow off the foot
    light(s, 20, 24, 20, 24, 1.0f);  // and a hole well inside, far from the foot
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.all.peterPanning, 60u);
    EXPECT_EQ(r.all.lightBleeding, 16u);
    EXPECT_EQ(r.classes[at(11, 20)], ArtifactClass::PeterPanning);
    // At half a texel of k the 1 m and 1.5 m columns are no longer at the contact.
    EXPECT_EQ(scoreSoftAccuracy(s, t, kTexel, {.k = 0.5f}).all.peterPanning, 20u);
}

// A shadow the map lost whole: a missing caster, not bleeding.
TEST(SoftAccuracyTest, AWholeShadowAbsentIsAMissingCaster) {
    MeasureSamples s = test::floorSamples(kSize, kSize);
    SoftTruth t = litTruth();
    addShadow(t, s, 2, 8, 2, 8, 5.0f);
    addShadow(t, s, 20, 36, 20, 36, 5.0f);
    light(s, 20, 36, 20, 36, 1.0f);
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.all.missingCaster, 256u);
    EXPECT_EQ(r.all.lightBleeding + r.all.edge, 0u);
    EXPECT_EQ(r.classes[at(5, 5)], ArtifactClass::Correct);
}

// Dark speckle on lit ground far from any shadow is acne; next to a shadow it is an edge error
// (a wide kernel darkens there by design); a grey under the tolerance is no error at all.
TEST(SoftAccuracyTest, ShadowWhereTheTruthIsLitIsAcne) {
    MeasureSamples s = test::floorSamples(kSize, kSize);
    SoftTruth t = litTruth();
    addShadow(t, s, 30, 40, 0, 40, 5.0f);
    for (int y = 0; y < kSize; y += 2)
        for (int x = 0; x < 20; x += 2) test::setMap(s, x, y, 1.0f, 0.6f);  // 3x3 PCF acne: 0.6 of the taps lit
    light(s, 28, 30, 0, 40, 0.5f);   // beside the shadow
    light(s, 22, 24, 0, 40, 0.85f);  // within the tolerance
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.all.acne, 200u);
    EXPECT_EQ(r.all.edge, 80u);
    EXPECT_EQ(r.all.lightBleeding + r.all.peterPanning + r.all.missingCaster, 0u);
    EXPECT_EQ(r.classes[at(0, 0)], ArtifactClass::Acne);
    EXPECT_EQ(r.classes[at(22, 0)], ArtifactClass::Correct);
}

// A linear ramp 8 px wide between umbra and light is an 8 px penumbra (7 pixels strictly
// between, plus one pixel's worth of ramp ends at 0 and 1); the filtered factor's, 4 px wide,
// is 4 px too narrow.
TEST(SoftAccuracyTest, PenumbraWidthIsPixelsOverContour) {
    MeasureSamples s = test::floorSamples(kSize, 10);
    SoftTruth t{std::vector<float>(kSize * 10, 1.0f), std::vector<float>(kSize * 10, 5.0f)};
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < kSize; ++x) {
            t.visible[at(x, y)] = std::clamp(float(x - 16) / 8.0f, 0.0f, 1.0f);
            const float f = std::clamp(float(x - 18) / 4.0f, 0.0f, 1.0f);
            test::setMap(s, x, y, f, f);
        }
    const SoftAccuracyReport r = scoreSoftAccuracy(s, t, kTexel);
    EXPECT_EQ(r.penumbra.truthContour, 10u);
    EXPECT_DOUBLE_EQ(r.penumbra.truthPx, 7.0);
    EXPECT_DOUBLE_EQ(r.penumbra.filteredPx, 3.0);
    EXPECT_DOUBLE_EQ(r.penumbra.errorPx(), -4.0);
}

TEST(SoftAccuracyTest, DistanceMapIsNearEuclidean) {
    std::vector<std::uint8_t> src(kSize * kSize, 0);
    src[at(0, 0)] = 1;
    const std::vector<float> d = distanceToNearest(kSize, kSize, src);
    EXPECT_EQ(d[at(0, 0)], 0.0f);
    EXPECT_FLOAT_EQ(d[at(10, 0)], 10.0f);
    EXPECT_NEAR(d[at(30, 30)], 42.43f, 0.08f * 42.43f);
    EXPECT_GT(distanceToNearest(4, 4, std::vector<std::uint8_t>(16, 0))[5], 1e6f);
}

}  // namespace
}  // namespace st::metrics
