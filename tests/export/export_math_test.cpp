// The split-fraction math against hand computations, exact fields following the preset, and the
// engine names.
#include "renderer/export/engine_export.h"
#include "renderer/export/export_common.h"
#include "renderer/export/unreal_splits.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace st::xport {
namespace {

// Near 1, splits 10, 30, 60, end 100: easy fractions by hand.
Settings handSplits() {
    Settings s;
    s.camera.nearPlane = 1.0f;
    s.camera.farPlane = 400.0f;
    s.cascades.count = 4;
    s.cascades.scheme = SplitScheme::Manual;
    s.cascades.manualSplits = {10.0f, 30.0f, 60.0f};
    s.cascades.shadowDistance = 100.0f;
    return s;
}

// An item the export must have: a missing one fails the test (an exception) instead of crashing it.
const ExportItem& requireItem(const EngineExport& e, const std::string& name) {
    const ExportItem* i = e.find(name);
    if (!i) throw std::runtime_error("no export item " + name);
    return *i;
}

double number(const EngineExport& e, const char* name) { return requireItem(e, name).value.get<double>(); }

TEST(ExportMathTest, GodotAndFilamentSplitsAreFractionsOfTheRangeFromNear) {
    const EngineExport g = exportSettings(handSplits(), Engine::Godot);
    EXPECT_NEAR(number(g, "directional_shadow_split_1"), 9.0 / 99.0, 1e-6);   // (10 - 1) / (100 - 1)
    EXPECT_NEAR(number(g, "directional_shadow_split_2"), 29.0 / 99.0, 1e-6);  // (30 - 1) / 99
    EXPECT_NEAR(number(g, "directional_shadow_split_3"), 59.0 / 99.0, 1e-6);  // (60 - 1) / 99
    const nlohmann::json pos = requireItem(exportSettings(handSplits(), Engine::Filament), "cascadeSplitPositions").value;
    EXPECT_NEAR(pos[1].get<double>(), 29.0 / 99.0, 1e-6);
}

TEST(ExportMathTest, UnityAndThreeJsSplitsAreFractionsOfTheEnd) {
    EXPECT_EQ(requireItem(exportSettings(handSplits(), Engine::Unity), "cascade4Split").value,
              nlohmann::json({0.1, 0.3, 0.6}));
    const EngineExport t = exportSettings(handSplits(), Engine::ThreeJs);
    EXPECT_EQ(requireItem(t, "breaks").value, nlohmann::json({0.1, 0.3, 0.6, 1.0}));
    EXPECT_EQ(requireItem(t, "mode").value, "custom");  // manual splits go through customSplitsCallback
}

TEST(ExportMathTest, UnrealAccumulatedScaleAndExponentFit) {
    EXPECT_DOUBLE_EQ(accumulatedScale(3.0, 1, 3), 1.0 / 13.0);  // 1 / (1 + 3 + 9)
    EXPECT_DOUBLE_EQ(accumulatedScale(3.0, 2, 3), 4.0 / 13.0);
    EXPECT_DOUBLE_EQ(accumulatedScale(1.0, 1, 4), 0.25);        // exponent 1: uniform
    EXPECT_NEAR(fitDistributionExponent({1.0 / 7.0, 3.0 / 7.0}, 3).exponent, 2.0, 1e-6);  // 1, 2, 4
    const ExponentFit fit = fitDistributionExponent({9.0 / 99.0, 29.0 / 99.0, 59.0 / 99.0}, 4);
    EXPECT_GT(fit.maxError, 0.0);  // 10/30/60 is no geometric series: approximated, with its error
    EXPECT_EQ(requireItem(exportSettings(handSplits(), Engine::Unreal), "CascadeDistributionExponent").mapping,
              Mapping::Approximated);
}

TEST(ExportMathTest, ExactFieldsFollowThePreset) {
    Settings s = handSplits();
    s.cascades.shadowDistance = 80.0f;
    s.cascades.mapSize = 512;
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_max_distance"), 80.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unity), "shadowDistance"), 80.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unreal), "DynamicShadowDistanceMovableLight"), 8000.0);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "mapSize").value, 512);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Bevy), "DirectionalLightShadowMap.size").value, 512);
    s.bias.constant = 0.05f;
    EXPECT_NEAR(number(exportSettings(s, Engine::Bevy), "DirectionalLight.shadow_depth_bias"), 0.05, 1e-7);
    EXPECT_NEAR(number(exportSettings(s, Engine::Filament), "constantBias"), 0.05, 1e-7);
}

// Near 1, last cascade 60..100, fadeBand 0.5: the fade covers 20 m, a fifth of the distance.
TEST(ExportMathTest, FarFadeIsAShareOfTheShadowDistance) {
    Settings s = handSplits();
    s.cascades.fadeBand = 0.5f;
    EXPECT_NEAR(number(exportSettings(s, Engine::Unity), "cascadeBorder"), 0.2, 1e-6);
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "directional_shadow_fade_start"), 0.8, 1e-6);
    EXPECT_NEAR(number(exportSettings(s, Engine::Unreal), "ShadowDistanceFadeoutFraction"), 0.2, 1e-6);
    for (Engine e : {Engine::Bevy, Engine::ThreeJs})
        EXPECT_EQ(requireItem(exportSettings(s, e), "(far fade)").mapping, Mapping::NoEquivalent) << kEngineNames[size_t(e)];
    // Filament fades from 0.894 x shadowFar to shadowFar whenever shadowFar > 0 (light_directional.fs), with no
    // setting for the band; with shadowFar 0 (the camera far) it cuts off.
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "(far fade)").mapping, Mapping::Approximated);
    s.cascades.fadeBand = 0.0f;  // no fade: the engines' cut-off, stated as exact
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unity), "cascadeBorder").mapping, Mapping::Exact);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_fade_start"), 1.0);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "(far fade)").mapping, Mapping::NoEquivalent);
    s.cascades.shadowDistance = 0.0f;
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("(far fade)"), nullptr);
}

