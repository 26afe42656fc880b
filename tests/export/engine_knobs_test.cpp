// renderer/export/engine_knobs.h: each web engine's knobs, its model and the export back to knobs.
#include "renderer/export/engine_export.h"
#include "renderer/export/engine_knobs.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace st::xport {
namespace {

Settings yard() { return loadPreset(ST_PRESET_DIR "/default.json"); }

// The shipped presets/engines/threejs.json is the model of three.js's defaults on its own view.
TEST(EngineKnobsTest, TheThreejsPresetIsTheModelOfItsDefaults) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/threejs.json");
    const Settings model = engineModel(WebEngine::Threejs, defaultKnobs(WebEngine::Threejs), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_EQ(model.cascades.casterFaces, CasterFaces::Back);
    EXPECT_EQ(model.cascades.fit, FitMode::Diagonal);
    EXPECT_FLOAT_EQ(model.bias.constant, -0.000001f * 1999.0f) << "shadowBias 1e-6 of the 1999 m light depth, away from the light";
}

// Knobs -> model -> knobs: what the model says is exported back as the same knobs.
TEST(EngineKnobsTest, TheModelExportsBackToTheSameKnobs) {
    for (WebEngine e : {WebEngine::Threejs, WebEngine::Babylon}) {
        const nlohmann::json defaults = defaultKnobs(e);
        const Settings model = engineModel(e, defaults, yard());
        const EngineKnobs back = knobsFor(e, model);
        EXPECT_TRUE(back.lacks.empty()) << webEngineName(e) << ": " << back.lacks.front();
        EXPECT_EQ(engineModel(e, back.knobs, yard()), model) << webEngineName(e) << " " << back.knobs.dump();
    }
    nlohmann::json custom = defaultKnobs(WebEngine::Threejs);
    custom["mode"] = "custom";
    custom["breaks"] = {0.05, 0.3, 1.0};
    custom["radius"] = 2.5;
    custom["normalBias"] = 0.02;
    custom["shadowSide"] = "double";
    const Settings model = engineModel(WebEngine::Threejs, custom, yard());
    EXPECT_EQ(model.cascades.scheme, SplitScheme::Manual);
    ASSERT_EQ(model.cascades.manualSplits.size(), 2u);
    EXPECT_FLOAT_EQ(model.cascades.manualSplits[0], 0.05f * yard().camera.farPlane);
    EXPECT_EQ(model.cascades.casterFaces, CasterFaces::Both);
    EXPECT_EQ(engineModel(WebEngine::Threejs, knobsFor(WebEngine::Threejs, model).knobs, yard()), model);
}

TEST(EngineKnobsTest, WhatThreejsLacksIsListedAndBadKnobsAreRefused) {
    Settings s = yard();
    s.bias.slope = 2.0f;
    s.bias.receiverPlane = true;
    s.cascades.fit = FitMode::Samples;
    const EngineKnobs k = knobsFor(WebEngine::Threejs, s);
    EXPECT_GE(k.lacks.size(), 3u);
    nlohmann::json bad = {{"cascade", 3}};
    EXPECT_THROW(engineModel(WebEngine::Threejs, bad, s), std::invalid_argument);
    bad = {{"cascades", 9}};
    EXPECT_THROW(engineModel(WebEngine::Threejs, bad, s), std::invalid_argument);
    bad = {{"mode", "sideways"}};
    EXPECT_THROW(engineModel(WebEngine::Threejs, bad, s), std::invalid_argument);
    bad = {{"shadowMapSize", "big"}};
    EXPECT_THROW(engineModel(WebEngine::Threejs, bad, s), std::invalid_argument);
}

}  // namespace
}  // namespace st::xport

namespace st::xport {
namespace {

// The shipped presets/engines/babylon.json is the model of Babylon.js's defaults on its own view, and
// `export --to babylon` gives those defaults back with nothing lacking.
TEST(EngineKnobsTest, TheBabylonPresetIsTheModelOfItsDefaultsAndExportsThemBack) {
    const Settings preset = loadPreset(ST_PRESET_DIR "/engines/babylon.json");
    const Settings model = engineModel(WebEngine::Babylon, defaultKnobs(WebEngine::Babylon), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_FLOAT_EQ(model.bias.constant, 1.5f * 0.00005f) << "the bias twice over with depth clamp (NOTES.md)";
    const EngineExport e = exportSettings(preset, Engine::Babylon);
    EXPECT_EQ(e.find("bias")->value.get<double>(), defaultKnobs(WebEngine::Babylon).at("bias").get<double>());
    EXPECT_EQ(e.find("filteringQuality")->value, "high");
    for (const ExportItem& i : e.items) EXPECT_NE(i.mapping, Mapping::NoEquivalent) << i.name << ": " << i.note;
}

}  // namespace
}  // namespace st::xport
