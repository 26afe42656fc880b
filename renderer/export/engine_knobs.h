#pragma once
// The knobs of the engines shadowtune runs in the loop (`engine-check`), in each engine's own
// names and units, and the model of what the engine does with them: the Settings that reproduce
// the engine's shadows with shadowtune's renderer methods (caster faces, the diagonal box, the
// Vogel kernel, ...). The knobs go to the engine's page as JSON (engines/README.md); the model
// renders the same settings here, and engine-check holds the two against each other.
#include "renderer/settings/settings.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace st::xport {

enum class WebEngine { Threejs, Babylon };

std::optional<WebEngine> parseWebEngine(const std::string& name);
std::string webEngineName(WebEngine e);
std::string webEngineList();  // "threejs, babylon"

struct EngineKnobs {
    nlohmann::json knobs;             // the engine's own names and units
    std::vector<std::string> lacks;   // what of the preset the engine cannot take, one line each
};

// The engine's defaults, as its constructor and shadow classes set them (engines/README.md cites
// the source lines).
nlohmann::json defaultKnobs(WebEngine e);

// The nearest knobs the engine takes for `s` (missing ones keep the defaults), and what it lacks.
EngineKnobs knobsFor(WebEngine e, const Settings& s);

// What the engine does with `knobs`, as shadowtune settings: `view`'s scene, camera, light,
// output and measure settings, with the cascades, filter and bias the engine would use. Throws
// std::invalid_argument naming the knob when a value is of the wrong type or out of range.
Settings engineModel(WebEngine e, const nlohmann::json& knobs, const Settings& view);

}  // namespace st::xport