// A moment filter or PCSS never reads as an exact PCF setting: each engine names its nearest
// mode or says it has none.
TEST(ExportMathTest, MomentFiltersAndPcssMapToTheEnginesOwnModes) {
    Settings s = handSplits();
    s.filter.kind = FilterKind::Vsm;
    const EngineExport unity = exportSettings(s, Engine::Unity);
    EXPECT_EQ(requireItem(unity, "supportsSoftShadows").value, true);
    EXPECT_EQ(requireItem(unity, "supportsSoftShadows").mapping, Mapping::Approximated);
    EXPECT_EQ(requireItem(unity, "(filter.kind vsm)").mapping, Mapping::NoEquivalent);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::ThreeJs), "renderer.shadowMap.type").value, "VSMShadowMap");
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "View::setShadowType").value, "VSM");
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "ShadowOptions.vsm.elvsm").value, false);
    s.filter.kind = FilterKind::Evsm4;
    s.filter.blurRadius = 3;
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "ShadowOptions.vsm.elvsm").value, true);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "ShadowOptions.vsm.blurWidth").value, 7);
    for (Engine e : {Engine::Godot, Engine::Unreal, Engine::Bevy})
        EXPECT_EQ(requireItem(exportSettings(s, e), "(filter.kind evsm4)").mapping, Mapping::NoEquivalent) << kEngineNames[size_t(e)];
    s.filter.kind = FilterKind::Pcss;
    s.light.angularDiameter = 0.53f;
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "light_angular_distance"), 0.53, 1e-6);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unreal), "r.Shadow.FilterMethod").value, 1);
    EXPECT_NEAR(number(exportSettings(s, Engine::Unreal), "LightSourceAngle"), 0.53, 1e-6);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "View::setShadowType").value, "PCSS");
    s.filter.kind = FilterKind::Pcf2x2;
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "light_angular_distance"), 0.0);
    EXPECT_EQ(exportSettings(s, Engine::Unreal).find("LightSourceAngle"), nullptr);
}

