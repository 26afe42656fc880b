#pragma once
// Settings <-> JSON presets, driven by the field table. Reading is strict: unknown keys, wrong
// types, non-finite numbers and broken rules are all reported, each as
// "<source>: <json path>: <reason>", e.g. "presets/bad.json: cascades.count: must be in 1..8, got 12".
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace st {

inline constexpr int kPresetVersion = 1;  // the "version" every preset must carry

// Everything that can go wrong reading, validating or writing a preset. what() is messages()
// joined by newlines; every problem found is listed, not just the first.
class SettingsError : public std::runtime_error {
public:
    explicit SettingsError(std::vector<std::string> messages);
    explicit SettingsError(const std::string& message);
    const std::vector<std::string>& messages() const noexcept { return messages_; }

private:
    std::vector<std::string> messages_;
};

// "version": 1 and every field, keys in table order. Does not validate.
nlohmann::ordered_json toOrderedJson(const Settings& s);
nlohmann::json toJson(const Settings& s);  // same content, keys sorted

// The JSON form of one field value (floats written with their shortest text, enums by name).
nlohmann::ordered_json fieldValueToJson(const FieldInfo& field, const FieldValue& value);

// Reads a preset. "version" (== kPresetVersion) is required; any other missing field takes its
// value from Settings{}. `sourceName` (usually the file path) starts every error message.
// Throws SettingsError listing every problem.
Settings fromJson(const nlohmann::json& json, const std::string& sourceName);

// Reads and validates a preset file. Invalid JSON is reported as "<file>:<line>:<col>: invalid
// JSON: <reason>"; a missing file, a directory or an unreadable file get their own message.
// Relative scene paths are left as written (relative to the preset). Throws SettingsError.
Settings loadPreset(const std::filesystem::path& file);

// A JSON file of the project's (a preset, a sweep) read with a preset's limits (16 MiB, not a
// folder) and parsed with "<file>:<line>:<col>: invalid JSON: ..." errors. `kind` names it in
// messages ("preset", "sweep"). Throws SettingsError.
nlohmann::json loadJsonFile(const std::filesystem::path& file, const std::string& kind = "preset");

// One value of `field` read exactly as a preset would read it (types, range, enum names);
// messages name `path`, e.g. "axes[1].values[3]". Throws SettingsError listing the problems.
FieldValue readFieldValue(const FieldInfo& field, const nlohmann::json& value, const std::string& path);

// Validates `s` (a preset that would not load is never written), then writes pretty JSON
// (2-space indent, table order) to "<file>.tmp-<pid>", flushes it to disk and renames it over
// `file`, so readers see the old or the new preset, never half of one. On failure the temporary
// file is removed and SettingsError says what failed (naming `file`, not the temporary one).
// `schemaRef`: written first as "$schema" (editors find the JSON Schema through it) unless empty.
void savePresetAtomic(const Settings& s, const std::filesystem::path& file, const std::string& schemaRef = "");

}  // namespace st
