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

bool hasKnobTable(Engine e) { return e == Engine::ThreeJs || e == Engine::Babylon || e == Engine::Godot; }

bool runsHere(Engine e) { return e == Engine::ThreeJs || e == Engine::Babylon; }

std::string engineName(Engine e) { return std::string(kEngineNames[std::size_t(e)]); }

std::string knobEngineList() { return "threejs, babylon, godot"; }

std::string loopEngineList() { return "threejs, babylon"; }

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

namespace {
void requireTable(Engine e) {
    if (!hasKnobTable(e))
        throw std::invalid_argument(engineName(e) + " has no knob table yet (engines with one: " + knobEngineList() + ")");
}
}  // namespace

nlohmann::json defaultKnobs(Engine e) {
    requireTable(e);
    return e == Engine::ThreeJs ? threejsDefaultKnobs() : e == Engine::Babylon ? babylonDefaultKnobs() : godotDefaultKnobs();
}

EngineKnobs knobsFor(Engine e, const Settings& s) {
    requireTable(e);
    return e == Engine::ThreeJs ? threejsKnobsFor(s) : e == Engine::Babylon ? babylonKnobsFor(s) : godotKnobsFor(s);
}

std::string knobUnit(Engine e, const std::string& knob) {
    static const std::vector<std::pair<std::string, std::string>> threejs{
        {"maxFar", "m"}, {"shadowMapSize", "texels"}, {"shadowBias", "share of lightNear..lightFar"},
        {"normalBias", "m"}, {"radius", "texels"}, {"lightNear", "m"}, {"lightFar", "m"}, {"lightMargin", "m"},
        {"breaks", "shares of maxFar"}};
    static const std::vector<std::pair<std::string, std::string>> babylon{
        {"mapSize", "texels"}, {"shadowMaxZ", "m"}, {"cascadeBlendPercentage", "share of a slice"},
        {"bias", "share of each box's depth"}, {"normalBias", "m"}};
    static const std::vector<std::pair<std::string, std::string>> godot{
        {"directional_shadow_split_1", "share of max distance"}, {"directional_shadow_split_2", "share of max distance"},
        {"directional_shadow_split_3", "share of max distance"}, {"directional_shadow_max_distance", "m"},
        {"directional_shadow_pancake_size", "m"}, {"directional_shadow_fade_start", "share of max distance"},
        {"shadow_bias", "x split depth range / 100"}, {"shadow_normal_bias", "texels"},
        {"rendering/lights_and_shadows/directional_shadow/size", "texels"}};
    const auto& table = e == Engine::ThreeJs ? threejs : e == Engine::Babylon ? babylon : godot;
    for (const auto& [name, unit] : table)
        if (name == knob) return unit;
    return "";
}

const std::vector<std::string>& engineFieldPaths(Engine e) {
    requireTable(e);
    // CSM's options, the lights' shadow properties, the renderer's map type, shadowSide.
    static const std::vector<std::string> threejs{
        "cascades.count",    "cascades.scheme",    "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize",
        "cascades.zExtensionDistance", "cascades.lightDepth", "cascades.casterFaces", "cascades.blendBand", "filter.kind",
        "filter.radius",     "bias.constant",      "bias.normalOffset"};
    // CascadedShadowGenerator's properties.
    static const std::vector<std::string> babylon{
        "cascades.count", "cascades.lambda",   "cascades.shadowDistance", "cascades.mapSize", "cascades.fit",
        "cascades.zExtension", "cascades.blendBand", "filter.kind", "filter.size", "bias.constant", "bias.normalOffset"};
    // DirectionalLight3D and the directional shadow project settings.
    static const std::vector<std::string> godot{
        "cascades.count",   "cascades.manualSplits", "cascades.shadowDistance", "cascades.mapSize",
        "cascades.zExtensionDistance", "cascades.blendBand", "cascades.fadeBand", "cascades.casterFaces", "filter.kind",
        "filter.vogelTaps", "filter.radius",         "bias.constant",           "bias.normalOffset"};
    return e == Engine::ThreeJs ? threejs : e == Engine::Babylon ? babylon : godot;
}

Settings engineModel(Engine e, const nlohmann::json& knobs, const Settings& view) {
    requireTable(e);
    try {
        return e == Engine::ThreeJs   ? threejsModel(knobs, view)
               : e == Engine::Babylon ? babylonModel(knobs, view)
                                      : godotModel(knobs, view);
    } catch (const nlohmann::json::exception& ex) {
        throw std::invalid_argument(std::string("settings: ") + ex.what());
    }
}

}  // namespace st::xport
