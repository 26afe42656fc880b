// The pure rules behind the settings widgets: clamping, legal ints, formats, derived figures.
#include "renderer/csm/limits.h"
#include "renderer/settings/field_table.h"
#include "ui/field_rules.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <vector>

using namespace st;
using namespace st::ui;

namespace {
const FieldInfo& field(std::string_view path) {
    const FieldInfo* f = findField(path);
    if (!f) throw std::runtime_error("no field " + std::string(path));
    return *f;
}
}  // namespace

TEST(FieldRulesTest, ClampKeepsValuesInTheTableRange) {
    EXPECT_EQ(clampToField(field("cascades.lambda"), 5.0), 1.0);
    EXPECT_EQ(clampToField(field("cascades.lambda"), -1.0), 0.0);
    EXPECT_EQ(clampToField(field("light.elevation"), 45.0), 45.0);
    EXPECT_EQ(clampToField(field("cascades.lambda"), std::nan("")), 0.0);
}

TEST(FieldRulesTest, OddIntsStepAwayFromThePreviousValueAndStayInRange) {
    const FieldInfo& size = field("filter.size");  // odd, 3..9
    EXPECT_EQ(legalInt(size, 4, 3), 5);
    EXPECT_EQ(legalInt(size, 4, 5), 3);
    EXPECT_EQ(legalInt(size, 10, 9), 9);
    EXPECT_EQ(legalInt(size, 1, 3), 3);
    EXPECT_EQ(legalInt(size, 7, 7), 7);
}

TEST(FieldRulesTest, PowerOfTwoIntsRoundToTheNearestAllowedSize) {
    const FieldInfo& mapSize = field("cascades.mapSize");  // 256..8192
    EXPECT_EQ(legalInt(mapSize, 1000, 1024), 1024);
    EXPECT_EQ(legalInt(mapSize, 1600, 1024), 2048);
    EXPECT_EQ(legalInt(mapSize, 100, 256), 256);
    EXPECT_EQ(legalInt(mapSize, 100000, 8192), 8192);
    EXPECT_EQ(powerOfTwoChoices(mapSize), (std::vector<int>{256, 512, 1024, 2048, 4096, 8192}));
}

TEST(FieldRulesTest, PlainIntsAreClamped) {
    EXPECT_EQ(legalInt(field("cascades.count"), 12, 4), 8);
    EXPECT_EQ(legalInt(field("cascades.count"), 0, 1), 1);
}

TEST(FieldRulesTest, ShortRangesGetSlidersLongRangesDragBoxes) {
    EXPECT_TRUE(prefersSlider(field("cascades.lambda")));
    EXPECT_TRUE(prefersSlider(field("light.elevation")));
    EXPECT_FALSE(prefersSlider(field("bias.constant")));   // 10 m in 1 mm steps
    EXPECT_FALSE(prefersSlider(field("camera.farPlane")));
}

TEST(FieldRulesTest, FormatsCarryTheStepPrecisionAndUnit) {
    EXPECT_EQ(decimalsForStep(0.01), 2);
    EXPECT_EQ(decimalsForStep(0.5), 1);
    EXPECT_EQ(decimalsForStep(0.001), 3);
    EXPECT_EQ(decimalsForStep(1.0), 0);
    EXPECT_EQ(floatFormat(field("light.elevation")), "%.0f deg");
    EXPECT_EQ(floatFormat(field("cascades.lambda")), "%.2f");
    EXPECT_EQ(floatFormat(field("bias.constant")), "%.3f m");
    EXPECT_EQ(intFormat(field("output.width")), "%d px");
}

TEST(FieldRulesTest, MapMemoryIsCountTimesSizeSquaredTimesFourBytes) {
    EXPECT_EQ(csm::shadowMapBytes(4, 1024), 4u * 1024u * 1024u * 4u);
    EXPECT_EQ(formatBytes(csm::shadowMapBytes(4, 1024)), "16.0 MiB");
    EXPECT_EQ(formatBytes(csm::shadowMapBytes(8, 8192)), "2.00 GiB");
    EXPECT_EQ(formatBytes(512 * 1024), "512 KiB");
    EXPECT_EQ(formatBytes(12), "12 B");
}