// Settings no engine exposes are listed as such, and only when the preset uses them.
TEST(ExportMathTest, ShadowtuneOnlySettingsAreListedWhereUsed) {
    Settings s = handSplits();
    for (size_t i = 0; i < kEngineNames.size(); ++i)
        EXPECT_EQ(exportSettings(s, Engine(i)).find("(depth-fitted cascades)"), nullptr) << kEngineNames[i];
    s.cascades.depthBounds = DepthBounds::Fit;
    s.cascades.updateInterval = {1, 1, 2, 4};
    s.filter.padding = true;
    s.filter.screenSpace = ScreenSpace::Blur;
    for (size_t i = 0; i < kEngineNames.size(); ++i) {
        const EngineExport e = exportSettings(s, Engine(i));
        for (const char* name :
             {"(depth-fitted cascades)", "(cascade update interval)", "(PCF padding)", "(screen-space shadow blur)"}) {
            ASSERT_NE(e.find(name), nullptr) << kEngineNames[i] << " " << name;
            EXPECT_EQ(requireItem(e, name).mapping, Mapping::NoEquivalent);
        }
    }
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unity), "(cascade update interval)").value, nlohmann::json({1, 1, 2, 4}));
}

// No engine holds a bias per cascade: every exporter lists each scaled bias with its values per
// cascade (global x factor) as no equivalent; factors of 1, a zero bias or a receiver-plane bias a
// moment filter ignores are not listed.
TEST(ExportMathTest, BiasPerCascadeAndIgnoredFieldsAreListedAsTheyApply) {
    Settings s = handSplits();
    s.bias = {.constant = 0.02f, .slope = 1.0f, .normalOffset = 0.0f, .receiverPlane = false,
              .constantScale = {1.0f, 1.0f, 2.0f, 3.0f}, .slopeScale = {1.0f, 1.0f, 1.0f, 1.0f},
              .normalOffsetScale = {1.0f, 2.0f, 2.0f, 2.0f}};
    for (size_t i = 0; i < kEngineNames.size(); ++i) {
        const EngineExport e = exportSettings(s, Engine(i));
        const ExportItem* constant = e.find("(constant bias per cascade)");
        ASSERT_NE(constant, nullptr) << kEngineNames[i];
        EXPECT_EQ(constant->mapping, Mapping::NoEquivalent);
        EXPECT_EQ(constant->value, nlohmann::json({0.02, 0.02, 0.04, 0.06})) << kEngineNames[i];
        EXPECT_EQ(e.find("(slope bias per cascade)"), nullptr) << "factors of 1";
        EXPECT_EQ(e.find("(normal offset per cascade)"), nullptr) << "a factor of a zero offset";
    }
    s.filter.kind = FilterKind::Vsm;
    s.bias.receiverPlane = true;  // valid, and ignored by a moment filter
    for (Engine engine : {Engine::Godot, Engine::Unity, Engine::Bevy, Engine::Filament})
        EXPECT_EQ(exportSettings(s, engine).find("(receiver-plane bias)"), nullptr);
    s.filter.kind = FilterKind::Pcf2x2;
    EXPECT_NE(exportSettings(s, Engine::Godot).find("(receiver-plane bias)"), nullptr);
}

