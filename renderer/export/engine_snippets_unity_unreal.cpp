// Unity URP's and Unreal Engine 5's knobs as their own text: the asset's serialized fields as the
// .asset file holds them, and UE's console variables (DefaultEngine.ini) with the light's properties
// set by an editor Python script. Built from the knobs alone, so what is pasted is what the model
// renders (engine_knobs_unity.cpp, engine_knobs_unreal.cpp).
#include "renderer/export/engine_knobs_detail.h"

#include <cctype>
#include <string>

namespace st::xport {
namespace {

// A Unity YAML value: a number, or a vector as {x: .., y: .., z: ..}.
std::string unityYamlValue(const nlohmann::json& v) {
    if (!v.is_array()) return v.dump();
    static constexpr const char* kAxes[] = {"x", "y", "z", "w"};
    std::string out = "{";
    for (std::size_t i = 0; i < v.size() && i < 4; ++i) out += std::string(i ? ", " : "") + kAxes[i] + ": " + v[i].dump();
    return out + "}";
}

// "DynamicShadowCascades" -> "dynamic_shadow_cascades": UE's Python names of C++ properties.
std::string snakeCase(const std::string& name) {
    std::string out;
    for (char ch : name) {
        if (std::isupper(static_cast<unsigned char>(ch)) && !out.empty()) out += '_';
        out += char(std::tolower(static_cast<unsigned char>(ch)));
    }
    return out;
}

}  // namespace

std::vector<PasteText> unitySnippets(const nlohmann::json& k) {
    std::string a = "# Unity URP, from shadowtune: the shadow fields of your UniversalRenderPipelineAsset. With\n"
                    "# Project Settings > Editor > Asset Serialization 'Force Text', replace these lines of the\n"
                    "# asset's .asset file (under MonoBehaviour:), or set the same values in its inspector.\n"
                    "# The sun's Light keeps 'Use Pipeline Settings' for its bias; Shadow Type 'Soft Shadows' when\n"
                    "# m_SoftShadowsSupported is 1.\n";
    for (auto it = k.begin(); it != k.end(); ++it) a += "  " + it.key() + ": " + unityYamlValue(it.value()) + "\n";
    return {{"unity-urp.asset", a}};
}

std::vector<PasteText> unrealSnippets(const nlohmann::json& k) {
    std::string ini = "; Unreal Engine 5, from shadowtune: merge into Config/DefaultEngine.ini.\n"
                      "[/Script/Engine.RendererSettings]\nr.Shadow.Virtual.Enable=0\n\n[SystemSettings]\n";
    std::string py = "# Unreal Engine 5, from shadowtune: select the sun's DirectionalLight actor, then run this in\n"
                     "# the editor (Tools > Execute Python Script, or the Python console). Distances in cm.\n"
                     "import unreal\n\n"
                     "for actor in unreal.EditorLevelLibrary.get_selected_level_actors():\n"
                     "    light = actor.get_component_by_class(unreal.DirectionalLightComponent)\n"
                     "    if light is None:\n"
                     "        continue\n"
                     "    light.set_editor_property('mobility', unreal.ComponentMobility.MOVABLE)\n";
    for (auto it = k.begin(); it != k.end(); ++it) {
        if (it.key().rfind("r.", 0) == 0) ini += it.key() + "=" + it.value().dump() + "\n";
        else py += "    light.set_editor_property('" + snakeCase(it.key()) + "', " + it.value().dump() + ")\n";
    }
    return {{"unreal-engine.ini", ini}, {"unreal-light.py", py}};
}

}  // namespace st::xport
