// The kinds' descriptors (renderer/settings/kind_descriptors.h): they cover the whole field table,
// name the enumerators they describe, and answer fieldApplies as the shaders read the fields.
// The GL half (a field a kind does not read leaves its image unchanged) is
// tests/render/kind_descriptors_gl_test.cpp.
#include "renderer/settings/cascade_factors.h"
#include "renderer/settings/enum_names.h"
#include "renderer/settings/kind_descriptors.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace st {
namespace {

bool contains(const std::vector<std::string_view>& v, std::string_view x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}

TEST(KindDescriptorsTest, EveryFieldIsGatedByOneModeOrKindIndependent) {
    std::map<std::string, int> owners;  // path -> modes gating it + 1 if kind-independent
    for (const ModeDescriptor& m : modeDescriptors())
        for (std::string_view gated : m.gates) ++owners[std::string(gated)];
    for (std::string_view path : kindIndependentFields()) ++owners[std::string(path)];
    for (const FieldInfo& f : fieldTable()) EXPECT_EQ(owners[std::string(f.path)], 1) << f.path;
    for (const auto& [path, n] : owners) EXPECT_NE(findField(path), nullptr) << path << " is not a field of the table";
    EXPECT_EQ(owners.size(), fieldTable().size());
}

TEST(KindDescriptorsTest, EachModeDescribesEveryEnumeratorOfItsField) {
    for (const ModeDescriptor& m : modeDescriptors()) {
        const FieldInfo* f = findField(m.field);
        ASSERT_NE(f, nullptr) << m.field;
        ASSERT_EQ(f->kind, FieldKind::Enum) << m.field;
        ASSERT_EQ(m.kinds.size(), f->enumNames.size()) << m.field;
        for (std::size_t i = 0; i < m.kinds.size(); ++i) {
            EXPECT_EQ(m.kinds[i].value, int(i)) << m.field;
            EXPECT_EQ(m.kinds[i].name, f->enumNames[i]) << m.field;
        }
    }
    EXPECT_EQ(describe(FilterKind::Evsm4).name, "evsm4");
    EXPECT_EQ(describe(CascadeStorage::Atlas).name, "atlas");
    EXPECT_EQ(describe(Selection::Map).name, "map");
}

// Against the shaders as read by hand (shadow_sampling.glsl, moments.glsl): which kinds read what.
TEST(KindDescriptorsTest, FilterParametersApplyToTheKindsWhoseShaderReadsThem) {
    using F = FilterKind;
    const std::vector<std::pair<const char*, std::vector<F>>> uses{
        {"filter.size", {F::PcfNxN, F::Pcss, F::Tent}},
        {"filter.weights", {F::PcfNxN, F::Pcss}},  // PCSS's kernel takes the NxN weights (pcfWeights)
        {"filter.minVariance", {F::Vsm, F::Evsm2, F::Evsm4}},
        {"filter.evsmNegative", {F::Evsm4}},
        {"filter.momentBias", {F::Msm}},
        {"filter.blockerTaps", {F::Pcss}},
        {"bias.receiverPlane", {F::Hard, F::Pcf2x2, F::PcfNxN, F::Pcss, F::Vogel, F::Tent}},
        {"filter.vogelTaps", {F::Vogel}},
        {"filter.radius", {F::Vogel}}};
    Settings s;
    for (const auto& [path, kinds] : uses)
        for (int k = 0; k < ST_FILTER_COUNT; ++k) {
            s.filter.kind = F(k);
            const bool reads = std::find(kinds.begin(), kinds.end(), F(k)) != kinds.end();
            EXPECT_EQ(fieldApplies(s, path), reads) << path << " with " << enumName(F(k));
        }
    s.filter.kind = F::Vsm;
    EXPECT_EQ(notApplicableReason(s, "bias.receiverPlane"),
              "Used with filter.kind hard, pcf2x2, pcf-nxn, pcss, pcf-vogel and pcf-tent only (now vsm).");
}

TEST(KindDescriptorsTest, NumericRulesElementPathsAndUnknownPaths) {
    Settings s;
    s.cascades.count = 1;
    EXPECT_FALSE(fieldApplies(s, "cascades.blendBand"));
    s.cascades.count = 2;
    EXPECT_TRUE(fieldApplies(s, "cascades.blendBand"));
    s.bias.normalOffset = 0.0f;  // a factor of 0 m is 0 m
    EXPECT_FALSE(fieldApplies(s, "bias.normalOffsetScale"));
    EXPECT_FALSE(fieldApplies(s, "bias.normalOffsetScale[1]"));
    EXPECT_TRUE(fieldApplies(s, "bias.constantScale[1]"));
    s.bias.normalOffset = 1.0f;
    EXPECT_TRUE(fieldApplies(s, "bias.normalOffsetScale"));
    EXPECT_FALSE(fieldApplies(s, "filter.nonsense"));
    EXPECT_FALSE(fieldApplies(s, "notes"));
    s.cascades.storage = CascadeStorage::Array;
    EXPECT_FALSE(fieldApplies(s, "cascades.atlasPadding"));
    EXPECT_FALSE(fieldApplies(s, "cascades.mapSizes"));
    s.cascades.storage = CascadeStorage::Textures;
    EXPECT_FALSE(fieldApplies(s, "cascades.atlasPadding"));
    EXPECT_TRUE(fieldApplies(s, "cascades.mapSizes"));
}

TEST(KindDescriptorsTest, TunableFieldsAreTheShadowSettingsThatApply) {
    Settings s;
    s.filter.kind = FilterKind::Evsm2;
    s.bias.normalOffset = 0.0f;
    std::vector<std::string_view> paths;
    for (const FieldInfo* f : tunableFields(s)) paths.push_back(f->path);
    for (const char* p : {"cascades.count", "cascades.lambda", "filter.kind", "filter.evsmPositive", "bias.constant",
                          "bias.constantScale", "cascades.blendBand", "cascades.fadeBand"})
        EXPECT_TRUE(contains(paths, p)) << p;
    for (const char* p : {"camera.fovY", "light.elevation", "output.width", "measure.sunRays", "notes",
                          "cascades.casterCulling", "cascades.matricesOneFrameLate", "origin", "filter.evsmNegative",
                          "filter.size", "bias.receiverPlane",
                          "bias.normalOffsetScale", "cascades.manualSplits", "filter.screenBlurRadius"})
        EXPECT_FALSE(contains(paths, p)) << p;
    // scene, origin, camera, light, output, ..., and the one-frame-late debug knob
    EXPECT_EQ(applicableFields(s).size() - tunableFields(s).size(), 22u);
}

TEST(KindDescriptorsTest, FilterKindsNameTheStoragesTheySample) {
    EXPECT_TRUE(storageSupports(FilterKind::Pcf2x2, CascadeStorage::Textures));
    EXPECT_FALSE(storageSupports(FilterKind::Msm, CascadeStorage::Atlas));
    EXPECT_TRUE(storageSupports(FilterKind::Pcss, CascadeStorage::Atlas));
    EXPECT_FALSE(storageSupports(FilterKind::Pcss, CascadeStorage::Textures));
}

// ---- Bias per cascade in presets ---------------------------------------------------------------

TEST(CascadeBiasTest, FactorsMultiplyTheGlobalBiasAndDefaultToOne) {
    BiasSettings b{.constant = 0.02f, .slope = 2.0f, .normalOffset = 0.5f, .receiverPlane = false,
                   .constantScale = {1.0f, 3.0f}, .slopeScale = {}, .normalOffsetScale = {0.0f, 2.0f}};
    EXPECT_FLOAT_EQ(cascadeBias(b, 0).constant, 0.02f);
    EXPECT_FLOAT_EQ(cascadeBias(b, 1).constant, 0.06f);
    EXPECT_FLOAT_EQ(cascadeBias(b, 1).slope, 2.0f);
    EXPECT_FLOAT_EQ(cascadeBias(b, 0).normalOffset, 0.0f);
    EXPECT_FLOAT_EQ(cascadeBias(b, 1).normalOffset, 1.0f);
    EXPECT_TRUE(hasCascadeBias(b));
    EXPECT_FALSE(hasCascadeBias(BiasSettings{.constantScale = {1.0f, 1.0f}}));
}

TEST(CascadeBiasTest, FactorListsFollowTheCascadeCount) {
    Settings s;
    s.cascades.count = 3;
    s.bias.constantScale = {1.0f, 2.0f, 3.0f};
    s.cascades.count = 5;
    fitCascadeFactors(s.bias, s.cascades.count);
    EXPECT_EQ(s.bias.constantScale, (std::vector<float>{1.0f, 2.0f, 3.0f, 1.0f, 1.0f}));
    EXPECT_TRUE(s.bias.slopeScale.empty());
    EXPECT_TRUE(validate(s).empty());
    s.cascades.count = 2;
    fitCascadeFactors(s.bias, s.cascades.count);
    EXPECT_EQ(s.bias.constantScale, (std::vector<float>{1.0f, 2.0f}));
    EXPECT_TRUE(validate(s).empty());
}

// The per-cascade map sizes follow the count (padded with the last size) and go with the array
// storage, which has one size for every layer.
TEST(CascadeBiasTest, MapSizesFollowTheCountAndTheStorage) {
    Settings s;
    s.cascades.count = 3;
    s.cascades.storage = CascadeStorage::Textures;
    s.cascades.mapSizes = {2048, 1024, 512};
    s.cascades.count = 4;
    keepCascadeListsValid(s, "cascades.count");
    EXPECT_EQ(s.cascades.mapSizes, (std::vector<int>{2048, 1024, 512, 512}));
    EXPECT_TRUE(validate(s).empty());
    keepCascadeListsValid(s, "cascades.lambda");
    EXPECT_EQ(s.cascades.mapSizes.size(), 4u) << "another field leaves them";
    s.cascades.storage = CascadeStorage::Array;
    keepCascadeListsValid(s, "cascades.storage");
    EXPECT_TRUE(s.cascades.mapSizes.empty());
    EXPECT_TRUE(validate(s).empty());
}

TEST(CascadeBiasTest, JsonRoundTripAndOldPresetsReadAsBefore) {
    Settings s;
    s.cascades.count = 2;
    s.bias.constantScale = {1.0f, 2.5f};
    s.bias.normalOffsetScale = {0.75f, 1.0f};
    const nlohmann::json j = toJson(s);
    EXPECT_EQ(j["bias"]["constantScale"], nlohmann::json::parse("[1.0, 2.5]"));
    EXPECT_EQ(fromJson(j, "round-trip"), s);
    // A preset written before the factors existed: empty lists, every cascade at the global bias.
    const Settings old = fromJson(test::preset({{"cascades", {{"count", 3}}}, {"bias", {{"constant", 0.05}}}}), "old");
    EXPECT_TRUE(old.bias.constantScale.empty() && old.bias.slopeScale.empty() && old.bias.normalOffsetScale.empty());
    EXPECT_FLOAT_EQ(cascadeBias(old.bias, 2).constant, 0.05f);
}

TEST(CascadeBiasTest, ReadErrorsNameThePathAndTheReason) {
    const auto count = test::readErrors(test::preset({{"cascades", {{"count", 2}}}, {"bias", {{"slopeScale", {1.0, 2.0, 3.0}}}}}));
    EXPECT_TRUE(test::hasMessage(count, "presets/bad.json: bias.slopeScale: needs one factor per cascade (cascades.count 2) or none, got 3"));
    const auto type = test::readErrors(test::preset({{"bias", {{"constantScale", {1.0, "x"}}}}}));
    EXPECT_TRUE(test::hasMessage(type, "presets/bad.json: bias.constantScale[1]"));
}

}  // namespace
}  // namespace st