// The knobs of issue 20's scenarios and contact shadows: every engine either names its own setting
// for each (with the preset's value) or says it has none, and only when the preset uses the knob.
TEST(ExportMathTest, NewerKnobsMapToTheEnginesSettingOrSayThereIsNone) {
    Settings s = handSplits();
    const char* knobItems[] = {"(camera-relative light space)", "(fit field of view)", "(contact shadows)",
                               "(matrices one frame late)", "directional_shadow_min_fov", "ContactShadowLength",
                               "screenSpaceContactShadows"};
    for (size_t i = 0; i < kEngineNames.size(); ++i)
        for (const char* name : knobItems)
            EXPECT_EQ(exportSettings(s, Engine(i)).find(name), nullptr) << kEngineNames[i] << ": unused " << name;

    s.cascades.cameraRelative = true;
    s.cascades.fitFovY = 70.0f;
    s.cascades.matricesOneFrameLate = true;
    s.filter.contact = ContactShadows::March;
    s.filter.contactLength = 0.25f;
    s.filter.contactSteps = 16;
    // Per engine, the item that answers each knob and its mapping (the engine's own setting where it
    // has one, else a no-equivalent item).
    struct Answer {
        Engine engine;
        const char* cameraRelative;
        Mapping cameraRelativeMapping;
        const char* fitFovY;
        Mapping fitFovYMapping;
        const char* contact;
        Mapping contactMapping;
    };
    using M = Mapping;
    const Answer answers[] = {
        {Engine::Godot, "(camera-relative light space)", M::NoEquivalent, "directional_shadow_min_fov", M::Approximated,
         "(contact shadows)", M::NoEquivalent},
        {Engine::Unity, "(camera-relative light space)", M::NoEquivalent, "(fit field of view)", M::NoEquivalent,
         "(contact shadows)", M::NoEquivalent},
        {Engine::Unreal, "(camera-relative light space)", M::Exact, "(fit field of view)", M::NoEquivalent,
         "ContactShadowLength", M::Approximated},
        {Engine::Bevy, "(camera-relative light space)", M::NoEquivalent, "(fit field of view)", M::NoEquivalent,
         "ContactShadows.length", M::Approximated},
        {Engine::ThreeJs, "(camera-relative light space)", M::NoEquivalent, "(fit field of view)", M::NoEquivalent,
         "(contact shadows)", M::NoEquivalent},
        {Engine::Filament, "(camera-relative light space)", M::NoEquivalent, "(fit field of view)", M::NoEquivalent,
         "maxShadowDistance", M::Approximated},
    };
    for (const Answer& a : answers) {
        const EngineExport e = exportSettings(s, a.engine);
        const std::string engine(kEngineNames[size_t(a.engine)]);
        for (auto [name, mapping] : {std::pair{a.cameraRelative, a.cameraRelativeMapping}, {a.fitFovY, a.fitFovYMapping},
                                     {a.contact, a.contactMapping}, {"(matrices one frame late)", M::NoEquivalent}}) {
            const ExportItem* found = e.find(name);
            ASSERT_NE(found, nullptr) << engine << ": " << name;
            EXPECT_EQ(found->mapping, mapping) << engine << ": " << name;
            EXPECT_FALSE(found->note.empty()) << engine << ": " << name;
        }
        // A knob answered by the engine's own setting is not listed again as having none.
        if (std::string(a.contact) != "(contact shadows)") EXPECT_EQ(e.find("(contact shadows)"), nullptr) << engine;
        if (std::string(a.fitFovY) != "(fit field of view)") EXPECT_EQ(e.find("(fit field of view)"), nullptr) << engine;
    }
    // The values are the preset's, in the engine's units.
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_min_fov"), 70.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "(contact shadows)"), 0.25);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unreal), "ContactShadowLength"), 25.0);  // cm
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unreal), "ContactShadowLengthInWS").value, true);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Filament), "maxShadowDistance"), 0.25);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Bevy), "ContactShadows.length"), 0.25);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Bevy), "ContactShadows.linear_steps").value, 16);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Bevy), "DirectionalLight.contact_shadows_enabled").value, true);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "stepCount").value, 16);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "screenSpaceContactShadows").value, true);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unity), "(fit field of view)"), 70.0);
}

