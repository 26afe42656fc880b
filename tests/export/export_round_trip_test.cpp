// Exporting each engine's own default preset (presets/engines/<engine>.json) to that engine gives
// the engine's documented defaults back. Every constant below cites where the default comes from;
// values derived through a texel size or a fit are compared within the rounding of the preset.
#include "renderer/export/engine_export.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace st::xport {
namespace {

EngineExport exported(const std::string& engine) {
    const Settings s = loadPreset(ST_PRESET_DIR "/engines/" + engine + ".json");
    return exportSettings(s, *parseEngine(engine));
}

// An item the export must have: a missing one fails the test (an exception) instead of crashing it.
const ExportItem& item(const EngineExport& e, const std::string& name) {
    const ExportItem* found = e.find(name);
    if (!found) throw std::runtime_error("no export item " + name);
    return *found;
}

const nlohmann::json& value(const EngineExport& e, const std::string& name) { return item(e, name).value; }

double number(const EngineExport& e, const std::string& name) { return value(e, name).get<double>(); }

TEST(ExportRoundTripTest, GodotGivesItsDefaultsBack) {
    const EngineExport e = exported("godot");
    // godotengine/godot scene/3d/light_3d.cpp: DirectionalLight3D::DirectionalLight3D and Light3D::Light3D.
    EXPECT_EQ(value(e, "directional_shadow_mode"), 2);  // SHADOW_PARALLEL_4_SPLITS
    EXPECT_DOUBLE_EQ(number(e, "directional_shadow_split_1"), 0.1);
    EXPECT_DOUBLE_EQ(number(e, "directional_shadow_split_2"), 0.2);
    EXPECT_DOUBLE_EQ(number(e, "directional_shadow_split_3"), 0.5);
    EXPECT_DOUBLE_EQ(number(e, "directional_shadow_max_distance"), 100.0);
    EXPECT_DOUBLE_EQ(number(e, "directional_shadow_pancake_size"), 20.0);
    EXPECT_NEAR(number(e, "directional_shadow_fade_start"), 0.8, 1e-4);
    EXPECT_EQ(value(e, "directional_shadow_blend_splits"), false);
    // shadow_bias / 100 x (2 r + pancake) x shadow_blur 1 x the soft-low quality radius 2 (light_storage.cpp
    // update_light_buffers; renderer_scene_render_rd.cpp directional_soft_shadow_filter_set_quality).
    EXPECT_NEAR(number(e, "shadow_bias"), 0.1, 1e-3);
    EXPECT_DOUBLE_EQ(number(e, "shadow_blur"), 1.0);
    EXPECT_DOUBLE_EQ(number(e, "shadow_normal_bias"), 2.0);
    // doc/classes/ProjectSettings.xml: directional_shadow/size 4096, soft_shadow_filter_quality 2.
    EXPECT_EQ(value(e, "rendering/lights_and_shadows/directional_shadow/size"), 4096);
    EXPECT_EQ(value(e, "rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality"), 2);
}

TEST(ExportRoundTripTest, UnityGivesItsDefaultsBack) {
    const EngineExport e = exported("unity");
    // Unity-Technologies/Graphics UniversalRenderPipelineAsset.cs field initialisers.
    EXPECT_EQ(value(e, "shadowCascadeCount"), 1);
    EXPECT_DOUBLE_EQ(number(e, "shadowDistance"), 50.0);
    EXPECT_EQ(value(e, "mainLightShadowmapResolution"), 2048);
    EXPECT_DOUBLE_EQ(number(e, "cascade2Split"), 0.25);
    EXPECT_EQ(value(e, "cascade4Split"), nlohmann::json({0.067, 0.2, 0.467}));
    EXPECT_NEAR(number(e, "shadowDepthBias"), 1.0, 1e-3);
    EXPECT_DOUBLE_EQ(number(e, "shadowNormalBias"), 1.0);
    EXPECT_EQ(value(e, "supportsSoftShadows"), false);
    EXPECT_NEAR(number(e, "cascadeBorder"), 0.2, 1e-4);
    // ShadowUtils.RenderShadowSlice: SetGlobalDepthBias(1, 2.5) on every caster, no asset setting.
    EXPECT_DOUBLE_EQ(number(e, "(slope bias)"), 2.5);
    EXPECT_EQ(item(e, "(slope bias)").mapping, Mapping::Approximated);
    EXPECT_EQ(item(e, "(cascade selection)").mapping, Mapping::Exact);  // one cascade
}

TEST(ExportRoundTripTest, UnrealGivesItsDefaultsBack) {
    const EngineExport e = exported("unreal");
    // DirectionalLightComponent.cpp, UDirectionalLightComponent constructor; r.Shadow.MaxCSMResolution.
    EXPECT_EQ(value(e, "DynamicShadowCascades"), 3);
    EXPECT_DOUBLE_EQ(number(e, "DynamicShadowDistanceMovableLight"), 20000.0);
    EXPECT_NEAR(number(e, "CascadeDistributionExponent"), 3.0, 1e-3);
    EXPECT_EQ(item(e, "CascadeDistributionExponent").mapping, Mapping::Exact);  // splits reproduced within 1 cm
    EXPECT_DOUBLE_EQ(number(e, "CascadeTransitionFraction"), 0.1);
    EXPECT_NEAR(number(e, "ShadowDistanceFadeoutFraction"), 0.1, 1e-4);
    EXPECT_EQ(value(e, "r.Shadow.MaxCSMResolution"), 2048);
    // LightComponent.cpp: ShadowBias 0.5, ShadowSlopeBias 0.5; ShadowRendering.cpp UpdateShaderDepthBias: the
    // slope bias is the constant one x r.Shadow.CSMSlopeScaleDepthBias 3 x ShadowSlopeBias (3.75 texels x tan).
    EXPECT_NEAR(number(e, "ShadowBias"), 0.5, 1e-3);
    EXPECT_NEAR(number(e, "ShadowSlopeBias"), 0.5, 1e-3);
    EXPECT_DOUBLE_EQ(number(e, "r.Shadow.ShadowMaxSlopeScaleDepthBias"), 1.0);
    EXPECT_DOUBLE_EQ(number(e, "r.Shadow.CSMReceiverBias"), 0.9);
}

TEST(ExportRoundTripTest, BevyGivesItsDefaultsBack) {
    const EngineExport e = exported("bevy");
    // bevyengine/bevy crates/bevy_light/src/cascade.rs, CascadeShadowConfigBuilder::default built into a
    // CascadeShadowConfig: bounds 10 x 15^(i/3) for i = 0..3 (calculate_cascade_bounds), minimum 0.1, overlap 0.2.
    const nlohmann::json& bounds = value(e, "CascadeShadowConfig.bounds");
    ASSERT_EQ(bounds.size(), 4u);
    for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(bounds[i].get<double>(), 10.0 * std::pow(15.0, double(i) / 3.0), 1e-3) << i;
    EXPECT_EQ(item(e, "CascadeShadowConfig.bounds").mapping, Mapping::Exact);
    EXPECT_NEAR(number(e, "CascadeShadowConfig.minimum_distance"), 0.1, 1e-6);
    EXPECT_NEAR(number(e, "CascadeShadowConfig.overlap_proportion"), 0.2, 1e-5);
    // crates/bevy_light/src/directional_light.rs: DirectionalLightShadowMap 2048, biases 0.02 / 1.8.
    EXPECT_EQ(value(e, "DirectionalLightShadowMap.size"), 2048);
    EXPECT_DOUBLE_EQ(number(e, "DirectionalLight.shadow_depth_bias"), 0.02);
    EXPECT_NEAR(number(e, "DirectionalLight.shadow_normal_bias"), 1.8, 1e-5);
    EXPECT_EQ(value(e, "ShadowFilteringMethod"), "Gaussian");  // crates/bevy_light/src/lib.rs #[default]
}

TEST(ExportRoundTripTest, ThreeJsGivesItsDefaultsBack) {
    const EngineExport e = exported("threejs");
    // mrdoob/three.js examples/jsm/csm/CSM.js constructor. shadowBias (+1e-6, toward acne) is not
    // compared: shadowtune's bias cannot point away from the light, so the preset carries 0.
    EXPECT_EQ(value(e, "cascades"), 3);
    EXPECT_DOUBLE_EQ(number(e, "maxFar"), 100000.0);
    EXPECT_EQ(value(e, "mode"), "practical");
    EXPECT_EQ(value(e, "shadowMapSize"), 2048);
    EXPECT_DOUBLE_EQ(number(e, "lightMargin"), 200.0);
    EXPECT_DOUBLE_EQ(number(e, "lightFar"), 2000.0);
}

TEST(ExportRoundTripTest, FilamentGivesItsDefaultsBack) {
    const EngineExport e = exported("filament");
    // google/filament filament/include/filament/LightManager.h, ShadowOptions.
    EXPECT_EQ(value(e, "mapSize"), 1024);
    EXPECT_EQ(value(e, "shadowCascades"), 1);
    EXPECT_EQ(value(e, "cascadeSplitPositions"), nlohmann::json({0.125, 0.25, 0.5}));
    EXPECT_DOUBLE_EQ(number(e, "shadowFar"), 0.0);
    EXPECT_EQ(value(e, "stable"), false);
    EXPECT_DOUBLE_EQ(number(e, "constantBias"), 0.001);
    EXPECT_DOUBLE_EQ(number(e, "normalBias"), 1.0);  // ShadowMapManager.cpp: x half a texel (normalOffset 0.5)
    EXPECT_DOUBLE_EQ(number(e, "polygonOffsetSlope"), 2.0);
}

}  // namespace
}  // namespace st::xport
