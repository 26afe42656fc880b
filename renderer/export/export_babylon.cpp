// Babylon.js 9.28: CascadedShadowGenerator's properties, from the one knob table of
// engine_knobs_babylon.cpp, so `export` says what engine-check runs and measures. Every knob is
// exact (its model is held against the engine, docs/engines.md); what the preset uses and Babylon
// lacks is listed as having no equivalent.
#include "renderer/export/engine_knobs_detail.h"
#include "renderer/export/export_common.h"

namespace st::xport {
namespace {

struct KnobText {
    const char* key;
    const char* note;
};

constexpr KnobText kBabylonKnobs[] = {
    {"mapSize", "new CascadedShadowGenerator(mapSize, light): texels per side of every cascade layer"},
    {"numCascades", "2 to 4"},
    {"lambda", "between uniform (0) and logarithmic (1) splits"},
    {"shadowMaxZ", "shadows end here (null: the camera's maxZ)"},
    {"stabilizeCascades", "a bounding sphere per slice instead of its tight box"},
    {"depthClamp", "casters toward the sun clamped onto the box (pancaking); the box cut to the casters' bounds"},
    {"cascadeBlendPercentage", "share of each slice blended into the next"},
    {"bias", "added to the casters' depth, a share of each box's depth (1.5x with depthClamp)"},
    {"normalBias", "metres casters move into their surface, times sin(theta)"},
    {"filter", "usePercentageCloserFiltering (PCF), PCSS or none"},
    {"filteringQuality", "PCF low: one 2x2 compare, medium: 3x3 tent, high: 5x5 tent"},
    {"darkness", "0: shadows at full strength"},
};

}  // namespace

EngineExport exportBabylon(const Settings& s, const PresetFacts&) {
    EngineExport e{Engine::Babylon, "Babylon.js 9.28: CascadedShadowGenerator (@babylonjs/core Lights/Shadows)", {}};
    const EngineKnobs k = babylonKnobsFor(s);
    for (const KnobText& t : kBabylonKnobs) e.add(t.key, k.knobs.at(t.key), Mapping::Exact, t.note);
    addLacks(e, k.lacks);
    addKnobsWithoutSetting(e, s,
                           {.cameraRelative = "Babylon fits its light boxes in world space, in float32 matrices",
                            .fitFovY = "Babylon fits the camera's current frustum",
                            .contact = "Babylon has no screen-space contact shadows"});
    addShadowtuneOnly(e, s, false);
    return e;
}

}  // namespace st::xport