// Godot's depth bias in metres is shadow_bias / 100 x (2 r + pancake) x shadow_blur x the quality radius
// of soft_shadow_filter_quality (renderer_scene_render_rd.cpp: 1, 1.5, 2, 2, 3, 4), which PCSS leaves out
// (light_storage.cpp update_light_buffers): the export divides by the radius of the quality it writes.
TEST(ExportMathTest, GodotShadowBiasDividesByTheSoftFilterRadius) {
    Settings s = handSplits();
    s.bias.constant = 0.05f;
    s.cascades.zExtension = ZExtension::Distance;
    s.cascades.zExtensionDistance = 20.0f;
    const double range = double(presetFacts(s).texel.front()) * s.cascades.mapSize + 20.0;  // 2 r + pancake
    s.filter.kind = FilterKind::PcfNxN;
    s.filter.size = 3;  // soft low: radius 2
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Godot), "rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality").value, 2);
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "shadow_bias"), 100.0 * 0.05 / (range * 2.0), 1e-5);
    s.filter.size = 7;  // soft high: radius 3
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "shadow_bias"), 100.0 * 0.05 / (range * 3.0), 1e-5);
    s.filter.kind = FilterKind::Pcf2x2;  // hard: radius 1
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "shadow_bias"), 100.0 * 0.05 / range, 1e-5);
    s.filter.kind = FilterKind::Pcss;  // light_angular_distance > 0: no quality radius
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "shadow_bias"), 100.0 * 0.05 / range, 1e-5);
}

// directional_shadow_pancake_size 0 turns Godot's caster clamp off (use_pancake = pancake_size > 0), so
// shadowtune's 'pancake' (clamp, no reach) must not become 0; 'none' (no clamp, no reach) is 0.
TEST(ExportMathTest, GodotPancakeKeepsTheClampOn) {
    Settings s = handSplits();
    s.cascades.zExtension = ZExtension::Pancake;
    EXPECT_GT(number(exportSettings(s, Engine::Godot), "directional_shadow_pancake_size"), 0.0);
    s.cascades.zExtension = ZExtension::None;
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_pancake_size"), 0.0);
    s.cascades.zExtension = ZExtension::Distance;
    s.cascades.zExtensionDistance = 35.0f;
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_pancake_size"), 35.0);
}

// Godot draws 1, 2 or 4 splits: 3 cascades become 4 splits whose first two are the preset's, and the
// export says the count cannot be expressed instead of leaving Godot's unused default splits.
TEST(ExportMathTest, GodotThreeCascadesAreFourSplitsAndSaySo) {
    Settings s = handSplits();
    s.cascades.count = 3;
    s.cascades.manualSplits = {10.0f, 30.0f};
    const EngineExport g = exportSettings(s, Engine::Godot);
    EXPECT_EQ(requireItem(g, "directional_shadow_mode").value, 2);
    EXPECT_EQ(requireItem(g, "directional_shadow_mode").mapping, Mapping::Approximated);
    EXPECT_NE(requireItem(g, "directional_shadow_mode").note.find("cannot be expressed"), std::string::npos);
    EXPECT_NEAR(number(g, "directional_shadow_split_1"), 9.0 / 99.0, 1e-6);
    EXPECT_EQ(requireItem(g, "directional_shadow_split_1").mapping, Mapping::Exact);
    EXPECT_NEAR(number(g, "directional_shadow_split_2"), 29.0 / 99.0, 1e-6);
    EXPECT_EQ(requireItem(g, "directional_shadow_split_2").mapping, Mapping::Exact);
    EXPECT_GT(number(g, "directional_shadow_split_3"), 29.0 / 99.0);  // inside the preset's last cascade
    EXPECT_LT(number(g, "directional_shadow_split_3"), 1.0);
    EXPECT_EQ(requireItem(g, "directional_shadow_split_3").mapping, Mapping::Approximated);
    s.cascades.count = 2;  // the 2-split mode reads split_1 only
    s.cascades.manualSplits = {10.0f};
    const EngineExport two = exportSettings(s, Engine::Godot);
    EXPECT_EQ(requireItem(two, "directional_shadow_split_1").mapping, Mapping::Exact);
    EXPECT_EQ(requireItem(two, "directional_shadow_split_2").mapping, Mapping::NoEquivalent);
}