TEST(FieldRulesTest, LengthsPickAReadableUnit) {
    EXPECT_EQ(formatLength(0.0032), "3.2 mm");
    EXPECT_EQ(formatLength(0.045), "4.50 cm");
    EXPECT_EQ(formatLength(12.34), "12.3 m");
    EXPECT_EQ(formatLength(400.0), "400 m");
    EXPECT_EQ(formatLength(1200.0), "1.20 km");
}

TEST(FieldRulesTest, ManualSplitsFollowTheCascadeCount) {
    Settings s;
    s.cascades.count = 4;
    s.cascades.manualSplits = {10.0f, 20.0f, 30.0f, 40.0f, 50.0f};
    EXPECT_EQ(fitManualSplits(s, {}), (std::vector<float>{10.0f, 20.0f, 30.0f}));
    s.cascades.manualSplits = {10.0f};
    s.camera.farPlane = 100.0f;
    EXPECT_EQ(fitManualSplits(s, {}), (std::vector<float>{10.0f, 40.0f, 70.0f}));  // evenly to the far plane
    s.cascades.shadowDistance = 40.0f;
    EXPECT_EQ(fitManualSplits(s, {}), (std::vector<float>{10.0f, 20.0f, 30.0f}));  // ... or the shadow distance
}

TEST(FieldRulesTest, EmptyManualSplitsStartFromTheRenderersSplits) {
    Settings s;
    s.cascades.count = 3;
    const std::vector<float> rendered{0.1f, 8.0f, 60.0f, 400.0f};  // count + 1 depths
    EXPECT_EQ(fitManualSplits(s, rendered), (std::vector<float>{8.0f, 60.0f}));
    s.cascades.count = 1;
    EXPECT_TRUE(fitManualSplits(s, rendered).empty());
}

TEST(FieldRulesTest, AzimuthWrapsIntoTheFieldRange) {
    EXPECT_FLOAT_EQ(advanceAzimuth(350.0f, 20.0f), 10.0f);
    EXPECT_FLOAT_EQ(advanceAzimuth(5.0f, -10.0f), 355.0f);
    EXPECT_FLOAT_EQ(advanceAzimuth(-300.0f, 0.0f), 60.0f);
}

// Issue 13 #7: near 0.0001 showed as "0.00 m"; typed values were clamped without a word.
TEST(FieldRulesTest, SmallValuesKeepTwoSignificantDigitsOnScreen) {
    const FieldInfo& nearPlane = *findField("camera.nearPlane");
    EXPECT_EQ(floatFormatFor(nearPlane, 0.1), "%.2f m");
    EXPECT_EQ(floatFormatFor(nearPlane, 0.0001), "%.5f m");
    EXPECT_EQ(floatFormatFor(nearPlane, 250.0), "%.2f m");
    EXPECT_EQ(floatFormatFor(*findField("camera.farPlane"), 0.1), "%.2f m");
}

TEST(FieldRulesTest, TypedValuesOutsideTheRulesAreNamedWithTheRange) {
    EXPECT_EQ(typedValueProblem(*findField("filter.size"), -5), "-5 taps is outside 3 .. 9 taps");
    EXPECT_EQ(typedValueProblem(*findField("filter.size"), 4), "4 is even; it must be odd");
    EXPECT_EQ(typedValueProblem(*findField("cascades.lambda"), 5), "5 is outside 0 .. 1");
    EXPECT_EQ(typedValueProblem(*findField("camera.nearPlane"), -1), "-1 m is outside 0.0001 .. 10000 m");
    EXPECT_EQ(typedValueProblem(*findField("cascades.lambda"), 0.3), "");
}

