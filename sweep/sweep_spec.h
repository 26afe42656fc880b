#pragma once
// A sweep file: a base preset, axes over field-table settings, and reference presets drawn as
// labelled points (docs/architecture.md "Speed vs accuracy"). Read strictly, like presets:
// every error names the file, the JSON path and the reason. No GL.
//
//   {
//     "version": 1,
//     "base": "../scenes/truck-town.json",           // preset path, relative to the sweep file
//     "set": {"output.width": 640, "output.height": 360},   // optional: fields set on the base
//     "axes": [
//       {"field": "cascades.count", "values": [1, 2, 3, 4]},
//       {"field": "cascades.lambda", "range": {"from": 0.5, "to": 0.95, "step": 0.15}}
//     ],
//     "references": ["../nvidia-sdk.json"]           // their cascades, filter and bias on the base
//   }
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <filesystem>
#include <string>
#include <vector>

namespace st::sweep {

inline constexpr int kSweepVersion = 1;
inline constexpr std::size_t kMaxPoints = 100000;  // a typo in a range should not queue a year of work

struct Axis {
    const FieldInfo* field = nullptr;
    std::vector<FieldValue> values;
    std::vector<std::string> valueText;  // each value as JSON text, for labels and the CSV
};

struct Reference {
    std::string name;  // the preset's file stem
    Settings settings; // the base with the reference's cascades, filter and bias
};

struct SweepSpec {
    std::filesystem::path file;
    std::string name;                 // the sweep file's stem
    std::filesystem::path presetDir;  // where the base preset is: its scene path is relative to it
    Settings base;
    std::vector<Axis> axes;
    std::vector<Reference> references;
    // What loading changed to make a reference fit the base's scene ("soft-shadows-blog: ..."):
    // the commands print these, so a reference is never quietly something else.
    std::vector<std::string> adapted;
};

// Throws SettingsError listing every problem; a sweep with any invalid point is refused whole.
SweepSpec loadSweep(const std::filesystem::path& file);

// A reference preset's method (cascades, filter, bias) on `base`'s scene, camera, light and size,
// its shadow range fitted to base's far plane where it reaches past it (then `adapted` gets a line
// saying so, naming the reference `name`). What a sweep's "references" and a tune's --budget-from do.
Settings referenceOnBase(const Settings& base, const Settings& ref, const std::string& name,
                         std::vector<std::string>& adapted);

struct Point {
    std::string id;     // stable across runs and machines: a hash of the point's settings
    std::string label;  // "cascades.count=2 cascades.fit=sphere" or the reference's name
    bool reference = false;
    std::vector<std::string> axisValues;  // per axis, JSON text ("" for references)
    Settings settings;
};

// Every combination of the axes (the last axis varies fastest), then the references.
std::vector<Point> expandPoints(const SweepSpec& spec);

// The share of `points` that shard `index` of `count` runs (index 1..count): every count-th point.
std::vector<Point> shardOf(const std::vector<Point>& points, int index, int count);

// FNV-1a 64 of the settings' JSON, as 16 hex digits.
std::string settingsId(const Settings& s);
std::string fnv1aHex(const std::string& text);  // the same hash of any text

// A field a sweep may vary: one the renderer reads and that keeps the scene.
bool isSweepable(const FieldInfo& field);

// "sphere" for the JSON text "\"sphere\"": axis values are kept as JSON, shown without quotes.
std::string unquoted(const std::string& json);

}  // namespace st::sweep
