// three.js r187: the CSM addon's options and the shadow knobs of its lights and renderer, from the one
// knob table of engine_knobs_threejs.cpp, so `export` says what engine-check runs and measures.
// Every knob is exact: the model (engineModel) renders what three.js does with it, and engine-check
// holds that model against the engine (docs/engines.md). What the preset uses and three.js lacks is
// listed as having no equivalent.
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

namespace st::xport {
namespace {

using M = Mapping;

// The knob's name in a three.js program and what it is.
struct KnobText {
    const char* key;
    const char* name;
    const char* note;
};

constexpr KnobText kThreejsKnobs[] = {
    {"cascades", "cascades", "new CSM({cascades}): cascades.count"},
    {"mode", "mode", "practical is lerp(uniform, logarithmic, 0.5); custom pushes the breaks below"},
    {"breaks", "breaks", "custom mode: split depth / far, what customSplitsCallback pushes (last 1)"},
    {"maxFar", "maxFar", "shadows end at min(camera.far, maxFar): cascades.shadowDistance"},
    {"shadowMapSize", "shadowMapSize", "texels per side of each cascade light's map"},
    {"shadowBias", "shadowBias", "added to the receiver's depth normalised over lightNear..lightFar: -bias.constant / lightDepth"},
    {"normalBias", "light.shadow.normalBias", "metres along the receiver's normal (set on each csm.lights[i].shadow)"},
    {"radius", "light.shadow.radius", "texels of the 5-tap Vogel disc (0: one 2x2 compare)"},
    {"lightNear", "lightNear", "the light camera's near plane beyond lightMargin"},
    {"lightFar", "lightFar", "lightFar - lightNear is the light box's depth (cascades.lightDepth)"},
    {"lightMargin", "lightMargin", "the light sits this far beyond the slice toward the sun (z extension + lightNear)"},
    {"fade", "csm.fade", "set after the constructor (it ignores data.fade); its margin grows with depth"},
    {"shadowMapType", "renderer.shadowMap.type", "PCFShadowMap (Vogel PCF), BasicShadowMap or VSMShadowMap"},
    {"shadowSide", "material.shadowSide", "null: single-sided materials cast their back faces (WebGLShadowMap.js)"},
};

}  // namespace

EngineExport exportThreeJs(const Settings& s, const PresetFacts&) {
    EngineExport e{Engine::ThreeJs, "three.js r187: CSM addon (examples/jsm/csm/CSM.js) and WebGLRenderer shadows", {}};
    const EngineKnobs k = threejsKnobsFor(s);
    for (const KnobText& t : kThreejsKnobs) {
        const nlohmann::json& v = k.knobs.at(t.key);
        if (std::string(t.key) == "breaks" && v.is_null()) continue;
        e.add(t.name, v, M::Exact, t.note);
    }
    addLacks(e, k.lacks);
    addKnobsWithoutSetting(
        e, s,
        {.cameraRelative = "CSM.js fits its light boxes in world space, in float32",
         .fitFovY = "CSM.js fits the camera's current frustum (updateFrustums() after a FOV change)",
         .contact = "three.js has no screen-space contact shadows"});
    addShadowtuneOnly(e, s, false);
    return e;
}

}  // namespace st::xport
