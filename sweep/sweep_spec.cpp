#include "sweep/sweep_spec.h"

#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>

namespace st::sweep {
namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// Problems found so far, each "<file>: <json path>: <reason>".
struct Problems {
    std::string file;
    std::vector<std::string> list;
    void add(const std::string& path, const std::string& reason) { list.push_back(file + ": " + path + ": " + reason); }
    void addAll(const std::string& prefix, const SettingsError& e) {
        for (const std::string& m : e.messages()) list.push_back(file + ": " + prefix + m);
    }
};

std::string typeName(const Json& v) { return v.type_name(); }

void checkTopKeys(const Json& root, Problems& p) {
    static const std::set<std::string> known = {"$schema", "version", "notes", "base", "set", "axes", "references"};
    for (const auto& [key, value] : root.items())
        if (!known.count(key))
            p.add(key, "unknown key, expected one of: version, notes, base, set, axes, references");
}

fs::path relativeTo(const fs::path& sweepFile, const std::string& path) {
    const fs::path p(path);
    return p.is_absolute() ? p : folderOf(sweepFile) / p;
}

std::optional<Settings> readPreset(const fs::path& file, const std::string& jsonPath, Problems& p) {
    try {
        return loadPreset(file);
    } catch (const SettingsError& e) {
        p.addAll(jsonPath + ": ", e);
    }
    return std::nullopt;
}

const FieldInfo* sweepableField(const Json& name, const std::string& path, Problems& p) {
    if (!name.is_string()) {
        p.add(path, "expected a field path (string), got " + typeName(name));
        return nullptr;
    }
    const FieldInfo* field = findField(name.get<std::string>());
    if (!field) p.add(path, "unknown field \"" + name.get<std::string>() + "\" (see schema/preset.schema.json)");
    else if (!isSweepable(*field))
        p.add(path, "\"" + std::string(field->path) + "\" cannot be swept: a sweep keeps one scene and scores frames");
    return field && isSweepable(*field) ? field : nullptr;
}

void readSet(const Json& root, Settings& base, Problems& p) {
    const auto it = root.find("set");
    if (it == root.end()) return;
    if (!it->is_object()) return p.add("set", "expected an object of field paths, got " + typeName(*it));
    for (const auto& [key, value] : it->items()) {
        const FieldInfo* field = findField(key);
        if (!field) {
            p.add("set." + key, "unknown field (see schema/preset.schema.json)");
            continue;
        }
        try {
            field->set(base, readFieldValue(*field, value, "set." + key));
        } catch (const SettingsError& e) {
            p.addAll("", e);
        }
    }
}

// A value count too large for an integer, as text: "250000", "1e+30", "more than 1e+308".
std::string countText(double count) {
    if (!std::isfinite(count)) return "more than 1e+308";
    char text[32];
    std::snprintf(text, sizeof text, count < 1e15 ? "%.0f" : "%.3g", count);
    return text;
}

// from, from + step, ... up to `to` (inclusive within a millionth of a step).
std::optional<std::vector<Json>> rangeValues(const FieldInfo& field, const Json& range, const std::string& path,
                                             Problems& p) {
    if (field.kind != FieldKind::Float && field.kind != FieldKind::Int) {
        p.add(path, "a range needs a number field; " + std::string(field.path) + " is " +
                        std::string(fieldKindName(field.kind)) + ": list its values");
        return std::nullopt;
    }
    for (const char* key : {"from", "to", "step"})
        if (!range.is_object() || !range.contains(key) || !range[key].is_number()) {
            p.add(path + "." + key, "expected a number");
            return std::nullopt;
        }
    const double from = range["from"], to = range["to"], step = range["step"];
    if (!(step > 0.0) || !(to >= from)) {
        p.add(path, "needs step > 0 and to >= from");
        return std::nullopt;
    }
    // In double and checked before any conversion: a huge count (or an infinite one, when
    // (to - from) / step overflows) does not fit an integer.
    const double count = std::floor((to - from) / step + 1e-6) + 1.0;
    if (!(count <= double(kMaxPoints))) {
        p.add(path, "gives " + countText(count) + " values, more than the " + std::to_string(kMaxPoints) +
                        " a sweep may have");
        return std::nullopt;
    }
    std::vector<Json> values;
    for (int i = 0; i < int(count); ++i) {
        const double v = from + i * step;
        if (field.kind == FieldKind::Int) values.emplace_back(static_cast<long long>(std::llround(v)));
        else values.emplace_back(static_cast<float>(std::round(v * 1e6) / 1e6));
    }
    return values;
}

std::optional<Axis> readAxis(const Json& a, const std::string& path, Problems& p) {
    if (!a.is_object()) {
        p.add(path, "expected an object {\"field\", \"values\" or \"range\"}, got " + typeName(a));
        return std::nullopt;
    }
    for (const auto& [key, value] : a.items())
        if (key != "field" && key != "values" && key != "range") p.add(path + "." + key, "unknown key, expected field, values, range");
    const FieldInfo* field = sweepableField(a.contains("field") ? a["field"] : Json(), path + ".field", p);
    if (!field) return std::nullopt;
    std::vector<Json> raw;
    std::string valuesPath = path + ".values";
    if (a.contains("values") == a.contains("range")) {
        p.add(path, "needs exactly one of \"values\" (a list) or \"range\" ({from, to, step})");
        return std::nullopt;
    }
    if (a.contains("range")) {
        auto r = rangeValues(*field, a["range"], path + ".range", p);
        if (!r) return std::nullopt;
        raw = *r;
        valuesPath = path + ".range";
    } else if (!a["values"].is_array() || a["values"].empty()) {
        p.add(valuesPath, "expected a non-empty list of values");
        return std::nullopt;
    } else {
        raw.assign(a["values"].begin(), a["values"].end());
    }
    Axis axis{field, {}, {}};
    std::set<std::string> seen;
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const std::string at = valuesPath + "[" + std::to_string(i) + "]";
        try {
            FieldValue v = readFieldValue(*field, raw[i], at);
            std::string text = fieldValueToJson(*field, v).dump();
            if (!seen.insert(text).second) p.add(at, "repeats the value " + text);
            axis.values.push_back(std::move(v));
            axis.valueText.push_back(std::move(text));
        } catch (const SettingsError& e) {
            p.addAll("", e);
        }
    }
    return axis.values.size() == raw.size() ? std::optional<Axis>(std::move(axis)) : std::nullopt;
}

