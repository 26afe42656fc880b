// renderer/export/engine_knobs.h: each web engine's knobs, its model and the export back to knobs.
#include "renderer/export/engine_export.h"
#include "renderer/export/engine_knobs.h"
#include "renderer/csm/cascade_plan.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace st::xport {
namespace {

Settings yard() { return loadPreset(ST_PRESET_DIR "/default.json"); }

std::vector<Engine> tabledEngines() {
    std::vector<Engine> out;
    for (std::size_t i = 0; i < kEngineNames.size(); ++i)
        if (hasKnobTable(Engine(i))) out.push_back(Engine(i));
    return out;
}

// The shipped presets/engines/threejs.json is the model of three.js's defaults on its own view.
TEST(EngineKnobsTest, TheThreejsPresetIsTheModelOfItsDefaults) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/threejs.json");
    const Settings model = engineModel(Engine::ThreeJs, defaultKnobs(Engine::ThreeJs), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_EQ(model.cascades.casterFaces, CasterFaces::Back);
    EXPECT_EQ(model.cascades.fit, FitMode::Diagonal);
    EXPECT_FLOAT_EQ(model.bias.constant, -0.000001f * 1999.0f) << "shadowBias 1e-6 of the 1999 m light depth, away from the light";
}

// Knobs -> model -> knobs: what the model says is exported back as the same knobs.
TEST(EngineKnobsTest, TheModelExportsBackToTheSameKnobs) {
    for (Engine e : tabledEngines()) {
        const nlohmann::json defaults = defaultKnobs(e);
        const Settings model = engineModel(e, defaults, yard());
        const EngineKnobs back = knobsFor(e, model);
        EXPECT_TRUE(back.lacks.empty()) << engineName(e) << ": " << back.lacks.front();
        EXPECT_EQ(engineModel(e, back.knobs, yard()), model) << engineName(e) << " " << back.knobs.dump();
    }
    nlohmann::json custom = defaultKnobs(Engine::ThreeJs);
    custom["mode"] = "custom";
    custom["breaks"] = {0.05, 0.3, 1.0};
    custom["radius"] = 2.5;
    custom["normalBias"] = 0.02;
    custom["shadowSide"] = "double";
    const Settings model = engineModel(Engine::ThreeJs, custom, yard());
    EXPECT_EQ(model.cascades.scheme, SplitScheme::Manual);
    ASSERT_EQ(model.cascades.manualSplits.size(), 2u);
    EXPECT_FLOAT_EQ(model.cascades.manualSplits[0], 0.05f * yard().camera.farPlane);
    EXPECT_EQ(model.cascades.casterFaces, CasterFaces::Both);
    EXPECT_EQ(engineModel(Engine::ThreeJs, knobsFor(Engine::ThreeJs, model).knobs, yard()), model);
}

TEST(EngineKnobsTest, WhatThreejsLacksIsListedAndBadKnobsAreRefused) {
    Settings s = yard();
    s.bias.slope = 2.0f;
    s.bias.receiverPlane = true;
    s.cascades.fit = FitMode::Samples;
    const EngineKnobs k = knobsFor(Engine::ThreeJs, s);
    EXPECT_GE(k.lacks.size(), 3u);
    nlohmann::json bad = {{"cascade", 3}};
    EXPECT_THROW(engineModel(Engine::ThreeJs, bad, s), std::invalid_argument);
    bad = {{"cascades", 9}};
    EXPECT_THROW(engineModel(Engine::ThreeJs, bad, s), std::invalid_argument);
    bad = {{"mode", "sideways"}};
    EXPECT_THROW(engineModel(Engine::ThreeJs, bad, s), std::invalid_argument);
    bad = {{"shadowMapSize", "big"}};
    EXPECT_THROW(engineModel(Engine::ThreeJs, bad, s), std::invalid_argument);
}

}  // namespace
}  // namespace st::xport

namespace st::xport {
namespace {

// The shipped presets/engines/babylon.json is the model of Babylon.js's defaults on its own view, and
// `export --to babylon` gives those defaults back with nothing lacking.
TEST(EngineKnobsTest, TheBabylonPresetIsTheModelOfItsDefaultsAndExportsThemBack) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/babylon.json");
    const Settings model = engineModel(Engine::Babylon, defaultKnobs(Engine::Babylon), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_FLOAT_EQ(model.bias.constant, 1.5f * 0.00005f) << "the bias twice over with depth clamp (NOTES.md)";
    const EngineExport e = exportSettings(preset, Engine::Babylon);
    EXPECT_EQ(e.find("bias")->value.get<double>(), defaultKnobs(Engine::Babylon).at("bias").get<double>());
    EXPECT_EQ(e.find("filteringQuality")->value, "high");
    for (const ExportItem& i : e.items) EXPECT_NE(i.mapping, Mapping::NoEquivalent) << i.name << ": " << i.note;
}

}  // namespace
}  // namespace st::xport

