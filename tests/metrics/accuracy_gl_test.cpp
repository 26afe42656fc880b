// The accuracy and texel-density figures on real frames of the yard (presets/default.json):
// they must move the way the settings say they should, and gross errors must mean real ones.
#include "tests/metrics/metrics_gl_util.h"
#include "tests/support/gl_fixture.h"

namespace st {
namespace {

class AccuracyGLTest : public test::GLTest {
protected:
    metrics::PresetMeasurement measure(const Settings& s) { return test::measureStill(session_, s); }
    metrics::MeasureSession session_;
};

double misclassified(const metrics::PresetMeasurement& m) { return m.accuracy.all.share(m.accuracy.all.misclassified()); }

TEST_F(AccuracyGLTest, MisclassificationFallsAsTheMapGrows) {
    Settings s = test::presetAtTestSize("default");
    double previous = 1.0;
    for (int size : {512, 1024, 2048}) {
        s.cascades.mapSize = size;
        const double share = misclassified(measure(s));
        EXPECT_LT(share, previous) << "map size " << size;
        EXPECT_GT(share, 0.0) << "a finite map always errs at some shadow edge";
        previous = share;
    }
}

TEST_F(AccuracyGLTest, FourCascadesBeatOneAtEqualMapSize) {
    Settings s = test::presetAtTestSize("default");
    const double four = misclassified(measure(s));
    s.cascades.count = 1;
    const double one = misclassified(measure(s));
    EXPECT_LT(four * 2.0, one);  // one cascade over 400 m spends its texels far too thinly
}

TEST_F(AccuracyGLTest, DefaultPresetHasNoGrossErrors) {
    Settings s = test::presetAtTestSize("default", 640, 360);  // its own size: more pixels to fail
    const metrics::PresetMeasurement m = measure(s);
    EXPECT_GT(m.accuracy.all.receivers, 100000u);
    EXPECT_GT(m.accuracy.edgePixels, 500u);  // there are shadows to get wrong
    EXPECT_EQ(m.accuracy.all.gross(), 0u);
    EXPECT_LT(m.accuracy.all.share(m.accuracy.all.misclassified()), 1e-3);
}

TEST_F(AccuracyGLTest, NoBiasIsGrossAcne) {
    Settings s = test::presetAtTestSize("default");
    s.bias.constant = 0.0f;
    s.bias.slope = 0.0f;
    const metrics::ErrorCounts e = measure(s).accuracy.all;
    EXPECT_GT(e.share(e.falseShadowGross), 0.1);  // self-shadowing speckle over lit ground
    EXPECT_GT(e.falseShadowGross, 10 * e.falseLight());
}

TEST_F(AccuracyGLTest, HugeBiasIsGrossPeterPanning) {
    Settings s = test::presetAtTestSize("default", 640, 360);
    s.bias.constant = 0.5f;  // half a metre: shadows detach from the boxes' feet
    const metrics::ErrorCounts e = measure(s).accuracy.all;
    EXPECT_GT(e.falseLightGross, 0u);
    EXPECT_EQ(e.falseShadowGross, 0u);
}

TEST_F(AccuracyGLTest, FilteredErrorIsSmallAndCountsTheSoftEdges) {
    Settings s = test::presetAtTestSize("default");
    const metrics::PresetMeasurement m = measure(s);
    EXPECT_GT(m.accuracy.all.filteredError(), 0.0);
    EXPECT_LT(m.accuracy.all.filteredError(), 0.01);
    ASSERT_EQ(m.accuracy.cascades.size(), 4u);
    std::size_t perCascade = 0;
    for (const auto& c : m.accuracy.cascades) perCascade += c.receivers;
    EXPECT_EQ(perCascade + m.accuracy.beyond.receivers, m.accuracy.all.receivers);
}

TEST_F(AccuracyGLTest, TexelDensityImprovesFromOneToFourCascades) {
    Settings s = test::presetAtTestSize("default");
    const metrics::DensityStats four = measure(s).density.all;
    s.cascades.count = 1;
    const metrics::DensityStats one = measure(s).density.all;
    EXPECT_LT(four.median, one.median);
    EXPECT_LT(four.p90, one.p90);
    EXPECT_LT(four.p95, one.p95);
    EXPECT_LT(four.aliasingShare, one.aliasingShare);
    EXPECT_GT(one.median, 10.0);  // one 1024 map over 400 m: a texel spans many pixels
}

}  // namespace
}  // namespace st
