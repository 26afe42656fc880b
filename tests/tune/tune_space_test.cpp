// The tuner's per-cascade moves (docs/tuning.md#the-space): a split depth turns a computed scheme
// manual with its other splits where they were, a map size leaves the other cascades' sizes, and
// count, storage and global size moves keep the lists valid. No GL.
#include "tune/tune_space.h"

#include "renderer/csm/splits.h"
#include "renderer/settings/validation.h"

#include <gtest/gtest.h>

#include <cmath>

namespace st::tune {
namespace {

Settings threeCascades() {
    Settings s;
    s.cascades.count = 3;
    s.cascades.scheme = SplitScheme::Practical;
    s.cascades.lambda = 0.8f;
    s.camera.nearPlane = 0.5f;
    s.camera.farPlane = 500.0f;
    return s;
}

// The practical scheme's interior splits, from seed 000's formula by hand (N = 3, n = 0.5, f = 500).
float practicalSplit(int i, float lambda) {
    const float n = 0.5f, f = 500.0f, t = float(i) / 3.0f;
    return lambda * n * std::pow(f / n, t) + (1.0f - lambda) * (n + t * (f - n));
}

TEST(TuneSpaceTest, ASplitMoveTurnsTheSchemeManualAndKeepsTheOtherSplit) {
    const Settings s = threeCascades();
    const Space space = defaultSpace(s);
    const Dimension* d = space.find("cascades.manualSplits[0]");
    ASSERT_NE(d, nullptr);
    EXPECT_TRUE(applies(s, d->path));
    EXPECT_TRUE(applies(s, "cascades.manualSplits[1]"));
    EXPECT_FALSE(applies(s, "cascades.manualSplits[2]")) << "three cascades have two splits";
    EXPECT_NEAR(currentValue(s, *d).get<double>(), practicalSplit(1, 0.8f), 1e-3);

    const std::size_t up = currentIndex(s, *d) + 1;
    const Settings moved = withValue(s, *d, up);
    EXPECT_EQ(moved.cascades.scheme, SplitScheme::Manual);
    ASSERT_EQ(moved.cascades.manualSplits.size(), 2u);
    EXPECT_FLOAT_EQ(moved.cascades.manualSplits[0], d->values[up].get<float>());
    EXPECT_NEAR(moved.cascades.manualSplits[1], practicalSplit(2, 0.8f), 1e-3);
    EXPECT_TRUE(validate(moved).empty()) << validate(moved).front();

    // A weight move goes back to computed splits.
    const Settings back = withFieldJson(moved, "cascades.lambda", 0.5);
    EXPECT_EQ(back.cascades.scheme, SplitScheme::Practical);
    EXPECT_TRUE(back.cascades.manualSplits.empty());
}

TEST(TuneSpaceTest, ASplitPastTheNextIsRefusedByValidation) {
    const Settings s = threeCascades();
    const Settings crossed = withFieldJson(s, "cascades.manualSplits[0]", 400.0);
    EXPECT_FALSE(validate(crossed).empty()) << "the first split beyond the second is not a preset";
}

TEST(TuneSpaceTest, AMapSizeMoveSizesOneCascadeWhereTheStorageHasSizesPerCascade) {
    Settings s = threeCascades();
    s.cascades.mapSize = 1024;
    EXPECT_FALSE(applies(s, "cascades.mapSizes[0]")) << "the array storage has one size";
    s.cascades.storage = CascadeStorage::Textures;
    EXPECT_TRUE(applies(s, "cascades.mapSizes[2]"));
    EXPECT_FALSE(applies(s, "cascades.mapSizes[3]"));
    const Space space = defaultSpace(s);
    const Dimension* d = space.find("cascades.mapSizes[0]");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(currentValue(s, *d).get<int>(), 1024);

    Settings big = withFieldJson(s, "cascades.mapSizes[0]", 2048);
    EXPECT_EQ(big.cascades.mapSizes, (std::vector<int>{2048, 1024, 1024}));
    EXPECT_TRUE(validate(big).empty()) << validate(big).front();

    // The global size keeps the ratios; a count move pads with the last size; the array storage drops them.
    EXPECT_EQ(withFieldJson(big, "cascades.mapSize", 512).cascades.mapSizes, (std::vector<int>{1024, 512, 512}));
    const Settings four = withFieldJson(big, "cascades.count", 4);
    EXPECT_EQ(four.cascades.mapSizes, (std::vector<int>{2048, 1024, 1024, 1024}));
    EXPECT_TRUE(validate(four).empty()) << validate(four).front();
    EXPECT_EQ(withFieldJson(big, "cascades.count", 2).cascades.mapSizes, (std::vector<int>{2048, 1024}));
    const Settings array = withFieldJson(big, "cascades.storage", "array");
    EXPECT_TRUE(array.cascades.mapSizes.empty());
    EXPECT_TRUE(validate(array).empty()) << validate(array).front();
}

}  // namespace
}  // namespace st::tune
