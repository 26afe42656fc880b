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



}  // namespace st::tune
