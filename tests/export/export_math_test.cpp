// The split-fraction math against hand computations, exact fields following the preset, and the
// engine names.
#include "renderer/export/engine_export.h"
#include "renderer/export/unreal_splits.h"

#include <gtest/gtest.h>

#include <string>
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

double number(const EngineExport& e, const char* name) { return e.find(name)->value.get<double>(); }

TEST(ExportMathTest, GodotAndFilamentSplitsAreFractionsOfTheRangeFromNear) {
    const EngineExport g = exportSettings(handSplits(), Engine::Godot);
    EXPECT_NEAR(number(g, "directional_shadow_split_1"), 9.0 / 99.0, 1e-6);   // (10 - 1) / (100 - 1)
    EXPECT_NEAR(number(g, "directional_shadow_split_2"), 29.0 / 99.0, 1e-6);  // (30 - 1) / 99
    EXPECT_NEAR(number(g, "directional_shadow_split_3"), 59.0 / 99.0, 1e-6);  // (60 - 1) / 99
    const nlohmann::json pos = exportSettings(handSplits(), Engine::Filament).find("cascadeSplitPositions")->value;
    EXPECT_NEAR(pos[1].get<double>(), 29.0 / 99.0, 1e-6);
}

TEST(ExportMathTest, UnityAndThreeJsSplitsAreFractionsOfTheEnd) {
    EXPECT_EQ(exportSettings(handSplits(), Engine::Unity).find("cascade4Split")->value,
              nlohmann::json({0.1, 0.3, 0.6}));
    const EngineExport t = exportSettings(handSplits(), Engine::ThreeJs);
    EXPECT_EQ(t.find("breaks")->value, nlohmann::json({0.1, 0.3, 0.6, 1.0}));
    EXPECT_EQ(t.find("mode")->value, "custom");  // manual splits go through customSplitsCallback
}

TEST(ExportMathTest, UnrealAccumulatedScaleAndExponentFit) {
    EXPECT_DOUBLE_EQ(accumulatedScale(3.0, 1, 3), 1.0 / 13.0);  // 1 / (1 + 3 + 9)
    EXPECT_DOUBLE_EQ(accumulatedScale(3.0, 2, 3), 4.0 / 13.0);
    EXPECT_DOUBLE_EQ(accumulatedScale(1.0, 1, 4), 0.25);        // exponent 1: uniform
    EXPECT_NEAR(fitDistributionExponent({1.0 / 7.0, 3.0 / 7.0}, 3).exponent, 2.0, 1e-6);  // 1, 2, 4
    const ExponentFit fit = fitDistributionExponent({9.0 / 99.0, 29.0 / 99.0, 59.0 / 99.0}, 4);
    EXPECT_GT(fit.maxError, 0.0);  // 10/30/60 is no geometric series: approximated, with its error
    EXPECT_EQ(exportSettings(handSplits(), Engine::Unreal).find("CascadeDistributionExponent")->mapping,
              Mapping::Approximated);
}

TEST(ExportMathTest, ExactFieldsFollowThePreset) {
    Settings s = handSplits();
    s.cascades.shadowDistance = 80.0f;
    s.cascades.mapSize = 512;
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_max_distance"), 80.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unity), "shadowDistance"), 80.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unreal), "DynamicShadowDistanceMovableLight"), 8000.0);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("mapSize")->value, 512);
    EXPECT_EQ(exportSettings(s, Engine::Bevy).find("DirectionalLightShadowMap.size")->value, 512);
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
    for (Engine e : {Engine::Bevy, Engine::ThreeJs, Engine::Filament})
        EXPECT_EQ(exportSettings(s, e).find("(far fade)")->mapping, Mapping::NoEquivalent) << kEngineNames[size_t(e)];
    s.cascades.fadeBand = 0.0f;  // no fade: the engines' cut-off, stated as exact
    EXPECT_EQ(exportSettings(s, Engine::Unity).find("cascadeBorder")->mapping, Mapping::Exact);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_fade_start"), 1.0);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("(far fade)"), nullptr);
}