// CascadeShadowConfig.bounds takes any list of far bounds (cascade.rs), so the preset's splits map exactly;
// Bevy draws at most MAX_CASCADES_PER_LIGHT = 4 (light.rs), so 8 cascades are not exact.
TEST(ExportMathTest, BevyBoundsAreThePresetsSplitsUpToFour) {
    const EngineExport b = exportSettings(handSplits(), Engine::Bevy);  // 10, 30, 60: no geometric series
    EXPECT_EQ(requireItem(b, "CascadeShadowConfig.bounds").value, nlohmann::json({10.0, 30.0, 60.0, 100.0}));
    EXPECT_EQ(requireItem(b, "CascadeShadowConfig.bounds").mapping, Mapping::Exact);
    Settings s = handSplits();
    s.cascades.count = 8;
    s.cascades.manualSplits = {5.0f, 10.0f, 20.0f, 30.0f, 45.0f, 60.0f, 80.0f};
    const EngineExport eight = exportSettings(s, Engine::Bevy);
    EXPECT_EQ(requireItem(eight, "CascadeShadowConfig.bounds").value, nlohmann::json({5.0, 10.0, 20.0, 100.0}));
    EXPECT_EQ(requireItem(eight, "CascadeShadowConfig.bounds").mapping, Mapping::Approximated);
}

// DirectionalLight.soft_shadow_size is a world size in metres (shadow_sampling.wesl: the search's uv
// offset is size / (texel x map size)), not an angle: the export gives the reach of shadowtune's search.
TEST(ExportMathTest, BevySoftShadowSizeIsAWorldSize) {
    Settings s = handSplits();
    s.filter.kind = FilterKind::Pcss;
    s.light.angularDiameter = 0.53f;
    s.filter.pcssMaxRadius = 16.0f;
    const double texel = presetFacts(s).texel.front();
    EXPECT_NEAR(number(exportSettings(s, Engine::Bevy), "DirectionalLight.soft_shadow_size"), 16.0 * texel, 1e-6);
}

// Filament's stable is not only snapping: it fits a sphere and turns LiSPSM and caster focusing off
// (ShadowMap.cpp); its normal bias is normalBias x half a texel (ShadowMapManager.cpp).
TEST(ExportMathTest, FilamentStableIsNotExactAndNormalBiasIsHalfTexels) {
    Settings s = handSplits();
    s.cascades.fit = FitMode::Sphere;
    s.cascades.stabilize = true;
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "stable").value, true);
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "stable").mapping, Mapping::Approximated);
    s.cascades.stabilize = false;
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Filament), "stable").mapping, Mapping::Approximated);
    s.bias.normalOffset = 0.75f;
    EXPECT_NEAR(number(exportSettings(s, Engine::Filament), "normalBias"), 1.5, 1e-6);
}

// URP takes the first cascade whose culling sphere holds the pixel (Shadows.hlsl ComputeCascadeIndex):
// shadowtune's 'map' selection, never 'interval'.
TEST(ExportMathTest, UnitySelectionIsTheFirstSphereHoldingThePixel) {
    Settings s = handSplits();  // 4 cascades, interval
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unity), "(cascade selection)").mapping, Mapping::NoEquivalent);
    s.cascades.selection = Selection::Map;
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unity), "(cascade selection)").mapping, Mapping::Approximated);
    s.cascades.count = 1;
    s.cascades.manualSplits.clear();
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unity), "(cascade selection)").mapping, Mapping::Exact);
}

