// Misclassification and filtered error on synthetic samples: what counts, where, and in which class.
#include "metrics/accuracy.h"
#include "tests/metrics/samples_builder.h"

#include <gtest/gtest.h>

#include <set>

namespace st::metrics {
namespace {

std::vector<std::uint8_t> allLit(const MeasureSamples& s) { return std::vector<std::uint8_t>(s.size(), 1); }

ResolutionExplains explainedAt(std::set<std::size_t> pixels) {
    return [pixels](std::size_t i, bool) { return pixels.contains(i); };
}

TEST(AccuracyTest, AgreementIsNoError) {
    const MeasureSamples s = test::floorSamples(8, 4);
    const AccuracyReport r = scoreAccuracy(s, allLit(s), 1, explainedAt({}));
    EXPECT_EQ(r.all.receivers, 32u);
    EXPECT_EQ(r.all.misclassified(), 0u);
    EXPECT_EQ(r.all.filteredError(), 0.0);
    EXPECT_EQ(r.classes[5], PixelClass::CorrectLit);
}

TEST(AccuracyTest, FalseShadowAndFalseLightAreSeparate) {
    MeasureSamples s = test::floorSamples(8, 4);
    std::vector<std::uint8_t> truth = allLit(s);
    test::setMap(s, 1, 0, 0.0f, 0.0f);  // acne: map dark, truth lit
    test::setMap(s, 2, 0, 0.0f, 0.5f);
    truth[8] = 0;                       // (0,1): truth dark, map lit: a leak
    const AccuracyReport r = scoreAccuracy(s, truth, 1, explainedAt({}));
    EXPECT_EQ(r.all.falseShadow(), 2u);
    EXPECT_EQ(r.all.falseLight(), 1u);
    EXPECT_DOUBLE_EQ(r.all.share(r.all.misclassified()), 3.0 / 32.0);
    EXPECT_DOUBLE_EQ(r.all.filteredError(), (1.0 + 0.5 + 1.0) / 32.0);
    EXPECT_EQ(r.classes[1], PixelClass::FalseShadowGross);
    EXPECT_EQ(r.classes[8], PixelClass::FalseLightGross);
}

TEST(AccuracyTest, ResolutionDecidesEdgeOrGross) {
    MeasureSamples s = test::floorSamples(8, 4);
    test::setMap(s, 1, 0, 0.0f, 0.0f);
    test::setMap(s, 2, 0, 0.0f, 0.0f);
    const AccuracyReport r = scoreAccuracy(s, allLit(s), 1, explainedAt({1}));
    EXPECT_EQ(r.all.falseShadowEdge, 1u);
    EXPECT_EQ(r.all.falseShadowGross, 1u);
    EXPECT_EQ(r.all.gross(), 1u);
    EXPECT_EQ(r.classes[1], PixelClass::FalseShadowEdge);
}

TEST(AccuracyTest, FacingAwayTerminatorAndEmptyPixelsAreNotScored) {
    MeasureSamples s = test::floorSamples(4, 2);
    s.position[0].w = 0.0f;  // no surface
    s.normal[1].w = -0.2f;   // faces away: truth and image are dark whatever the map says
    s.geometry[1].w = -0.2f;
    s.geometry[2].w = -0.1f;  // smooth normal to the sun, triangle away from it
    std::vector<std::uint8_t> truth = allLit(s);
    truth[1] = truth[2] = 0;
    const AccuracyReport r = scoreAccuracy(s, truth, 1, explainedAt({}));
    EXPECT_EQ(r.covered, 7u);
    EXPECT_EQ(r.facingAway, 1u);
    EXPECT_EQ(r.terminator, 1u);
    EXPECT_EQ(r.all.receivers, 5u);
    EXPECT_EQ(r.all.misclassified(), 0u);
    EXPECT_EQ(r.classes[0], PixelClass::NoSurface);
    EXPECT_EQ(r.classes[1], PixelClass::FacingAway);
    EXPECT_EQ(r.classes[2], PixelClass::Terminator);
}

TEST(AccuracyTest, PerCascadeAndBeyondTheShadowRange) {
    MeasureSamples s = test::floorSamples(4, 1);
    s.shadow[1].z = 1.0f;   // cascade 1
    s.shadow[2].z = -1.0f;  // beyond: the renderer draws it lit
    s.shadow[3].z = -1.0f;
    std::vector<std::uint8_t> truth = allLit(s);
    truth[1] = 0;
    truth[3] = 0;
    const AccuracyReport r = scoreAccuracy(s, truth, 2, explainedAt({1, 3}));
    ASSERT_EQ(r.cascades.size(), 2u);
    EXPECT_EQ(r.cascades[0].receivers, 1u);
    EXPECT_EQ(r.cascades[1].falseLightEdge, 1u);
    EXPECT_EQ(r.beyond.receivers, 2u);
    EXPECT_EQ(r.beyond.falseLightGross, 1u);  // never an edge: no resolution brings it back
}

TEST(AccuracyTest, TruthEdgesLieOnBothSidesOfABoundary) {
    const MeasureSamples s = test::floorSamples(4, 1);
    const std::vector<std::uint8_t> truth = {1, 1, 0, 0};
    EXPECT_EQ(truthEdges(s, truth), (std::vector<std::uint8_t>{0, 1, 1, 0}));
}

}  // namespace
}  // namespace st::metrics
