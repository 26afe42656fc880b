#pragma once
// The engines' knob tables: each engine's shadow knobs in its own names and units, and the model
// of what the engine does with them: the Settings that reproduce the engine's shadows with
// shadowtune's renderer methods (caster faces, the diagonal box, the Vogel kernel, ...). The tuner
// searches them (`tune --engine`); for the engines that run here (`engine-check`: three.js and
// Babylon.js) the knobs go to the engine's page as JSON (engines/README.md) and the check holds the
// engine against the model. Godot's table is a model read from its source, not measured.
#include "renderer/export/engine_export.h"
#include "renderer/settings/settings.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace st::xport {

// The engines with a knob table (three.js, Babylon.js, Godot), by name ("three.js" and "babylon.js" too).
std::optional<Engine> parseKnobEngine(const std::string& name);
bool hasKnobTable(Engine e);
// The engines `engine-check` runs here, in headless Chromium: three.js and Babylon.js.
bool runsHere(Engine e);
std::string engineName(Engine e);  // "threejs", "babylon", "godot", ...
std::string knobEngineList();      // "godot, threejs, babylon", in kEngineNames order
std::string loopEngineList();      // "threejs, babylon"

struct EngineKnobs {
    nlohmann::json knobs;             // the engine's own names and units
    std::vector<std::string> lacks;   // what of the preset the engine cannot take, one line each
};

// The engine's defaults, as its constructor and shadow classes set them (engines/README.md and
// docs/engines.md cite the source lines). These three throw std::invalid_argument for an engine
// without a knob table.
nlohmann::json defaultKnobs(Engine e);

// The nearest knobs the engine takes for `s` (missing ones keep the defaults), and what it lacks.
EngineKnobs knobsFor(Engine e, const Settings& s);

// A knob's unit as the engine's documentation gives it ("m", "texels", "share of the light's
// depth", ...), "" for a count, a choice or a flag.
std::string knobUnit(Engine e, const std::string& knob);

// The shadow settings (cascades.*, filter.*, bias.*) the engine's knobs set; every other one of
// those groups is fixed by the engine (its model sets it) or has no knob there. The editor greys
// the rest; the tuner's space for the engine (tune/tune_engine.h) moves these only.
const std::vector<std::string>& engineFieldPaths(Engine e);  // built once per engine

// What the engine does with `knobs`, as shadowtune settings: `view`'s scene, camera, light,
// output and measure settings, with the cascades, filter and bias the engine would use. Throws
// std::invalid_argument naming the knob when a value is of the wrong type or out of range.
Settings engineModel(Engine e, const nlohmann::json& knobs, const Settings& view);

}  // namespace st::xport
