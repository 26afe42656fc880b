// The golden tolerance table: an override applies to its preset only, must give a reason, and the
// shipped table's default is the documented 5/255 and 0.1 %.
#include "tests/support/golden_tolerance.h"
#include "tests/support/image_compare.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::test {
namespace {

const nlohmann::json kTable = nlohmann::json::parse(R"({
  "default": {"maxChannelDiff": 5, "maxFailingFraction": 0.001, "reason": "llvmpipe rounding"},
  "presets": {"noisy": {"maxChannelDiff": 40, "maxFailingFraction": 0.3, "reason": "dithered on purpose"}}
})");

// A 10x10 grey image and the same with 20 pixels 30/255 brighter: 20 % of the pixels differ by
// more than 5 but less than 40.
std::pair<Rgba8Image, Rgba8Image> imagesTwentyPercentApart() {
    Rgba8Image a{10, 10, std::vector<std::uint8_t>(400, 100)};
    Rgba8Image b = a;
    for (std::size_t i = 0; i < 20; ++i) b.pixels[i * 4] = 130;
    return {a, b};
}

TEST(GoldenToleranceTest, OverrideIsAppliedToItsPresetOnly) {
    const auto [a, b] = imagesTwentyPercentApart();
    const GoldenTolerance noisy = toleranceFor(kTable, "noisy");
    const GoldenTolerance other = toleranceFor(kTable, "default-preset");
    EXPECT_TRUE(noisy.overridden);
    EXPECT_EQ(noisy.reason, "dithered on purpose");
    EXPECT_FALSE(other.overridden);
    EXPECT_EQ(other.reason, "llvmpipe rounding");
    EXPECT_TRUE(compareImages(a, b, noisy.tolerance).pass);
    EXPECT_FALSE(compareImages(a, b, other.tolerance).pass);
    EXPECT_NE(noisy.describe().find("dithered on purpose"), std::string::npos) << noisy.describe();
    EXPECT_NE(noisy.describe().find("40/255"), std::string::npos) << noisy.describe();
}

TEST(GoldenToleranceTest, MalformedEntriesAreRejected) {
    nlohmann::json t = kTable;
    t["presets"]["noisy"].erase("reason");
    EXPECT_THROW(toleranceFor(t, "noisy"), std::runtime_error);
    EXPECT_THROW(toleranceFor(t, "other"), std::runtime_error);  // a bad entry fails every preset
    t = kTable;
    t["presets"]["noisy"]["maxChannelDiff"] = 300;
    EXPECT_THROW(toleranceFor(t, "noisy"), std::runtime_error);
    t = kTable;
    t["presets"]["noisy"]["maxFailingFraction"] = 2.0;
    EXPECT_THROW(toleranceFor(t, "noisy"), std::runtime_error);
    t = kTable;
    t["presets"]["noisy"]["tolerance"] = 1;
    EXPECT_THROW(toleranceFor(t, "noisy"), std::runtime_error);
}

TEST(GoldenToleranceTest, ShippedTableDefaultIsTheDocumentedOne) {
    const nlohmann::json table = readToleranceTable(ST_GOLDEN_TOLERANCES);
    const GoldenTolerance d = toleranceFor(table, "a preset with no entry");
    EXPECT_EQ(d.tolerance.maxChannelDiff, Tolerance{}.maxChannelDiff);
    EXPECT_EQ(d.tolerance.maxFailingFraction, Tolerance{}.maxFailingFraction);
    EXPECT_FALSE(d.reason.empty());
}

}  // namespace
}  // namespace st::test
