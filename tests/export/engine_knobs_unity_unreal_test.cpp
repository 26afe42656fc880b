// Unity URP's and Unreal Engine 5's knob tables (renderer/export/engine_knobs_unity.cpp,
// engine_knobs_unreal.cpp): the shipped presets are the models of the engines' defaults, the models
// follow the sources' formulas, and the paste-ready text parses back to the knobs by readers of the
// engines' own formats written here (not the writers').
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <cctype>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace st::xport {
namespace {

Settings presetOf(const char* name) { return loadPreset(std::string(ST_PRESET_DIR "/engines/") + name); }

std::string textOf(const std::vector<PasteText>& texts, const std::string& file) {
    for (const PasteText& t : texts)
        if (t.file == file) return t.text;
    ADD_FAILURE() << "no " << file;
    return "";
}

// A Unity .asset's `  m_Name: value` lines (YAML; vectors as {x: a, y: b, z: c}) back to JSON.
nlohmann::json readUnityAsset(const std::string& text) {
    nlohmann::json out = nlohmann::json::object();
    const std::regex line(R"(^  (m_[A-Za-z0-9]+): (.+)$)"), axis(R"([xyzw]: ([-0-9.e]+))");
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) {
        std::smatch m;
        if (l.empty() || l[0] == '#') continue;
        if (!std::regex_match(l, m, line)) throw std::runtime_error("not a field line: " + l);
        const std::string v = m[2];
        if (v.front() != '{') {
            out[m[1].str()] = nlohmann::json::parse(v);
            continue;
        }
        nlohmann::json list = nlohmann::json::array();
        for (std::sregex_iterator it(v.begin(), v.end(), axis), end; it != end; ++it) list.push_back(nlohmann::json::parse((*it)[1].str()));
        out[m[1].str()] = list;
    }
    return out;
}

// UE's DefaultEngine.ini `r.X=value` lines under [SystemSettings], and the Python script's
// `set_editor_property('snake_name', value)` calls, the names back in UE's C++ spelling.
nlohmann::json readUnreal(const std::string& ini, const std::string& py) {
    nlohmann::json out = nlohmann::json::object();
    std::istringstream in(ini);
    bool system = false;
    for (std::string l; std::getline(in, l);) {
        if (!l.empty() && l[0] == '[') system = l == "[SystemSettings]";
        const auto eq = l.find('=');
        if (system && eq != std::string::npos) out[l.substr(0, eq)] = nlohmann::json::parse(l.substr(eq + 1));
    }
    const std::regex call(R"(set_editor_property\('([a-z_]+)', ([-0-9.e]+)\))");
    for (std::sregex_iterator it(py.begin(), py.end(), call), end; it != end; ++it) {
        std::string camel;
        bool up = true;
        for (char ch : (*it)[1].str()) {
            if (ch == '_') up = true;
            else camel += up ? char(std::toupper(static_cast<unsigned char>(ch))) : ch, up = false;
        }
        out[camel] = nlohmann::json::parse((*it)[2].str());
    }
    return out;
}

TEST(EngineKnobsUnityTest, ThePresetIsTheModelOfTheAssetDefaults) {
    const Settings preset = presetOf("unity.json");
    const Settings model = engineModel(Engine::Unity, defaultKnobs(Engine::Unity), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    EXPECT_EQ(model.cascades.casterFaces, CasterFaces::Front) << "Lit.shader's ShadowCaster pass culls back faces";
    EXPECT_FLOAT_EQ(model.bias.slope, 2.5f) << "SetGlobalDepthBias(1, 2.5)";
}

// Four cascades share the atlas in half-side tiles; the biases are texels of each cascade, x 2.5
// with medium soft shadows (ShadowUtils.GetShadowBias).
TEST(EngineKnobsUnityTest, CascadesTileTheAtlasAndTheBiasIsInEachCascadesTexels) {
    const Settings view = presetOf("unity.json");
    nlohmann::json k = {{"m_ShadowCascadeCount", 4}, {"m_ShadowDistance", 40.0}, {"m_SoftShadowsSupported", 1},
                        {"m_ShadowDepthBias", 1.0}, {"m_ShadowNormalBias", 0.5}};
    const Settings m = engineModel(Engine::Unity, k, view);
    EXPECT_EQ(m.cascades.mapSize, 1024);
    ASSERT_EQ(m.cascades.manualSplits.size(), 3u);
    EXPECT_FLOAT_EQ(m.cascades.manualSplits[1], 0.2f * 40.0f);
    EXPECT_EQ(m.filter.kind, FilterKind::Tent);
    EXPECT_EQ(m.filter.size, 5);
    EXPECT_FLOAT_EQ(m.bias.normalOffset, 1.25f);
    ASSERT_EQ(m.bias.constantScale.size(), 4u);
    EXPECT_GT(m.bias.constantScale[3], m.bias.constantScale[1]) << "the far cascade's texel is larger";
    const EngineKnobs back = knobsFor(Engine::Unity, m);
    EXPECT_TRUE(back.lacks.empty()) << back.lacks.front();
    EXPECT_DOUBLE_EQ(back.knobs.at("m_ShadowDepthBias").get<double>(), 1.0);
    EXPECT_EQ(back.knobs.at("m_MainLightShadowmapResolution"), 2048);
    Settings blended = m;
    blended.cascades.blendBand = 0.1f;
    blended.filter.kind = FilterKind::Vsm;
    EXPECT_GE(knobsFor(Engine::Unity, blended).lacks.size(), 2u);
    EXPECT_THROW(engineModel(Engine::Unity, {{"m_Cascade3Split", {0.3, 0.1}}, {"m_ShadowCascadeCount", 3}}, view),
                 std::invalid_argument);
    EXPECT_THROW(engineModel(Engine::Unity, {{"m_MainLightShadowmapResolution", 3000}}, view), std::invalid_argument);
    EXPECT_THROW(engineModel(Engine::Unity, {{"m_ShadowDistnace", 30.0}}, view), std::invalid_argument) << "a typo";
}

TEST(EngineKnobsUnityTest, TheAssetTextParsesBackToTheKnobs) {
    nlohmann::json k = defaultKnobs(Engine::Unity);
    k["m_ShadowCascadeCount"] = 3;
    k["m_Cascade3Split"] = {0.12, 0.35};
    k["m_SoftShadowsSupported"] = 1;
    const std::string text = textOf(engineSnippets(Engine::Unity, k), "unity-urp.asset");
    EXPECT_EQ(readUnityAsset(text), k) << text;
    EXPECT_NE(text.find("  m_Cascade3Split: {x: 0.12, y: 0.35}"), std::string::npos) << text;
}

TEST(EngineKnobsUnrealTest, ThePresetIsTheModelOfTheLightsDefaults) {
    const Settings preset = presetOf("unreal.json");
    const Settings model = engineModel(Engine::Unreal, defaultKnobs(Engine::Unreal), preset);
    EXPECT_EQ(model.cascades, preset.cascades);
    EXPECT_EQ(model.filter, preset.filter);
    EXPECT_EQ(model.bias, preset.bias);
    // GetSplitDistance: 1/13 and 4/13 of (200 m - near) past the near plane with exponent 3.
    const float near = preset.camera.nearPlane;
    EXPECT_NEAR(model.cascades.manualSplits[0], near + (200.0f - near) / 13.0f, 1e-4f);
    EXPECT_NEAR(model.cascades.manualSplits[1], near + 4.0f * (200.0f - near) / 13.0f, 1e-4f);
    EXPECT_FLOAT_EQ(model.bias.slope, 3.75f) << "5 x 0.5 x 3 x 0.5 texels x tan";
}

TEST(EngineKnobsUnrealTest, SplitsTheExponentCannotReachAreListedAndTheTextParsesBack) {
    Settings s = presetOf("unreal.json");
    s.cascades.manualSplits = {60.0f, 70.0f};  // the first split far out, the second close behind it
    const EngineKnobs k = knobsFor(Engine::Unreal, s);
    ASSERT_FALSE(k.lacks.empty());
    EXPECT_NE(k.lacks.front().find("distribution"), std::string::npos) << k.lacks.front();
    nlohmann::json knobs = defaultKnobs(Engine::Unreal);
    knobs["ShadowBias"] = 0.8;
    knobs["r.ShadowQuality"] = 3;
    const auto texts = engineSnippets(Engine::Unreal, knobs);
    EXPECT_EQ(readUnreal(textOf(texts, "unreal-engine.ini"), textOf(texts, "unreal-light.py")), knobs);
    EXPECT_EQ(engineModel(Engine::Unreal, knobs, s).filter.size, 3);
    EXPECT_THROW(engineModel(Engine::Unreal, {{"CascadeDistributionExponent", 9.0}}, s), std::invalid_argument);
}

}  // namespace
}  // namespace st::xport
