#include "app/cli/calibration_set.h"

#include "renderer/settings/field_table.h"
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "sweep/sweep_spec.h"

#include <algorithm>

namespace st::app {
namespace fs = std::filesystem;
namespace {

using Json = nlohmann::json;

// A preset with fields set by their table paths, as a sweep's "set" does.
struct Variant {
    const char* preset;  // relative to the presets folder
    const char* set;     // JSON object of field paths
};

// The sweeps vary count, map size and fit on the scene presets at 640x360; the builtin scenes
// and scenarios cover the filters, cascade counts up to 8 and the small end of the range.
constexpr Variant kVariants[] = {
    {"scenes/dutch-ship.json", R"({"cascades.count": 1, "cascades.mapSize": 512, "cascades.fit": "cascade"})"},
    {"scenes/fox.json", R"({"cascades.count": 2, "cascades.mapSize": 2048})"},
    {"scenes/living-room.json", R"({"cascades.count": 1, "cascades.mapSize": 1024, "cascades.fit": "cascade"})"},
    {"scenes/palm-tree-island.json", R"({"cascades.count": 2, "cascades.mapSize": 512})"},
    {"scenes/truck-town.json", R"({"cascades.count": 1, "cascades.mapSize": 1024, "cascades.fit": "scene"})"},
    {"scenes/truck-town.json", R"({"cascades.count": 3, "cascades.mapSize": 512, "cascades.lambda": 0.5})"},
    {"scenes/zdm2-sauerbraten.json", R"({"cascades.count": 4, "cascades.mapSize": 512, "cascades.fit": "cascade"})"},
    {"scenes/truck-town.json", R"({"cascades.depthBounds": "fit"})"},
    // Heavy frames of a real scene (4 x 2048, many casters per map): without them the fit, weighted
    // toward relative error over mostly small frames, priced truck-town's sweep at 60 % of its time.
    {"scenes/truck-town.json", R"({"cascades.count": 4, "cascades.mapSize": 2048, "cascades.fit": "sphere"})"},
    {"scenes/truck-town.json", R"({"cascades.count": 2, "cascades.mapSize": 2048, "cascades.fit": "cascade"})"},
    {"scenes/truck-town.json", R"({"cascades.count": 4, "cascades.mapSize": 1024, "cascades.fit": "scene"})"},
    {"scenes/fox.json", R"({"cascades.count": 4, "cascades.mapSize": 1024})"},
    {"scenes/palm-tree-island.json", R"({"cascades.count": 4, "cascades.mapSize": 2048})"},
    // The screen-space mask draws the scene again: its cost follows the scene's triangles, which the
    // builtin scenes (~150 primitives) cannot tell from a fixed cost.
    {"scenes/dutch-ship.json", R"({"filter.kind": "hard", "filter.screenSpace": "blur", "filter.screenDownsample": 2, "filter.screenBlurRadius": 4})"},
    {"scenes/zdm2-sauerbraten.json", R"({"filter.kind": "hard", "filter.screenSpace": "blur", "filter.screenDownsample": 1, "filter.screenBlurRadius": 2})"},
    {"scenes/fox.json", R"({"filter.kind": "vsm", "cascades.mapSize": 1024})"},
    {"scenes/palm-tree-island.json", R"({"filter.kind": "pcf-nxn", "filter.size": 5})"},
    {"default.json", R"({"cascades.depthBounds": "fit", "output.width": 640, "output.height": 360})"},
    {"default.json", R"({"cascades.count": 2, "cascades.mapSize": 4096})"},
    // The depth-bounds pass is fitted on its own timers (metrics::fittedOnOwnTimers): one frame per
    // scene and size of the prepass's draws, primitives and fragments, and a sample fit.
    {"default.json", R"({"cascades.depthBounds": "fit", "output.width": 320, "output.height": 180})"},
    {"default.json", R"({"cascades.fit": "samples", "output.width": 1280, "output.height": 720})"},
    {"scenes/dutch-ship.json", R"({"cascades.depthBounds": "fit"})"},
    {"scenes/fox.json", R"({"cascades.depthBounds": "fit"})"},
    {"scenes/living-room.json", R"({"cascades.depthBounds": "fit"})"},
    {"scenes/palm-tree-island.json", R"({"cascades.depthBounds": "fit", "cascades.fit": "samples"})"},
    {"scenes/zdm2-sauerbraten.json", R"({"cascades.depthBounds": "fit"})"},
    {"scenes/truck-town.json", R"({"cascades.depthBounds": "fit", "cascades.fit": "samples", "output.width": 320, "output.height": 180})"},
    {"default.json", R"({"filter.kind": "vsm", "cascades.mapSize": 512})"},
    {"default.json", R"({"filter.kind": "pcf-nxn", "filter.size": 7, "output.width": 640, "output.height": 360})"},
    {"default.json", R"({"filter.kind": "pcss", "filter.size": 7, "output.width": 640, "output.height": 360})"},
    {"default.json", R"({"filter.kind": "evsm4", "cascades.count": 3, "output.width": 640, "output.height": 360})"},
};

// " count=1 mapSize=512@640x360": the fields' last names, then the size if set.
std::string labelOf(const Json& set) {
    std::string out;
    for (const auto& [key, value] : set.items()) {
        if (key.rfind("output.", 0) == 0) continue;
        const std::size_t dot = key.rfind('.');
        out += " " + key.substr(dot == std::string::npos ? 0 : dot + 1) + "=" +
               (value.is_string() ? value.get<std::string>() : value.dump());
    }
    if (set.contains("output.width") && set.contains("output.height"))
        out += "@" + set["output.width"].dump() + "x" + set["output.height"].dump();
    return out;
}

CalibrationPoint point(const fs::path& presetDir, const fs::path& relative, const Json& set) {
    const fs::path file = presetDir / relative;
    Settings s = loadPreset(file);
    for (const auto& [key, value] : set.items()) {
        const FieldInfo* field = findField(key);
        if (!field) throw SettingsError(file.string() + ": calibration variant: unknown field " + key);
        field->set(s, readFieldValue(*field, value, key));
    }
    if (const auto problems = validate(s); !problems.empty())
        throw SettingsError(file.string() + ": calibration variant" + labelOf(set) + ": " + problems.front());
    return {file.stem().string() + labelOf(set), s, folderOf(file)};
}

std::vector<fs::path> presetsIn(const fs::path& dir, const fs::path& sub) {
    std::vector<fs::path> out;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir / sub, ec))
        if (entry.path().extension() == ".json") out.push_back(sub / entry.path().filename());
    std::sort(out.begin(), out.end());  // a fixed order: the directory's is not
    return out;
}

