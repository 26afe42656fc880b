#include "renderer/export/engine_snippets.h"

#include "renderer/export/engine_knobs_detail.h"

#include <string>

namespace st::xport {
namespace {

std::string threejsSnippet(const nlohmann::json& k) {
    std::string breaks = k.at("breaks").is_null() ? "" : k.at("breaks").dump();
    std::string js;
    js += "// three.js r187, from shadowtune. Paste after creating the renderer, camera and scene.\n";
    js += "import { CSM } from 'three/addons/csm/CSM.js';\n";
    js += "renderer.shadowMap.enabled = true;\n";
    js += "renderer.shadowMap.type = THREE." + k.at("shadowMapType").get<std::string>() + ";\n";
    js += "const csm = new CSM({\n";
    js += "  camera, parent: scene, lightDirection: sunDirection,\n";
    js += "  cascades: " + k.at("cascades").dump() + ", mode: " + k.at("mode").dump() + ", maxFar: " + k.at("maxFar").dump() +
          ",\n";
    js += "  shadowMapSize: " + k.at("shadowMapSize").dump() + ", shadowBias: " + k.at("shadowBias").dump() + ",\n";
    js += "  lightNear: " + k.at("lightNear").dump() + ", lightFar: " + k.at("lightFar").dump() +
          ", lightMargin: " + k.at("lightMargin").dump() + ",\n";
    if (!breaks.empty())
        js += "  customSplitsCallback: (cascades, near, far, breaks) => breaks.push(..." + breaks + "),\n";
    js += "});\n";
    js += "csm.fade = " + k.at("fade").dump() + ";  // set after the constructor, which ignores data.fade\n";
    js += "for (const light of csm.lights) {\n";
    js += "  light.shadow.normalBias = " + k.at("normalBias").dump() + ";\n";
    js += "  light.shadow.radius = " + k.at("radius").dump() + ";\n";
    js += "}\n";
    if (!k.at("shadowSide").is_null()) {
        const std::string side = k.at("shadowSide").get<std::string>();
        const std::string name = side == "front" ? "FrontSide" : side == "back" ? "BackSide" : "DoubleSide";
        js += "scene.traverse((o) => { if (o.material) o.material.shadowSide = THREE." + name + "; });\n";
    }
    js += "scene.traverse((o) => { if (o.material) csm.setupMaterial(o.material); });\n";
    js += "csm.updateFrustums();  // and csm.update() every frame before rendering\n";
    return js;
}

std::string babylonSnippet(const nlohmann::json& k) {
    std::string js;
    js += "// Babylon.js 9, from shadowtune. `light` is the sun's DirectionalLight.\n";
    js += "const csm = new BABYLON.CascadedShadowGenerator(" + k.at("mapSize").dump() + ", light);\n";
    js += "csm.numCascades = " + k.at("numCascades").dump() + ";\n";
    js += "csm.lambda = " + k.at("lambda").dump() + ";\n";
    if (!k.at("shadowMaxZ").is_null()) js += "csm.shadowMaxZ = " + k.at("shadowMaxZ").dump() + ";\n";
    js += "csm.stabilizeCascades = " + k.at("stabilizeCascades").dump() + ";\n";
    js += "csm.depthClamp = " + k.at("depthClamp").dump() + ";\n";
    js += "csm.cascadeBlendPercentage = " + k.at("cascadeBlendPercentage").dump() + ";\n";
    js += "csm.bias = " + k.at("bias").dump() + ";\n";
    js += "csm.normalBias = " + k.at("normalBias").dump() + ";\n";
    const std::string filter = k.at("filter").get<std::string>();
    if (filter == "none") js += "csm.usePercentageCloserFiltering = false;\n";
    else if (filter == "PCSS") js += "csm.useContactHardeningShadow = true;\n";
    else js += "csm.usePercentageCloserFiltering = true;\n";
    const std::string q = k.at("filteringQuality").get<std::string>();
    js += "csm.filteringQuality = BABYLON.ShadowGenerator.QUALITY_" + std::string(q == "low" ? "LOW" : q == "medium" ? "MEDIUM" : "HIGH") + ";\n";
    js += "for (const mesh of scene.meshes) { mesh.receiveShadows = true; csm.addShadowCaster(mesh); }\n";
    return js;
}

}  // namespace

std::vector<PasteText> threejsSnippets(const nlohmann::json& k) { return {{"threejs.js", threejsSnippet(k)}}; }
std::vector<PasteText> babylonSnippets(const nlohmann::json& k) { return {{"babylon.js", babylonSnippet(k)}}; }

// Godot 4: the light's property lines as a .tscn holds them, and project.godot's [rendering] lines.
std::vector<PasteText> godotSnippets(const nlohmann::json& k) {
    std::string light = "; Godot 4, from shadowtune. The sun's DirectionalLight3D properties: paste under\n"
                        "; its [node ...] line in the .tscn (or set them in the inspector).\n"
                        "shadow_enabled = true\n";
    std::string project = "; Godot 4, from shadowtune. Merge into project.godot.\n[rendering]\n\n";
    const std::string prefix = "rendering/";
    for (auto it = k.begin(); it != k.end(); ++it) {
        if (it.key().rfind(prefix, 0) == 0) project += it.key().substr(prefix.size()) + "=" + it.value().dump() + "\n";
        else light += it.key() + " = " + it.value().dump() + "\n";
    }
    return {{"godot-light.tscn", light}, {"godot-project.godot", project}};
}

std::vector<PasteText> engineSnippets(Engine e, const nlohmann::json& knobs) { return knobTable(e).snippets(knobs); }

}  // namespace st::xport