// ShadowUtils.GetShadowBias: with soft shadows both biases grow by 1.5 / 2.5 / 3.5 for low / medium / high.
TEST(ExportMathTest, UnitySoftShadowBiasFollowsTheQuality) {
    Settings s = handSplits();
    s.bias.constant = 0.05f;
    s.bias.normalOffset = 3.0f;
    const double texel = presetFacts(s).texel.front();
    s.filter.kind = FilterKind::PcfNxN;
    for (auto [size, quality, kernel] : {std::tuple{3, "Low", 1.5}, {5, "Medium", 2.5}, {7, "High", 3.5}}) {
        s.filter.size = size;
        const EngineExport u = exportSettings(s, Engine::Unity);
        EXPECT_EQ(requireItem(u, "softShadowQuality").value, quality);
        EXPECT_NEAR(number(u, "shadowDepthBias"), 0.05 / (texel * kernel), 1e-5) << quality;
        EXPECT_NEAR(number(u, "shadowNormalBias"), 3.0 / kernel, 1e-6) << quality;
    }
    s.filter.kind = FilterKind::Pcf2x2;  // hard: no multiplier
    EXPECT_NEAR(number(exportSettings(s, Engine::Unity), "shadowDepthBias"), 0.05 / texel, 1e-5);
}

// UE's slope bias is its constant bias x r.Shadow.CSMSlopeScaleDepthBias 3 x ShadowSlopeBias (ShadowRendering.cpp
// UpdateShaderDepthBias), tan clamped at r.Shadow.ShadowMaxSlopeScaleDepthBias 1: with the constant at
// 5 ShadowBias texels, bias.slope = 15 x ShadowBias x ShadowSlopeBias texels.
TEST(ExportMathTest, UnrealSlopeBiasIsAMultipleOfTheConstantBias) {
    Settings s = handSplits();
    const double texel = presetFacts(s).texel.front();
    s.bias.constant = float(2.5 * texel);  // ShadowBias 0.5
    s.bias.slope = 3.75f;                  // 2.5 texels x 3 x 0.5
    const EngineExport u = exportSettings(s, Engine::Unreal);
    EXPECT_NEAR(number(u, "ShadowBias"), 0.5, 1e-4);
    EXPECT_NEAR(number(u, "ShadowSlopeBias"), 0.5, 1e-4);
    EXPECT_EQ(requireItem(u, "r.Shadow.ShadowMaxSlopeScaleDepthBias").mapping, Mapping::NoEquivalent);
    EXPECT_EQ(requireItem(u, "r.Shadow.CSMReceiverBias").mapping, Mapping::NoEquivalent);
    s.bias.constant = 0.0f;  // no constant bias: UE's slope bias is 0 whatever ShadowSlopeBias says
    EXPECT_EQ(requireItem(exportSettings(s, Engine::Unreal), "ShadowSlopeBias").mapping, Mapping::NoEquivalent);
}

TEST(ExportMathTest, EngineNames) {
    EXPECT_EQ(parseEngine("godot"), Engine::Godot);
    EXPECT_EQ(parseEngine("threejs"), Engine::ThreeJs);
    EXPECT_FALSE(parseEngine("cryengine"));
    EXPECT_EQ(parseEngine("babylon"), Engine::Babylon);
    EXPECT_EQ(engineList(), "godot, unity, unreal, bevy, threejs, filament, babylon");
}

TEST(ExportMathTest, TextAndJsonListTheThreeGroups) {
    const EngineExport e = exportSettings(handSplits(), Engine::Godot);
    const std::string text = toText(e);
    for (const char* g : {"\nexact:\n", "\napproximated:\n", "\nno equivalent:\n"})
        EXPECT_NE(text.find(g), std::string::npos) << g;
    const nlohmann::ordered_json j = toJson(e);
    EXPECT_EQ(j["engine"], "godot");
    EXPECT_TRUE(j["exact"].is_array() && j["approximated"].is_array() && j["noEquivalent"].is_array());
}

}  // namespace
}  // namespace st::xport