Json sized(int w, int h) { return Json{{"output.width", w}, {"output.height", h}}; }

void addSweepPoints(const fs::path& file, std::vector<CalibrationPoint>& out) {
    const sweep::SweepSpec spec = sweep::loadSweep(file);
    const std::vector<sweep::Point> points = sweep::expandPoints(spec);
    for (std::size_t i = kSweepFirst; i < points.size(); i += kSweepEvery)
        out.push_back({spec.name + " " + points[i].label, points[i].settings, spec.presetDir});
}

}  // namespace

std::vector<CalibrationPoint> calibrationSet(const fs::path& presetDir, std::optional<std::pair<int, int>> size,
                                             std::vector<fs::path> sweeps) {
    std::vector<CalibrationPoint> out;
    for (const fs::path& p : presetsIn(presetDir, "")) {
        out.push_back(point(presetDir, p, sized(320, 180)));
        out.push_back(point(presetDir, p, sized(640, 360)));
    }
    for (const char* sub : {"scenarios", "engines"})
        for (const fs::path& p : presetsIn(presetDir, sub)) out.push_back(point(presetDir, p, sized(320, 180)));
    for (const fs::path& p : presetsIn(presetDir, "scenes")) out.push_back(point(presetDir, p, Json::object()));
    for (const Variant& v : kVariants) out.push_back(point(presetDir, v.preset, Json::parse(v.set)));
    if (sweeps.empty())
        for (const fs::path& p : presetsIn(presetDir, "sweeps")) sweeps.push_back(presetDir / p);
    for (const fs::path& file : sweeps) addSweepPoints(file, out);
    if (size) {
        for (CalibrationPoint& p : out) {
            p.settings.output.width = size->first;
            p.settings.output.height = size->second;
        }
    }
    return out;
}

}  // namespace st::app
