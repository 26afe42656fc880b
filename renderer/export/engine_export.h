#pragma once
// The nearest settings of a shadowtune preset in another engine's own terms (issue 10, item 4).
// Pure: Settings in, a list of named values out; no GL, no files. Each value says whether it maps
// exactly, is approximated (and how), or has no equivalent, with the engine's source next to it.
#include "renderer/settings/settings.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace st::xport {

enum class Engine { Godot, Unity, Unreal, Bevy, ThreeJs, Filament, Babylon };
inline constexpr std::array<std::string_view, 7> kEngineNames{"godot", "unity", "unreal", "bevy", "threejs",
                                                              "filament", "babylon"};

std::optional<Engine> parseEngine(std::string_view name);
std::string engineList();  // "godot, unity, unreal, bevy, threejs, filament, babylon"

enum class Mapping { Exact, Approximated, NoEquivalent };

struct ExportItem {
    std::string name;       // the engine's own name: "directional_shadow_split_1", "r.Shadow.MaxCSMResolution"
    nlohmann::json value;   // number, bool, string or array, in the engine's units
    Mapping mapping = Mapping::Exact;
    std::string note;       // how it was derived, or why it cannot be
};

struct EngineExport {
    Engine engine = Engine::Godot;
    std::string title;      // "Godot 4: DirectionalLight3D + ProjectSettings"
    std::vector<ExportItem> items;

    const ExportItem* find(std::string_view name) const;
    void add(std::string name, nlohmann::json value, Mapping m, std::string note);
};

// Throws std::invalid_argument (from the cascade math) for settings that do not validate.
EngineExport exportSettings(const Settings& s, Engine engine);

std::string toText(const EngineExport& e);     // three groups: exact, approximated, no equivalent
nlohmann::ordered_json toJson(const EngineExport& e);

}  // namespace st::xport