TEST(FieldRulesTest, FieldsOfOtherModesSayWhyTheyDoNotApply) {
    Settings s;
    s.cascades.scheme = SplitScheme::Logarithmic;
    EXPECT_NE(notApplicableReason(*findField("cascades.lambda"), s).find("practical"), std::string::npos);
    s.cascades.scheme = SplitScheme::Practical;
    EXPECT_EQ(notApplicableReason(*findField("cascades.lambda"), s), "");
    s.filter.kind = FilterKind::PcfNxN;
    EXPECT_EQ(notApplicableReason(*findField("filter.size"), s), "");
    s.cascades.zExtension = ZExtension::Pancake;
    EXPECT_NE(notApplicableReason(*findField("cascades.zExtensionDistance"), s), "");
    EXPECT_EQ(notApplicableReason(*findField("light.elevation"), s), "");
}

// Every filter parameter applies exactly to the kinds whose shader reads it, storage fields to
// their storage, view fields to their view.
TEST(FieldRulesTest, FilterStorageAndViewFieldsApplyToTheirModesOnly) {
    auto applies = [](const char* path, const Settings& s) { return notApplicableReason(*findField(path), s).empty(); };
    Settings s;
    const std::vector<std::pair<const char*, std::vector<FilterKind>>> uses{
        {"filter.size", {FilterKind::PcfNxN, FilterKind::Pcss, FilterKind::Tent}},
        {"filter.weights", {FilterKind::PcfNxN, FilterKind::Pcss}},  // PCSS spreads the NxN weights
        {"filter.blurRadius", {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm}},
        {"filter.bleedExponent", {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm}},
        {"filter.minVariance", {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4}},
        {"filter.evsmPositive", {FilterKind::Evsm2, FilterKind::Evsm4}},
        {"filter.evsmNegative", {FilterKind::Evsm4}},
        {"filter.momentBias", {FilterKind::Msm}},
        {"filter.pcssMaxRadius", {FilterKind::Pcss}},
        {"filter.padding", {FilterKind::Hard, FilterKind::Pcf2x2, FilterKind::PcfNxN, FilterKind::Vsm, FilterKind::Evsm2,
                            FilterKind::Evsm4, FilterKind::Msm, FilterKind::Pcss, FilterKind::Vogel, FilterKind::Tent}}};
    for (const auto& [path, kinds] : uses)
        for (int k = 0; k < ST_FILTER_COUNT; ++k) {
            s.filter.kind = FilterKind(k);
            const bool used = std::find(kinds.begin(), kinds.end(), FilterKind(k)) != kinds.end();
            EXPECT_EQ(applies(path, s), used) << path << " with " << EnumNames<FilterKind>::names[std::size_t(k)];
        }
    s.filter.kind = FilterKind::Vsm;
    EXPECT_FALSE(applies("bias.receiverPlane", s));
    s.filter.kind = FilterKind::Pcf2x2;
    EXPECT_TRUE(applies("bias.receiverPlane", s));
    EXPECT_FALSE(applies("cascades.atlasPadding", s));
    EXPECT_FALSE(applies("cascades.mapSizes", s));
    s.cascades.storage = CascadeStorage::Atlas;
    EXPECT_TRUE(applies("cascades.atlasPadding", s));
    EXPECT_TRUE(applies("cascades.mapSizes", s));
    EXPECT_FALSE(applies("output.texelBlock", s));
    s.output.view = View::TexelGrid;
    EXPECT_TRUE(applies("output.texelBlock", s));
    EXPECT_FALSE(applies("output.sideTexels", s));
    s.output.view = View::Side;
    EXPECT_TRUE(applies("output.sideTexels", s));
    EXPECT_TRUE(applies("filter.screenSpace", s));
    EXPECT_FALSE(applies("filter.screenBlurRadius", s));
    s.filter.screenSpace = ScreenSpace::Blur;
    for (const char* p : {"filter.screenBlurRadius", "filter.screenDownsample", "filter.screenDepthSigma"})
        EXPECT_TRUE(applies(p, s)) << p;
}