// A moment filter or PCSS never reads as an exact PCF setting: each engine names its nearest
// mode or says it has none.
TEST(ExportMathTest, MomentFiltersAndPcssMapToTheEnginesOwnModes) {
    Settings s = handSplits();
    s.filter.kind = FilterKind::Vsm;
    const EngineExport unity = exportSettings(s, Engine::Unity);
    EXPECT_EQ(unity.find("supportsSoftShadows")->value, true);
    EXPECT_EQ(unity.find("supportsSoftShadows")->mapping, Mapping::Approximated);
    EXPECT_EQ(unity.find("(filter.kind vsm)")->mapping, Mapping::NoEquivalent);
    EXPECT_EQ(exportSettings(s, Engine::ThreeJs).find("renderer.shadowMap.type")->value, "VSMShadowMap");
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("View::setShadowType")->value, "VSM");
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("ShadowOptions.vsm.elvsm")->value, false);
    s.filter.kind = FilterKind::Evsm4;
    s.filter.blurRadius = 3;
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("ShadowOptions.vsm.elvsm")->value, true);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("ShadowOptions.vsm.blurWidth")->value, 7);
    for (Engine e : {Engine::Godot, Engine::Unreal, Engine::Bevy})
        EXPECT_EQ(exportSettings(s, e).find("(filter.kind evsm4)")->mapping, Mapping::NoEquivalent) << kEngineNames[size_t(e)];
    s.filter.kind = FilterKind::Pcss;
    s.light.angularDiameter = 0.53f;
    EXPECT_NEAR(number(exportSettings(s, Engine::Godot), "light_angular_distance"), 0.53, 1e-6);
    EXPECT_EQ(exportSettings(s, Engine::Unreal).find("r.Shadow.FilterMethod")->value, 1);
    EXPECT_NEAR(number(exportSettings(s, Engine::Unreal), "LightSourceAngle"), 0.53, 1e-6);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("View::setShadowType")->value, "PCSS");
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
            EXPECT_EQ(e.find(name)->mapping, Mapping::NoEquivalent);
        }
    }
    EXPECT_EQ(exportSettings(s, Engine::Unity).find("(cascade update interval)")->value, nlohmann::json({1, 1, 2, 4}));
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
         "(contact shadows)", M::NoEquivalent},
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
            const ExportItem* item = e.find(name);
            ASSERT_NE(item, nullptr) << engine << ": " << name;
            EXPECT_EQ(item->mapping, mapping) << engine << ": " << name;
            EXPECT_FALSE(item->note.empty()) << engine << ": " << name;
        }
        // A knob answered by the engine's own setting is not listed again as having none.
        if (std::string(a.contact) != "(contact shadows)") EXPECT_EQ(e.find("(contact shadows)"), nullptr) << engine;
        if (std::string(a.fitFovY) != "(fit field of view)") EXPECT_EQ(e.find("(fit field of view)"), nullptr) << engine;
    }
    // The values are the preset's, in the engine's units.
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "directional_shadow_min_fov"), 70.0);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Godot), "(contact shadows)"), 0.25);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unreal), "ContactShadowLength"), 25.0);  // cm
    EXPECT_EQ(exportSettings(s, Engine::Unreal).find("ContactShadowLengthInWS")->value, true);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Filament), "maxShadowDistance"), 0.25);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("stepCount")->value, 16);
    EXPECT_EQ(exportSettings(s, Engine::Filament).find("screenSpaceContactShadows")->value, true);
    EXPECT_DOUBLE_EQ(number(exportSettings(s, Engine::Unity), "(fit field of view)"), 70.0);
}

TEST(ExportMathTest, EngineNames) {
    EXPECT_EQ(parseEngine("godot"), Engine::Godot);
    EXPECT_EQ(parseEngine("threejs"), Engine::ThreeJs);
    EXPECT_FALSE(parseEngine("cryengine"));
    EXPECT_EQ(engineList(), "godot, unity, unreal, bevy, threejs, filament");
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