void readAxes(const Json& root, SweepSpec& spec, Problems& p) {
    const auto it = root.find("axes");
    if (it == root.end()) return;
    if (!it->is_array()) return p.add("axes", "expected a list of axes, got " + typeName(*it));
    std::set<std::string_view> fields;
    for (std::size_t i = 0; i < it->size(); ++i) {
        const std::string path = "axes[" + std::to_string(i) + "]";
        auto axis = readAxis((*it)[i], path, p);
        if (!axis) continue;
        if (!fields.insert(axis->field->path).second) p.add(path + ".field", "sweeps " + std::string(axis->field->path) + " twice");
        spec.axes.push_back(std::move(*axis));
    }
}

std::string metres(float m) {
    char text[32];
    std::snprintf(text, sizeof text, "%g m", double(m));
    return text;
}

// A reference's own method (cascades, filter, bias) on the base's scene, camera, light and size.
// Its distances were chosen for its own camera: when its shadow range (shadow distance, or its far
// plane) reaches past the base's far plane, the range becomes the base's far plane and manual
// splits keep their proportions of it. Anything else is kept as the reference has it.
Settings onBase(const Settings& base, const Settings& ref, const std::string& name, std::vector<std::string>& adapted) {
    Settings s = base;
    s.cascades = ref.cascades;
    s.filter = ref.filter;
    s.bias = ref.bias;
    const float far = base.camera.farPlane;
    const float refEnd = ref.cascades.shadowDistance > 0.0f ? ref.cascades.shadowDistance : ref.camera.farPlane;
    const auto& splits = ref.cascades.manualSplits;
    const bool outside = ref.cascades.shadowDistance > far ||
                         std::any_of(splits.begin(), splits.end(), [far](float d) { return d >= far; });
    if (!outside || refEnd <= far) return s;
    const float scale = far / refEnd;
    std::string what = name + ": shadow range " + metres(refEnd) + " is past this scene's far plane (" + metres(far) +
                       "); it ends at the far plane";
    s.cascades.shadowDistance = 0.0f;
    if (!s.cascades.manualSplits.empty()) {
        what += ", and the manual splits keep their proportions:";
        for (float& split : s.cascades.manualSplits) {
            what += " " + metres(split) + " ->";
            split *= scale;
            what += " " + metres(split);
        }
    }
    adapted.push_back(what);
    return s;
}

void readReferences(const Json& root, SweepSpec& spec, Problems& p) {
    const auto it = root.find("references");
    if (it == root.end()) return;
    if (!it->is_array()) return p.add("references", "expected a list of preset paths, got " + typeName(*it));
    for (std::size_t i = 0; i < it->size(); ++i) {
        const std::string path = "references[" + std::to_string(i) + "]";
        if (!(*it)[i].is_string()) {
            p.add(path, "expected a preset path (string), got " + typeName((*it)[i]));
            continue;
        }
        const fs::path file = relativeTo(spec.file, (*it)[i].get<std::string>());
        if (auto ref = readPreset(file, path, p)) spec.references.push_back(
                {file.stem().string(), onBase(spec.base, *ref, file.stem().string(), spec.adapted)});
    }
}

