#include "renderer/export/engine_knobs.h"

#include "renderer/csm/cascade_plan.h"
#include "renderer/export/engine_knobs_detail.h"

#include <cmath>
#include <stdexcept>

namespace st::xport {

std::optional<Engine> parseKnobEngine(const std::string& name) {
    if (name == "three.js" || name == "three") return Engine::ThreeJs;
    if (name == "babylonjs" || name == "babylon.js") return Engine::Babylon;
    const std::optional<Engine> e = parseEngine(name);
    return e && hasKnobTable(*e) ? e : std::nullopt;
}

namespace {
const KnobTable* tableOf(Engine e) {
    switch (e) {
        case Engine::ThreeJs: return &threejsTable();
        case Engine::Babylon: return &babylonTable();
        case Engine::Godot: return &godotTable();
        case Engine::Bevy: return &bevyTable();
        case Engine::Filament: return &filamentTable();
        case Engine::Unity: return &unityTable();
        case Engine::Unreal: return &unrealTable();
        default: return nullptr;
    }
}

std::string listOf(bool (*has)(Engine)) {
    std::string out;
    for (std::size_t i = 0; i < kEngineNames.size(); ++i)
        if (has(Engine(i))) out += (out.empty() ? "" : ", ") + std::string(kEngineNames[i]);
    return out;
}
}  // namespace

bool hasKnobTable(Engine e) { return tableOf(e) != nullptr; }

bool runsHere(Engine e) { return e == Engine::ThreeJs || e == Engine::Babylon; }

std::string engineName(Engine e) { return std::string(kEngineNames[std::size_t(e)]); }

std::string knobEngineList() { return listOf(hasKnobTable); }

std::string loopEngineList() { return listOf(runsHere); }

const KnobTable& knobTable(Engine e) {
    if (const KnobTable* t = tableOf(e)) return *t;
    throw std::invalid_argument(engineName(e) + " has no knob table yet (engines with one: " + knobEngineList() + ")");
}

nlohmann::json withDefaults(const nlohmann::json& defaults, const nlohmann::json& given) {
    nlohmann::json out = defaults;
    if (given.is_null()) return out;
    if (!given.is_object()) throw std::invalid_argument("settings: expected an object of the engine's knobs");
    for (auto it = given.begin(); it != given.end(); ++it) {
        if (!defaults.contains(it.key())) throw std::invalid_argument("settings." + it.key() + ": the engine has no such knob");
        out[it.key()] = it.value();
    }
    return out;
}

float knobFloat(const nlohmann::json& knobs, const char* name, double lo, double hi) {
    const nlohmann::json& v = knobs.at(name);
    if (!v.is_number()) throw std::invalid_argument(std::string("settings.") + name + ": expected a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
        throw std::invalid_argument(std::string("settings.") + name + ": " + v.dump() + " is outside " +
                                    nlohmann::json(lo).dump() + " .. " + nlohmann::json(hi).dump());
    return static_cast<float>(d);
}

int knobInt(const nlohmann::json& knobs, const char* name, int lo, int hi) {
    const nlohmann::json& v = knobs.at(name);
    if (!v.is_number_integer()) throw std::invalid_argument(std::string("settings.") + name + ": expected a whole number");
    const long long n = v.get<long long>();
    if (n < lo || n > hi)
        throw std::invalid_argument(std::string("settings.") + name + ": " + std::to_string(n) + " is outside " +
                                    std::to_string(lo) + " .. " + std::to_string(hi));
    return static_cast<int>(n);
}

std::vector<float> presetSplits(const Settings& s) { return csm::planSplits(s, std::nullopt); }

nlohmann::json defaultKnobs(Engine e) { return knobTable(e).defaults(); }

EngineKnobs knobsFor(Engine e, const Settings& s) { return knobTable(e).knobsFor(s); }

std::string knobUnit(Engine e, const std::string& knob) {
    for (const auto& [name, unit] : knobTable(e).units)
        if (name == knob) return unit;
    return "";
}

const std::vector<std::string>& engineFieldPaths(Engine e) { return knobTable(e).fieldPaths; }

Settings engineModel(Engine e, const nlohmann::json& knobs, const Settings& view) {
    const KnobTable& t = knobTable(e);
    try {
        return t.model(knobs, view);
    } catch (const nlohmann::json::exception& ex) {
        throw std::invalid_argument(std::string("settings: ") + ex.what());
    }
}

}  // namespace st::xport
