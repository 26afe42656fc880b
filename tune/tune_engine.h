#pragma once
// `tune --engine NAME` (issue "Tune for your engine"): the search space is the engine's own knobs
// and nothing else (renderer/export/engine_knobs.h's table and model), every start is projected
// onto what the engine can take, and the tuned settings come out as the engine's knobs and as
// paste-ready text. Pure settings code, no GL.
#include "renderer/export/engine_knobs.h"
#include "tune/tune_space.h"

#include <string>
#include <vector>

namespace st::tune {

// `s` as the engine renders it: its knobs (knobsFor) through the engine's model (engineModel).
Settings ontoEngine(xport::Engine e, const Settings& s);

// The dimensions the engine's knobs span, with candidates in the engine's units (three.js: cascades,
// split mode or custom breaks, maxFar, shadowMapSize, lightMargin, shadowBias, normalBias in metres,
// PCF or basic, radius, shadowSide; Babylon.js: numCascades, lambda, shadowMaxZ, mapSize,
// cascadeBlendPercentage, filteringQuality, bias, normalBias; stabilizeCascades and depthClamp
// stay at their defaults, whose model is exact, where their other values are approximate).
Space engineSpace(xport::Engine e, const Settings& base);

// The knobs as the engine's own source text, to paste, one file each: three.js (`threejs.js`: the
// CSM addon and its lights), Babylon.js (`babylon.js`: the CascadedShadowGenerator's properties),
// Godot (`godot-light.tscn`: the DirectionalLight3D's property lines; `godot-project.godot`: the
// [rendering] settings of project.godot).
struct PasteText {
    std::string file;
    std::string text;
};
std::vector<PasteText> engineSnippets(xport::Engine e, const nlohmann::json& knobs);

}  // namespace st::tune