// "count" for cascades.count, unless another axis ends the same way: labels stay short on charts.
std::vector<std::string> shortNames(const std::vector<Axis>& axes) {
    std::vector<std::string> names;
    for (const Axis& a : axes) {
        const std::string_view path = a.field->path;
        names.emplace_back(path.substr(path.rfind('.') + 1));
    }
    for (std::size_t i = 0; i < names.size(); ++i)
        if (std::count(names.begin(), names.end(), names[i]) > 1) names[i] = std::string(axes[i].field->path);
    return names;
}

std::size_t gridSize(const SweepSpec& spec) {
    std::size_t n = 1;
    for (const Axis& a : spec.axes) n = std::min(kMaxPoints + 1, n * a.values.size());
    return n;
}

void checkPoints(const SweepSpec& spec, Problems& p) {
    if (spec.axes.empty() && spec.references.empty()) p.add("axes", "a sweep needs at least one axis or reference");
    if (gridSize(spec) > kMaxPoints) return p.add("axes", "more than " + std::to_string(kMaxPoints) + " combinations");
    std::size_t bad = 0;
    for (const Point& point : expandPoints(spec)) {
        for (const std::string& problem : validate(point.settings)) {
            if (++bad <= 10) p.add(point.reference ? "references" : "axes", "point " + point.label + ": " + problem);
        }
    }
    if (bad > 10) p.add("axes", "... and " + std::to_string(bad - 10) + " more invalid points");
}

}  // namespace

Settings referenceOnBase(const Settings& base, const Settings& ref, const std::string& name,
                         std::vector<std::string>& adapted) {
    return onBase(base, ref, name, adapted);
}

SweepSpec loadSweep(const fs::path& file) {
    SweepSpec spec;
    spec.file = file;
    spec.name = file.stem().string();
    const Json root = loadJsonFile(file, "sweep");
    Problems p{file.string(), {}};
    if (!root.is_object()) throw SettingsError(file.string() + ": (top level): expected an object, got " + typeName(root));
    checkTopKeys(root, p);
    if (!root.contains("version") || root["version"] != kSweepVersion)
        p.add("version", "must be " + std::to_string(kSweepVersion));
    if (!root.contains("base") || !root["base"].is_string()) {
        p.add("base", "expected the path of the base preset (string)");
        throw SettingsError(p.list);
    }
    const fs::path baseFile = relativeTo(file, root["base"].get<std::string>());
    auto base = readPreset(baseFile, "base", p);
    if (!base) throw SettingsError(p.list);
    spec.base = *base;
    spec.presetDir = folderOf(baseFile);
    readSet(root, spec.base, p);
    readAxes(root, spec, p);
    readReferences(root, spec, p);
    if (p.list.empty()) checkPoints(spec, p);
    if (!p.list.empty()) throw SettingsError(p.list);
    return spec;
}

std::string fnv1aHex(const std::string& text) {
    std::uint64_t h = 1469598103934665603ull;
    for (const unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
}

std::string settingsId(const Settings& s) { return fnv1aHex(toJson(s).dump()); }

bool isSweepable(const FieldInfo& field) {
    return field.change != ChangeClass::Scene && field.change != ChangeClass::None;
}

std::string unquoted(const std::string& json) {
    return json.size() >= 2 && json.front() == '"' && json.back() == '"' ? json.substr(1, json.size() - 2) : json;
}

std::vector<Point> expandPoints(const SweepSpec& spec) {
    std::vector<Point> points;
    const std::vector<std::string> names = shortNames(spec.axes);
    std::vector<std::size_t> at(spec.axes.size(), 0);
    const std::size_t total = spec.axes.empty() ? 0 : gridSize(spec);
    for (std::size_t n = 0; n < total; ++n) {
        Point point{{}, {}, false, {}, spec.base};
        for (std::size_t a = 0; a < spec.axes.size(); ++a) {
            const Axis& axis = spec.axes[a];
            axis.field->set(point.settings, axis.values[at[a]]);
            point.axisValues.push_back(axis.valueText[at[a]]);
            point.label += (a ? " " : "") + names[a] + "=" + unquoted(axis.valueText[at[a]]);
        }
        point.id = settingsId(point.settings);
        points.push_back(std::move(point));
        for (std::size_t a = spec.axes.size(); a-- > 0;) {  // odometer: the last axis fastest
            if (++at[a] < spec.axes[a].values.size()) break;
            at[a] = 0;
        }
    }
    for (const Reference& ref : spec.references)
        points.push_back({"ref-" + settingsId(ref.settings), ref.name, true, std::vector<std::string>(spec.axes.size()),
                          ref.settings});
    return points;
}

std::vector<Point> shardOf(const std::vector<Point>& points, int index, int count) {
    std::vector<Point> mine;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (int(i % std::size_t(count)) == index - 1) mine.push_back(points[i]);
    return mine;
}

}  // namespace st::sweep
