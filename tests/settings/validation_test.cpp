// validate() on in-memory Settings: the editor's check, same rules as the JSON reader.
#include "renderer/settings/enum_names.h"
#include "renderer/settings/validation.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <limits>

namespace st {
namespace {

using test::hasMessage;

TEST(ValidationTest, DefaultAndChangedSettingsAreValid) {
    EXPECT_TRUE(validate(Settings{}).empty());
    EXPECT_TRUE(validate(test::everyFieldChanged()).empty());
}

TEST(ValidationTest, MessagesArePathColonReason) {
    Settings s;
    s.cascades.count = 12;
    EXPECT_EQ(validate(s), std::vector<std::string>{"cascades.count: must be in 1..8, got 12"});
}

TEST(ValidationTest, NonFiniteValues) {
    Settings s;
    s.cascades.lambda = std::numeric_limits<float>::quiet_NaN();
    s.camera.target.z = std::numeric_limits<float>::infinity();
    const auto messages = validate(s);
    EXPECT_TRUE(hasMessage(messages, "cascades.lambda: must be finite, got nan"));
    EXPECT_TRUE(hasMessage(messages, "camera.target[2]: must be finite, got inf"));
}

TEST(ValidationTest, EdgesOfRangesAreInclusive) {
    Settings s;
    s.camera.fovY = 179.0f;
    s.camera.nearPlane = 1e-4f;  // stored as a float just below 1e-4: still accepted
    s.cascades.blendBand = 0.5f;
    s.cascades.mapSize = 8192;
    s.filter.size = 9;
    s.light.elevation = -90.0f;
    EXPECT_TRUE(validate(s).empty()) << validate(s)[0];
    s.camera.fovY = 179.01f;
    EXPECT_TRUE(hasMessage(validate(s), "camera.fovY: must be in 1..179, got 179.01"));
}

TEST(ValidationTest, MapSizesNeedAStorageThatAllowsThemAndOneSizePerCascade) {
    Settings s;
    s.cascades.count = 4;
    s.cascades.mapSizes = {2048, 1024, 1024, 512};
    EXPECT_EQ(validate(s), std::vector<std::string>{
                               "cascades.mapSizes: the array storage gives every layer one size (cascades.mapSize); "
                               "per-cascade sizes need cascades.storage \"atlas\" or \"textures\""});
    for (CascadeStorage storage : {CascadeStorage::Atlas, CascadeStorage::Textures}) {
        s.cascades.storage = storage;
        EXPECT_TRUE(validate(s).empty()) << validate(s)[0];
    }
    s.cascades.count = 3;
    EXPECT_EQ(validate(s), std::vector<std::string>{"cascades.mapSizes: needs one size per cascade (3), got 4"});
    s.cascades.count = 4;
    s.cascades.mapSizes[2] = 1000;
    EXPECT_EQ(validate(s), std::vector<std::string>{
                               "cascades.mapSizes[2]: must be a power of two in 256..8192, got 1000"});
}

TEST(ValidationTest, InvalidEnumValue) {
    Settings s;
    s.output.view = static_cast<View>(9);
    EXPECT_TRUE(hasMessage(validate(s), "output.view: must be one of \"shaded\", \"cascades\", \"shadow\", "
                                        "\"texel-density\", \"side\", \"texel-grid\", got invalid value 9"));
}

TEST(ValidationTest, CrossFieldRules) {
    Settings s;
    s.camera.farPlane = 0.05f;
    EXPECT_EQ(validate(s), std::vector<std::string>{
                               "camera.farPlane: must be greater than camera.nearPlane (0.1), got 0.05"});
    s = Settings{};
    s.cascades.scheme = SplitScheme::Manual;
    EXPECT_TRUE(hasMessage(validate(s), "cascades.manualSplits: the manual scheme with 4 cascades needs exactly 3"));
    s.cascades.manualSplits = {5.0f, 20.0f, 80.0f};
    EXPECT_TRUE(validate(s).empty());
}

TEST(ValidationTest, RulesSkipFieldsThatBrokeTheirOwnRule) {
    Settings s;
    s.cascades.count = 20;  // out of range: the manual-split count rule must not also complain
    s.cascades.scheme = SplitScheme::Manual;
    EXPECT_EQ(validate(s).size(), 1u);
}

TEST(ValidationTest, CheckNumberTakesDoublesBeforeNarrowing) {
    const FieldInfo& far = *findField("camera.farPlane");
    EXPECT_EQ(checkNumber(far, 100.0), std::nullopt);
    EXPECT_EQ(checkNumber(far, 1e39), "must be in 0.0001..1000000, got 1e+39");
    EXPECT_EQ(checkNumber(*findField("cascades.mapSize"), 768), "must be a power of two in 256..8192, got 768");
}

TEST(ValidationTest, GroundIsOnlyForGltfScenes) {
    Settings s;
    s.ground = true;
    EXPECT_EQ(validate(s), std::vector<std::string>{"ground: must be false for builtin:yard, which has its own ground"});
    s.scene = "ship.glb";
    EXPECT_TRUE(validate(s).empty());
}

TEST(ValidationTest, UpdateIntervalsAreWholeFrames) {
    Settings s;
    s.cascades.updateInterval = {1.0f, 2.0f, 4.0f, 8.0f, 3.0f};  // past count: unused, but still frames
    EXPECT_TRUE(validate(s).empty());
    s.cascades.updateInterval = {1.0f, 2.5f};
    EXPECT_EQ(validate(s), std::vector<std::string>{"cascades.updateInterval[1]: must be a whole number of frames, got 2.5"});
    s.cascades.updateInterval = {0.0f};
    EXPECT_EQ(validate(s).size(), 1u);  // below the row's range
}

// The moment filters do not read bias.receiverPlane (kind_descriptors.h): it is kept, unused, as
// every field of another kind is, so choosing vsm with it on gives vsm's image.
TEST(ValidationTest, ReceiverPlaneBiasIsIgnoredByTheMomentFilters) {
    Settings s;
    s.bias.receiverPlane = true;
    for (int k = 0; k < ST_FILTER_COUNT; ++k) {
        s.filter.kind = FilterKind(k);
        EXPECT_TRUE(validate(s).empty()) << enumName(s.filter.kind);
    }
}

TEST(ValidationTest, BiasScalesHoldOneFactorPerCascadeOrNone) {
    Settings s;
    s.cascades.count = 3;
    s.bias.constantScale = {1.0f, 2.0f, 4.0f};
    s.bias.slopeScale = {};
    EXPECT_TRUE(validate(s).empty());
    s.bias.slopeScale = {1.0f, 0.5f};
    s.bias.normalOffsetScale = {1.0f, 1.0f, 1.0f, 1.0f};
    EXPECT_EQ(validate(s), (std::vector<std::string>{
                               "bias.slopeScale: needs one factor per cascade (cascades.count 3) or none, got 2",
                               "bias.normalOffsetScale: needs one factor per cascade (cascades.count 3) or none, got 4"}));
    s.bias.slopeScale = {};
    s.bias.normalOffsetScale = {};
    s.bias.constantScale = {1.0f, -1.0f, 200.0f};
    EXPECT_EQ(validate(s), (std::vector<std::string>{"bias.constantScale[1]: must be in 0..100, got -1",
                                                     "bias.constantScale[2]: must be in 0..100, got 200"}));
}

TEST(ValidationTest, MomentFiltersNeedTheArrayStorage) {
    Settings s;
    for (FilterKind k : {FilterKind::Vsm, FilterKind::Evsm2, FilterKind::Evsm4, FilterKind::Msm}) {
        s.filter.kind = k;
        s.cascades.storage = CascadeStorage::Array;
        EXPECT_TRUE(validate(s).empty()) << enumName(k);
        for (CascadeStorage storage : {CascadeStorage::Atlas, CascadeStorage::Textures}) {
            s.cascades.storage = storage;
            EXPECT_EQ(validate(s), std::vector<std::string>{
                                       "filter.kind: \"" + std::string(enumName(k)) +
                                       "\" needs cascades.storage \"array\", got \"" + std::string(enumName(storage)) +
                                       "\": the moment maps hold one layer per cascade of one texture array"});
        }
    }
    s.filter.kind = FilterKind::PcfNxN;  // the depth-compare filters read every storage
    EXPECT_TRUE(validate(s).empty());
}

TEST(ValidationTest, PcssNeedsOneDepthTexture) {
    Settings s;
    s.filter.kind = FilterKind::Pcss;
    for (CascadeStorage storage : {CascadeStorage::Array, CascadeStorage::Atlas}) {
        s.cascades.storage = storage;
        EXPECT_TRUE(validate(s).empty()) << enumName(storage);
    }
    s.cascades.storage = CascadeStorage::Textures;
    EXPECT_EQ(validate(s), std::vector<std::string>{"filter.kind: \"pcss\" needs cascades.storage \"array\" or "
                                                    "\"atlas\", got \"textures\": the blocker search reads raw "
                                                    "depths from one depth texture"});
}

TEST(ValidationTest, TheBleedRemapNeedsItsCutBelowItsTop) {
    Settings s;
    s.filter.bleedLow = 0.5f;
    s.filter.bleedHigh = 0.5f;
    EXPECT_EQ(validate(s), std::vector<std::string>{"filter.bleedHigh: must be greater than filter.bleedLow (0.5), got 0.5"});
    s.filter.bleedHigh = 0.95f;
    EXPECT_TRUE(validate(s).empty());
}

TEST(ValidationTest, CrossFieldRulesAreDescribed) {
    EXPECT_EQ(crossFieldRuleDescriptions().size(), 12u);
    for (const auto description : crossFieldRuleDescriptions()) EXPECT_EQ(description.back(), '.');
}

}  // namespace
}  // namespace st
