// Bevy's Rust and Filament's C++ for the knobs of engine_knobs_bevy.cpp / engine_knobs_filament.cpp:
// every knob of the table written as the engine's own field, so the text parses back to exactly the
// knobs (tests/export/engine_snippets_bevy_filament_test.cpp reads it with regexes of its own).
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/settings/number_text.h"

#include <string>

namespace st::xport {
namespace {

// A Rust f32 literal: `150.0`, not `150` (an integer literal does not coerce to f32 in vec![..]).
std::string rustFloat(const nlohmann::json& v) {
    std::string t = formatNumber(v.get<double>());
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t;
}

// A C++ float literal: `0.001f`, `1.0f`; exponents stay (`1e-05f`).
std::string cppFloat(const nlohmann::json& v) {
    std::string t = formatNumber(v.get<double>());
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t + "f";
}

std::string bevySnippet(const nlohmann::json& k) {
    std::string bounds;
    for (const nlohmann::json& b : k.at("bounds")) bounds += (bounds.empty() ? "" : ", ") + rustFloat(b);
    std::string rs;
    rs += "// Bevy 0.20 (main at 4805ca79), from shadowtune. The sun's components, the shadow map resource\n";
    rs += "// and the camera's filter; CascadeShadowConfig's fields are public, so the bounds go in as they are.\n";
    rs += "use bevy::light::{CascadeShadowConfig, DirectionalLightShadowMap, ShadowFilteringMethod};\n";
    rs += "use bevy::prelude::*;\n\n";
    rs += "fn shadowtune_shadows(mut commands: Commands) {\n";
    rs += "    commands.insert_resource(DirectionalLightShadowMap { size: " + k.at("shadow_map_size").dump() + " });\n";
    rs += "    commands.spawn((\n";
    rs += "        DirectionalLight {\n";
    rs += "            shadow_maps_enabled: true,\n";
    rs += "            shadow_depth_bias: " + rustFloat(k.at("shadow_depth_bias")) + ",\n";
    rs += "            shadow_normal_bias: " + rustFloat(k.at("shadow_normal_bias")) + ",\n";
    rs += "            ..default()\n";
    rs += "        },\n";
    rs += "        CascadeShadowConfig {\n";
    rs += "            bounds: vec![" + bounds + "],\n";
    rs += "            overlap_proportion: " + rustFloat(k.at("overlap_proportion")) + ",\n";
    rs += "            minimum_distance: " + rustFloat(k.at("minimum_distance")) + ",\n";
    rs += "        },\n";
    rs += "        // and the sun's Transform\n";
    rs += "    ));\n";
    rs += "    // On the camera entity (Camera3d):\n";
    rs += "    // commands.entity(camera).insert(ShadowFilteringMethod::" + k.at("shadow_filtering_method").get<std::string>() + ");\n";
    rs += "}\n";
    return rs;
}

std::string filamentSnippet(const nlohmann::json& k) {
    std::string cpp;
    cpp += "// Filament 1.51, from shadowtune. `engine`, `view` and the sun's entity `sun` (a DIRECTIONAL or SUN light).\n";
    cpp += "#include <filament/LightManager.h>\n#include <filament/View.h>\n\n";
    cpp += "using namespace filament;\n\n";
    cpp += "LightManager::ShadowOptions options;\n";
    cpp += "options.mapSize = " + k.at("mapSize").dump() + ";\n";
    cpp += "options.shadowCascades = " + k.at("shadowCascades").dump() + ";\n";
    const nlohmann::json& p = k.at("cascadeSplitPositions");
    for (std::size_t i = 0; i < p.size(); ++i)
        cpp += "options.cascadeSplitPositions[" + std::to_string(i) + "] = " + cppFloat(p[i]) + ";\n";
    for (const char* name : {"constantBias", "normalBias", "shadowFar", "shadowNearHint", "shadowFarHint"})
        cpp += std::string("options.") + name + " = " + cppFloat(k.at(name)) + ";\n";
    for (const char* name : {"stable", "lispsm"}) cpp += std::string("options.") + name + " = " + k.at(name).dump() + ";\n";
    for (const char* name : {"polygonOffsetConstant", "polygonOffsetSlope"})
        cpp += std::string("options.") + name + " = " + cppFloat(k.at(name)) + ";\n";
    cpp += "LightManager& lm = engine->getLightManager();\n";
    cpp += "lm.setShadowCaster(lm.getInstance(sun), true);\n";
    cpp += "lm.setShadowOptions(lm.getInstance(sun), options);\n";
    cpp += "view->setShadowingEnabled(true);\n";
    cpp += "view->setShadowType(View::ShadowType::" + k.at("shadowType").get<std::string>() + ");\n";
    return cpp;
}

}  // namespace

std::vector<PasteText> bevySnippets(const nlohmann::json& k) { return {{"bevy.rs", bevySnippet(k)}}; }
std::vector<PasteText> filamentSnippets(const nlohmann::json& k) { return {{"filament.cpp", filamentSnippet(k)}}; }

}  // namespace st::xport
