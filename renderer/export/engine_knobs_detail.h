#pragma once
// What the engine knob tables share (engine_knobs_*.cpp): reading a knob with its range checked,
// and the split depths a preset renders with.
#include "renderer/export/engine_knobs.h"
#include "renderer/export/engine_snippets.h"
#include "renderer/settings/enum_names.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace st::xport {

// `defaults` with every key of `given` put over it; throws std::invalid_argument on a key the
// engine does not have (a typo must not fall back to a default silently).
nlohmann::json withDefaults(const nlohmann::json& defaults, const nlohmann::json& given);
// knobs[name] as a number in [lo, hi]; throws std::invalid_argument "settings.NAME: ...".
float knobFloat(const nlohmann::json& knobs, const char* name, double lo, double hi);
int knobInt(const nlohmann::json& knobs, const char* name, int lo, int hi);
// The count + 1 view depths the preset's cascades span (renderer/csm/cascade_plan.h, no samples).
std::vector<float> presetSplits(const Settings& s);

// One engine's knob table: what engine_knobs.h and engine_snippets.h answer for it. A new engine is
// a file defining its table and one line in engine_knobs.cpp's tableOf.
struct KnobTable {
    nlohmann::json (*defaults)();
    Settings (*model)(const nlohmann::json& knobs, const Settings& view);
    EngineKnobs (*knobsFor)(const Settings& s);
    std::vector<PasteText> (*snippets)(const nlohmann::json& knobs);
    std::vector<std::pair<std::string, std::string>> units;  // knob -> its unit, as the engine documents it
    std::vector<std::string> fieldPaths;                     // engineFieldPaths
};
// The engine's table; throws std::invalid_argument for an engine without one.
const KnobTable& knobTable(Engine e);
const KnobTable& threejsTable();
const KnobTable& babylonTable();
const KnobTable& godotTable();
const KnobTable& unityTable();
const KnobTable& unrealTable();
const KnobTable& bevyTable();
const KnobTable& filamentTable();

std::vector<PasteText> threejsSnippets(const nlohmann::json& knobs);
std::vector<PasteText> babylonSnippets(const nlohmann::json& knobs);
std::vector<PasteText> godotSnippets(const nlohmann::json& knobs);
std::vector<PasteText> unitySnippets(const nlohmann::json& knobs);   // unity-urp.asset
std::vector<PasteText> unrealSnippets(const nlohmann::json& knobs);  // unreal-engine.ini, unreal-light.py
std::vector<PasteText> bevySnippets(const nlohmann::json& knobs);      // bevy.rs
std::vector<PasteText> filamentSnippets(const nlohmann::json& knobs);  // filament.cpp

nlohmann::json threejsDefaultKnobs();
Settings threejsModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs threejsKnobsFor(const Settings& s);

}  // namespace st::xport

namespace st::xport {
nlohmann::json godotDefaultKnobs();
Settings godotModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs godotKnobsFor(const Settings& s);

nlohmann::json babylonDefaultKnobs();
Settings babylonModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs babylonKnobsFor(const Settings& s);

nlohmann::json unityDefaultKnobs();
Settings unityModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs unityKnobsFor(const Settings& s);

nlohmann::json unrealDefaultKnobs();
Settings unrealModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs unrealKnobsFor(const Settings& s);

nlohmann::json bevyDefaultKnobs();
Settings bevyModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs bevyKnobsFor(const Settings& s);

nlohmann::json filamentDefaultKnobs();
Settings filamentModel(const nlohmann::json& knobs, const Settings& view);
EngineKnobs filamentKnobsFor(const Settings& s);
}  // namespace st::xport