namespace st::xport {
namespace {

// Godot's defaults on the yard's view (60 deg, 16:9, near 0.1), against the formulas of
// docs/engines.md computed here by hand: splits at near + split_i x (max - near), a quarter of the
// 4096 atlas per split, Vogel taps of soft low, and split 0's depth bias 0.1 / 100 x (2 r + 20 m) x
// (blur 1 x radius 2), r the farthest corner from the mean of the slice's corners, widened a texel.
TEST(EngineKnobsTest, GodotDefaultsFollowItsSource) {
    const Settings view = yard();
    const Settings m = engineModel(Engine::Godot, defaultKnobs(Engine::Godot), view);
    ASSERT_EQ(m.cascades.count, 4);
    ASSERT_EQ(m.cascades.manualSplits.size(), 3u);
    const double near = view.camera.nearPlane, max = 100.0;
    EXPECT_NEAR(m.cascades.manualSplits[0], near + 0.1 * (max - near), 1e-4);
    EXPECT_NEAR(m.cascades.manualSplits[2], near + 0.5 * (max - near), 1e-4);
    EXPECT_EQ(m.cascades.mapSize, 2048);
    EXPECT_EQ(m.cascades.casterFaces, CasterFaces::Front);
    EXPECT_EQ(m.filter.kind, FilterKind::Vogel);
    EXPECT_EQ(m.filter.vogelTaps, 4);
    EXPECT_FLOAT_EQ(m.filter.radius, 2.0f);
    EXPECT_EQ(m.bias.normalOffsetUnit, OffsetUnit::Texels);
    EXPECT_FLOAT_EQ(m.bias.normalOffset, 2.0f);
    const double tanY = std::tan(0.5 * view.camera.fovY * M_PI / 180.0);
    const double aspect = double(view.output.width) / view.output.height;
    const double z0 = near, z1 = m.cascades.manualSplits[0];
    const double centreZ = 0.5 * (z0 + z1);  // the corners' mean lies on the view axis
    const double h = z1 * tanY, w = h * aspect;
    const double r = std::sqrt((z1 - centreZ) * (z1 - centreZ) + h * h + w * w) * 2048.0 / 2046.0;
    EXPECT_NEAR(m.bias.constant, 0.1 / 100.0 * (2.0 * r + 20.0) * 2.0, 1e-5);
    ASSERT_EQ(m.bias.constantScale.size(), 4u);
    EXPECT_GT(m.bias.constantScale[3], m.bias.constantScale[1]) << "a farther split has a larger sphere, so more bias";
    // fade from 0.8 x 100 m to 100 m: a share (100 - 80) / (100 - split 3) of the last cascade.
    EXPECT_NEAR(m.cascades.fadeBand, 20.0 / (max - m.cascades.manualSplits[2]), 1e-5);
}

TEST(EngineKnobsTest, WhatGodotLacksIsListedAndItsModesHoldOneTwoOrFourSplits) {
    Settings s = yard();
    s.cascades.count = 3;
    s.bias.slope = 1.0f;
    s.cascades.casterFaces = CasterFaces::Both;
    const EngineKnobs k = knobsFor(Engine::Godot, s);
    EXPECT_EQ(k.knobs.at("directional_shadow_mode"), 2);
    EXPECT_GE(k.lacks.size(), 3u);
    EXPECT_EQ(engineModel(Engine::Godot, k.knobs, s).cascades.count, 4);
    nlohmann::json bad = {{"directional_shadow_split_2", 0.05}};
    EXPECT_THROW(engineModel(Engine::Godot, bad, s), std::invalid_argument) << "splits must increase";
    bad = {{"rendering/lights_and_shadows/directional_shadow/soft_shadow_filter_quality", 6}};
    EXPECT_THROW(engineModel(Engine::Godot, bad, s), std::invalid_argument);
    EXPECT_TRUE(runsHere(Engine::ThreeJs));
    EXPECT_FALSE(runsHere(Engine::Godot));
    // The knobs carry their units (a knob renamed in its table without its unit would drop below).
    for (Engine e : tabledEngines()) {
        int withUnit = 0;
        const nlohmann::json knobs = defaultKnobs(e);
        for (auto it = knobs.begin(); it != knobs.end(); ++it) withUnit += !knobUnit(e, it.key()).empty();
        EXPECT_GE(withUnit, 4) << engineName(e);
    }
    EXPECT_EQ(knobUnit(Engine::Godot, "shadow_normal_bias"), "texels");
    EXPECT_EQ(knobUnit(Engine::ThreeJs, "normalBias"), "m");
}

// Whatever the settings, the knobs an engine's table gives for them load back in its model: a tuner
// projecting onto the engine must never get knobs the engine refuses (they would leave the point
// unprojected). Extremes each table has to clamp, with what it lacks listed instead.
TEST(EngineKnobsTest, TheKnobsForAnySettingsLoadInTheModel) {
    Settings wild = yard();
    wild.cascades.count = 8;
    wild.cascades.scheme = SplitScheme::Manual;
    wild.cascades.manualSplits = {0.5f, 1.0f, 2.0f, 300.0f, 301.0f, 302.0f, 303.0f};
    wild.bias.constant = 0.0001f;
    wild.bias.slope = 10.0f;
    wild.bias.normalOffset = 9.0f;
    wild.cascades.blendBand = 0.9f;
    for (Engine e : tabledEngines()) {
        const EngineKnobs k = knobsFor(e, wild);
        EXPECT_FALSE(k.lacks.empty()) << engineName(e);
        EXPECT_NO_THROW(engineModel(e, k.knobs, wild)) << engineName(e) << " " << k.knobs.dump();
    }
}

// An engine's defaults load on any view, a room's 15 m far plane too (Bevy's default bounds run to
// 150 m; the living room's tune failed on them).
TEST(EngineKnobsTest, TheDefaultsLoadOnAShortView) {
    Settings room = yard();
    room.camera.farPlane = 15.0f;
    for (Engine e : tabledEngines()) {
        Settings m;
        EXPECT_NO_THROW(m = engineModel(e, defaultKnobs(e), room)) << engineName(e);
        const std::vector<float> splits = csm::planSplits(m, std::nullopt);
        EXPECT_LE(splits.back(), 15.0f) << engineName(e);
    }
}

}  // namespace
}  // namespace st::xport
