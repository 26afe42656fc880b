// renderer/export/engine_knobs_bevy.cpp and engine_knobs_filament.cpp: the engines' defaults model
// their shipped presets, the formulas of docs/engines.md by hand, what each lacks, bad knobs refused.
#include "renderer/export/engine_knobs.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace st::xport {
namespace {

Settings bevyFilamentYard() { return loadPreset(ST_PRESET_DIR "/default.json"); }

// presets/engines/bevy.json is the model of Bevy's defaults on its own view.
TEST(EngineKnobsTest, TheBevyPresetIsTheModelOfItsDefaults) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/bevy.json");
    const Settings model = engineModel(Engine::Bevy, defaultKnobs(Engine::Bevy), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    // By hand: bounds 10 x 15^(i/3) (cascade.rs calculate_cascade_bounds), ending at 150 m; the
    // overlap 0.2 of z2 as a share of cascade 1 (z1 .. z2); 1.8 x sqrt 2 texels of normal offset.
    ASSERT_EQ(model.cascades.manualSplits.size(), 3u);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(model.cascades.manualSplits[std::size_t(i)], 10.0 * std::pow(15.0, i / 3.0), 1e-4);
    EXPECT_FLOAT_EQ(model.cascades.shadowDistance, 150.0f);
    const double z1 = 10.0, z2 = 10.0 * std::pow(15.0, 1.0 / 3.0);
    EXPECT_NEAR(model.cascades.blendBand, 0.2 * z2 / (z2 - z1), 1e-6);
    EXPECT_NEAR(model.bias.normalOffset, 1.8 * std::sqrt(2.0), 1e-6);
    EXPECT_EQ(model.cascades.fit, FitMode::Diagonal);
    EXPECT_EQ(model.filter.kind, FilterKind::Tent) << "Gaussian is Castano's 5x5, shadowtune's tent";
}

// presets/engines/filament.json is the model of Filament's defaults on its own view.
TEST(EngineKnobsTest, TheFilamentPresetIsTheModelOfItsDefaults) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/filament.json");
    const Settings model = engineModel(Engine::Filament, defaultKnobs(Engine::Filament), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_FLOAT_EQ(model.bias.normalOffset, 0.5f) << "normalBias 1 x half a texel";
    EXPECT_EQ(model.filter.size, 3);
}

// Bevy by hand on the yard's view: more knobs than the defaults move.
TEST(EngineKnobsTest, BevyKnobsFollowItsSource) {
    const Settings view = bevyFilamentYard();
    nlohmann::json k = {{"bounds", {5.0, 40.0}}, {"overlap_proportion", 0.3}, {"shadow_map_size", 1500},
                        {"shadow_filtering_method", "Temporal"}, {"shadow_normal_bias", 1.0}};
    const Settings m = engineModel(Engine::Bevy, k, view);
    EXPECT_EQ(m.cascades.count, 2);
    EXPECT_EQ(m.cascades.manualSplits, std::vector<float>{5.0f});
    EXPECT_FLOAT_EQ(m.cascades.shadowDistance, 40.0f);
    EXPECT_EQ(m.cascades.mapSize, 2048) << "validate_shadow_map_size rounds up to a power of two";
    EXPECT_NEAR(m.cascades.blendBand, 0.3 * 5.0 / (5.0 - view.camera.nearPlane), 1e-6) << "two cascades: cascade 0's band";
    EXPECT_EQ(m.filter.kind, FilterKind::Vogel);
    EXPECT_EQ(m.filter.vogelTaps, 8);
    // Temporal: a disc of f(t) metres, t = ceil(diameter) / size, as texels of the unrounded box.
    const double tanY = std::tan(0.5 * view.camera.fovY * M_PI / 180.0), aspect = double(view.output.width) / view.output.height;
    const double h0 = view.camera.nearPlane * tanY, h1 = 5.0 * tanY, dz = 5.0 - view.camera.nearPlane;
    const double face = 2.0 * h1 * std::sqrt(1.0 + aspect * aspect);
    const double body = std::sqrt(dz * dz + std::pow((h0 + h1) * aspect, 2) + std::pow(h0 + h1, 2));
    const double d = std::max(face, body), t = std::ceil(d) / 2048.0;
    const double f = 0.015 + (t - 0.00390625) * 0.02 / (0.022949219 - 0.00390625);
    EXPECT_NEAR(m.filter.radius, f * 2048.0 / d, 1e-3);
    EXPECT_NEAR(m.bias.normalOffset, std::sqrt(2.0), 1e-6);
    k["bounds"] = {5.0, 500.0};  // past the 400 m far plane: the shadows end there
    EXPECT_FLOAT_EQ(engineModel(Engine::Bevy, k, view).cascades.shadowDistance, 0.0f);
}

TEST(EngineKnobsTest, WhatBevyAndFilamentLackIsListedAndBadKnobsAreRefused) {
    Settings s = bevyFilamentYard();
    s.cascades.count = 6;
    s.bias.slope = 1.0f;
    s.cascades.casterFaces = CasterFaces::Both;
    s.filter.kind = FilterKind::Msm;
    for (Engine e : {Engine::Bevy, Engine::Filament}) {
        const EngineKnobs k = knobsFor(e, s);
        EXPECT_GE(k.lacks.size(), 3u) << engineName(e);
        EXPECT_EQ(engineModel(e, k.knobs, s).cascades.count, 4) << engineName(e) << ": at most 4 cascades";
    }
    EXPECT_EQ(knobsFor(Engine::Bevy, s).knobs.at("bounds").size(), 4u);
    const Settings y = bevyFilamentYard();
    for (const nlohmann::json& bad : {nlohmann::json{{"bounds", {10.0, 5.0}}}, nlohmann::json{{"bounds", {1, 2, 3, 4, 5}}},
                                      nlohmann::json{{"overlap_proportion", 1.0}}, nlohmann::json{{"shadow_filtering_method", "Pcss"}},
                                      nlohmann::json{{"shadow_normal_bais", 1.0}}})
        EXPECT_THROW(engineModel(Engine::Bevy, bad, y), std::invalid_argument) << bad.dump();
    for (const nlohmann::json& bad :
         {nlohmann::json{{"shadowCascades", 5}}, nlohmann::json{{"shadowCascades", 3}, {"cascadeSplitPositions", {0.5, 0.25, 0.75}}},
          nlohmann::json{{"mapSize", 1000}}, nlohmann::json{{"shadowType", "DPCF"}}, nlohmann::json{{"constantbias", 0.01}}})
        EXPECT_THROW(engineModel(Engine::Filament, bad, y), std::invalid_argument) << bad.dump();
    EXPECT_EQ(knobUnit(Engine::Bevy, "shadow_depth_bias"), "m");
    EXPECT_EQ(knobUnit(Engine::Filament, "normalBias"), "half texels");
}

// Filament by hand: splits near + position x (shadowFar - near), the far fade from sqrt(0.8) x
// shadowFar, stable's snapped sphere; and the export back gives the same model.
TEST(EngineKnobsTest, FilamentKnobsFollowItsSourceAndExportBack) {
    const Settings view = bevyFilamentYard();
    const nlohmann::json k = {{"shadowCascades", 3}, {"cascadeSplitPositions", {0.1, 0.3, 0.5}}, {"shadowFar", 100.0},
                              {"stable", true}, {"normalBias", 2.0}, {"polygonOffsetSlope", 1.0}};
    const Settings m = engineModel(Engine::Filament, k, view);
    const double near = view.camera.nearPlane;
    ASSERT_EQ(m.cascades.manualSplits.size(), 2u);
    EXPECT_NEAR(m.cascades.manualSplits[1], near + 0.3 * (100.0 - near), 1e-4);
    EXPECT_FLOAT_EQ(m.cascades.shadowDistance, 100.0f);
    EXPECT_NEAR(m.cascades.fadeBand, (100.0 - std::sqrt(0.8) * 100.0) / (100.0 - m.cascades.manualSplits[1]), 1e-5);
    EXPECT_EQ(m.cascades.fit, FitMode::Sphere);
    EXPECT_TRUE(m.cascades.stabilize);
    EXPECT_FLOAT_EQ(m.bias.normalOffset, 1.0f);
    EXPECT_FLOAT_EQ(m.bias.slope, 1.0f);
    const EngineKnobs back = knobsFor(Engine::Filament, m);
    EXPECT_TRUE(back.lacks.empty()) << back.lacks.front();
    EXPECT_EQ(back.knobs.at("lispsm"), false) << "the model does not warp: the pasted text must not either";
    const Settings again = engineModel(Engine::Filament, back.knobs, view);
    EXPECT_NEAR(again.cascades.manualSplits[0], m.cascades.manualSplits[0], 1e-3);
    EXPECT_NEAR(again.cascades.fadeBand, m.cascades.fadeBand, 1e-5);
    EXPECT_EQ(again.cascades.fit, m.cascades.fit);
    EXPECT_EQ(again.bias, m.bias);
}

}  // namespace
}  // namespace st::xport
