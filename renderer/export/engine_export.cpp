#include "renderer/export/engine_export.h"

#include "renderer/export/export_common.h"

#include <algorithm>
#include <stdexcept>

namespace st::xport {

std::optional<Engine> parseEngine(std::string_view name) {
    for (size_t i = 0; i < kEngineNames.size(); ++i)
        if (kEngineNames[i] == name) return static_cast<Engine>(i);
    return std::nullopt;
}

std::string engineList() {
    std::string out;
    for (std::string_view n : kEngineNames) out += (out.empty() ? "" : ", ") + std::string(n);
    return out;
}

const ExportItem* EngineExport::find(std::string_view name) const {
    const auto it = std::find_if(items.begin(), items.end(), [&](const ExportItem& i) { return i.name == name; });
    return it == items.end() ? nullptr : &*it;
}

void EngineExport::add(std::string name, nlohmann::json value, Mapping m, std::string note) {
    items.push_back({std::move(name), std::move(value), m, std::move(note)});
}

EngineExport exportSettings(const Settings& s, Engine engine) {
    const PresetFacts f = presetFacts(s);
    switch (engine) {
        case Engine::Godot: return exportGodot(s, f);
        case Engine::Unity: return exportUnity(s, f);
        case Engine::Unreal: return exportUnreal(s, f);
        case Engine::Bevy: return exportBevy(s, f);
        case Engine::ThreeJs: return exportThreeJs(s, f);
        case Engine::Filament: return exportFilament(s, f);
        case Engine::Babylon: return exportBabylon(s, f);
    }
    throw std::invalid_argument("unknown engine");
}

namespace {

constexpr std::array<std::pair<Mapping, const char*>, 3> kGroups{{
    {Mapping::Exact, "exact"}, {Mapping::Approximated, "approximated"}, {Mapping::NoEquivalent, "noEquivalent"}}};

}  // namespace

std::string toText(const EngineExport& e) {
    std::string out = "# " + e.title + "\n";
    for (auto [mapping, key] : kGroups) {
        out += std::string("\n") + (mapping == Mapping::NoEquivalent ? "no equivalent" : key) + ":\n";
        const size_t before = out.size();
        for (const ExportItem& i : e.items) {
            if (i.mapping != mapping) continue;
            out += "  " + i.name + " = " + i.value.dump() + "\n      " + i.note + "\n";
        }
        if (out.size() == before) out += "  (none)\n";
    }
    return out;
}

nlohmann::ordered_json toJson(const EngineExport& e) {
    nlohmann::ordered_json j;
    j["engine"] = kEngineNames[static_cast<size_t>(e.engine)];
    j["title"] = e.title;
    for (auto [mapping, key] : kGroups) {
        nlohmann::ordered_json group = nlohmann::ordered_json::array();
        for (const ExportItem& i : e.items)
            if (i.mapping == mapping) group.push_back({{"name", i.name}, {"value", i.value}, {"note", i.note}});
        j[key] = group;
    }
    return j;
}

}  // namespace st::xport
