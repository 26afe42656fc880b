// JSON -> Settings: strict reading. Structure (version, unknown keys, types) is checked here;
// ranges and cross-field rules come from validation.cpp so they are written once.
#include "renderer/settings/enum_names.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace st {
namespace {

using Json = nlohmann::json;
using Issues = std::vector<SettingsIssue>;

// One level of a value, for messages: nested arrays and objects as [...] and {...}. Never recursive:
// a hostile preset can nest thousands deep, and dump() would recurse that far (found by fuzzing:
// tests/fuzz/crashes/preset/deep-nesting-describe-stack-overflow.json).
std::string shallowText(const Json& value) {
    if (value.is_array()) return value.empty() ? "[]" : "[...]";
    if (value.is_object()) return value.empty() ? "{}" : "{...}";
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string containerText(const Json& value) {
    const bool array = value.is_array();
    std::string text = array ? "[" : "{";
    for (auto it = value.begin(); it != value.end() && text.size() <= 40; ++it) {
        if (text.size() > 1) text += ",";
        if (!array) text += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace) + ":";
        text += shallowText(it.value());
    }
    return text + (array ? "]" : "}");
}

// A JSON value for "got ..." in messages: its text, cut short, with its type where that helps.
std::string describe(const Json& value) {
    std::string text = value.is_structured() ? containerText(value) : shallowText(value);
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    if (value.is_string()) return "string " + text;
    if (value.is_array()) return "array " + text;
    if (value.is_object()) return "object " + text;
    return text;
}

std::string join(const std::string& prefix, std::string_view key) {
    return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

// The keys allowed directly under `prefix` ("" = top level), in table order.
std::vector<std::string> childKeys(const std::string& prefix) {
    std::vector<std::string> keys;
    if (prefix.empty()) keys.emplace_back("version");
    for (const FieldInfo& field : fieldTable()) {
        std::string_view rest = field.path;
        if (!prefix.empty()) {
            if (!rest.starts_with(prefix + ".")) continue;
            rest.remove_prefix(prefix.size() + 1);
        }
        std::string key(rest.substr(0, rest.find('.')));
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(std::move(key));
    }
    return keys;
}

std::string listKeys(const std::vector<std::string>& keys) {
    std::string text;
    for (const auto& key : keys) text += (text.empty() ? "" : ", ") + key;
    return text;
}

// Reports unknown keys and groups ("camera") that are not objects, at every level.
void checkKeys(const Json& object, const std::string& prefix, Issues& issues) {
    for (const auto& [key, value] : object.items()) {
        const std::string path = join(prefix, key);
        const bool dotted = key.find('.') != std::string::npos;  // "camera.fovY" is not camera/fovY
        // "$schema" lets editors find schema/preset.schema.json; it carries no setting.
        if (path == "$schema" && value.is_string()) continue;
        if (!dotted && (path == "version" || findField(path))) continue;
        if (dotted || childKeys(path).empty()) {
            issues.push_back({path, std::string("unknown key") + (dotted ? " (nest objects; keys have no dots)" : "") +
                                        ", expected one of: " + listKeys(childKeys(prefix))});
        } else if (!value.is_object()) {
            issues.push_back({path, "expected an object, got " + describe(value)});
        } else {
            checkKeys(value, path, issues);
        }
    }
}

void checkVersion(const Json& root, Issues& issues) {
    const auto it = root.find("version");
    if (it == root.end()) {
        issues.push_back({"version", "missing; every preset must say \"version\": " + std::to_string(kPresetVersion)});
    } else if (!it->is_number_integer()) {
        issues.push_back({"version", "expected the integer " + std::to_string(kPresetVersion) + ", got " + describe(*it)});
    } else if (*it != kPresetVersion) {
        issues.push_back({"version", "unsupported version " + describe(*it) + ", this build reads version " +
                                         std::to_string(kPresetVersion)});
    }
}

// The value at a dotted path, or nullptr if it (or an enclosing object) is missing.
const Json* lookup(const Json& root, std::string_view path) {
    const Json* node = &root;
    for (std::size_t start = 0; start <= path.size();) {
        const std::size_t dot = std::min(path.find('.', start), path.size());
        if (!node->is_object()) return nullptr;
        const auto it = node->find(std::string(path.substr(start, dot - start)));
        if (it == node->end()) return nullptr;
        node = &*it;
        start = dot + 1;
    }
    return node;
}

std::optional<float> readFloat(const FieldInfo& field, const Json& value, const std::string& path, Issues& issues) {
    if (!value.is_number()) {
        issues.push_back({path, "expected a number, got " + describe(value)});
        return std::nullopt;
    }
    const auto number = value.get<double>();
    if (auto reason = checkNumber(field, number)) {
        issues.push_back({path, *reason});
        return std::nullopt;
    }
    return static_cast<float>(number);
}

std::optional<int> readInt(const FieldInfo& field, const Json& value, const std::string& path, Issues& issues) {
    if (!value.is_number_integer()) {
        issues.push_back({path, "expected an integer, got " + describe(value)});
        return std::nullopt;
    }
    const double number = value.is_number_unsigned() ? static_cast<double>(value.get<std::uint64_t>())
                                                     : static_cast<double>(value.get<std::int64_t>());
    if (auto reason = checkNumber(field, number)) {
        issues.push_back({path, *reason});
        return std::nullopt;
    }
    return static_cast<int>(value.get<std::int64_t>());
}

std::optional<std::vector<int>> readInts(const FieldInfo& field, const Json& value, const std::string& path,
                                         Issues& issues) {
    if (!value.is_array()) {
        issues.push_back({path, "expected an array of integers, got " + describe(value)});
        return std::nullopt;
    }
    std::vector<int> ints;
    const std::size_t before = issues.size();
    for (std::size_t i = 0; i < value.size(); ++i)
        ints.push_back(readInt(field, value[i], path + "[" + std::to_string(i) + "]", issues).value_or(0));
    if (issues.size() != before) return std::nullopt;
    return ints;
}

std::optional<int> readEnum(const FieldInfo& field, const Json& value, const std::string& path, Issues& issues) {
    const auto index = value.is_string() ? enumIndex(field.enumNames, value.get<std::string>()) : std::nullopt;
    if (!index) issues.push_back({path, "must be one of " + quotedNames(field.enumNames) + ", got " + describe(value)});
    return index;
}

// `path` names the value in messages: the field's path, or a keyframe member's.
std::optional<std::vector<float>> readFloats(const FieldInfo& field, const Json& value, const std::string& path,
                                             Issues& issues) {
    const bool isVec3 = field.kind == FieldKind::Vec3;
    if (!value.is_array() || (isVec3 && value.size() != 3)) {
        issues.push_back({path, (isVec3 ? "expected an array of 3 numbers, got " : "expected an array of numbers, got ") +
                                    describe(value)});
        return std::nullopt;
    }
    std::vector<float> floats;
    const std::size_t before = issues.size();
    for (std::size_t i = 0; i < value.size(); ++i) {
        floats.push_back(readFloat(field, value[i], path + "[" + std::to_string(i) + "]", issues).value_or(0.0f));
    }
    if (issues.size() != before) return std::nullopt;
    return floats;
}

std::optional<glm::vec3> readVec3(const FieldInfo& field, const Json& value, const std::string& path, Issues& issues) {
    const auto floats = readFloats(field, value, path, issues);
    if (!floats) return std::nullopt;
    return glm::vec3((*floats)[0], (*floats)[1], (*floats)[2]);
}

std::optional<FieldValue> readValueAt(const FieldInfo& field, const Json& value, const std::string& path,
                                      Issues& issues);

// "a position and a target": the members a keyframe cannot do without.
std::string requiredKeyframeMembers() {
    std::vector<std::string> names;
    for (const KeyframeFieldInfo& m : keyframeFieldTable())
        if (m.required) names.push_back("a " + std::string(m.field.path));
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return text;
}

// One {"position": [x,y,z], "target": [x,y,z], "fovY": deg} object (keyframeFieldTable()): the
// required members must be there (a pose without them is a typo, not a default), the others
// default to CameraKeyframe{}'s. Each member is checked like the camera field of the same name.
std::optional<CameraKeyframe> readKeyframe(const Json& value, const std::string& path, Issues& issues) {
    if (!value.is_object()) {
        issues.push_back({path, "expected an object {" + keyframeKeyList() + "}, got " + describe(value)});
        return std::nullopt;
    }
    const std::size_t before = issues.size();
    for (const auto& [key, member] : value.items()) {
        if (!findKeyframeField(key))
            issues.push_back({path + "." + key, "unknown key, expected one of: " + keyframeKeyList()});
    }
    CameraKeyframe frame;
    for (const KeyframeFieldInfo& m : keyframeFieldTable()) {
        const std::string key(m.field.path);
        const auto it = value.find(key);
        if (it == value.end()) {
            if (m.required) issues.push_back({path + "." + key, "missing; every keyframe needs " + requiredKeyframeMembers()});
            continue;
        }
        if (auto read = readValueAt(m.field, *it, path + "." + key, issues)) m.set(frame, *read);
    }
    if (issues.size() != before) return std::nullopt;
    return frame;
}

std::optional<std::vector<CameraKeyframe>> readKeyframes(const FieldInfo& field, const Json& value, Issues& issues) {
    const std::string path(field.path);
    if (!value.is_array()) {
        issues.push_back({path, "expected an array of keyframe objects, got " + describe(value)});
        return std::nullopt;
    }
    std::vector<CameraKeyframe> frames;
    bool ok = true;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const auto frame = readKeyframe(value[i], path + "[" + std::to_string(i) + "]", issues);
        ok = ok && frame.has_value();
        frames.push_back(frame.value_or(CameraKeyframe{}));
    }
    if (!ok) return std::nullopt;
    return frames;
}

template <class T>
std::optional<FieldValue> wrap(std::optional<T> value) {
    if (!value) return std::nullopt;
    return FieldValue(std::in_place_type<T>, std::move(*value));
}

std::optional<FieldValue> readBool(const Json& value, const std::string& path, Issues& issues) {
    if (value.is_boolean()) return FieldValue(std::in_place_type<bool>, value.get<bool>());
    issues.push_back({path, "expected true or false, got " + describe(value)});
    return std::nullopt;
}

std::optional<FieldValue> readString(const Json& value, const std::string& path, Issues& issues) {
    if (value.is_string()) return FieldValue(std::in_place_type<std::string>, value.get<std::string>());
    issues.push_back({path, "expected a string, got " + describe(value)});
    return std::nullopt;
}

// `path` names the value in messages: the field's path, or a keyframe member's.
std::optional<FieldValue> readValueAt(const FieldInfo& field, const Json& value, const std::string& path,
                                      Issues& issues) {
    switch (field.kind) {
        case FieldKind::Float: return wrap(readFloat(field, value, path, issues));
        case FieldKind::Int: return wrap(readInt(field, value, path, issues));
        case FieldKind::Enum: return wrap(readEnum(field, value, path, issues));
        case FieldKind::Bool: return readBool(value, path, issues);
        case FieldKind::String: return readString(value, path, issues);
        case FieldKind::FloatList: return wrap(readFloats(field, value, path, issues));
        case FieldKind::IntList: return wrap(readInts(field, value, path, issues));
        case FieldKind::Vec3: return wrap(readVec3(field, value, path, issues));
        case FieldKind::KeyframeList: return wrap(readKeyframes(field, value, issues));
    }
    return std::nullopt;
}

std::optional<FieldValue> readValue(const FieldInfo& field, const Json& value, Issues& issues) {
    return readValueAt(field, value, std::string(field.path), issues);
}

std::vector<std::string> withSource(const Issues& issues, const std::string& sourceName) {
    std::vector<std::string> messages;
    for (const auto& issue : issues) messages.push_back(sourceName + ": " + issue.message());
    return messages;
}

}  // namespace

FieldValue readFieldValue(const FieldInfo& field, const nlohmann::json& value, const std::string& path) {
    Issues issues;
    std::optional<FieldValue> read = readValueAt(field, value, path, issues);
    if (!issues.empty() || !read) {
        std::vector<std::string> messages;
        for (const auto& issue : issues) messages.push_back(issue.message());
        if (messages.empty()) messages.push_back(path + ": cannot be read as " + std::string(fieldKindName(field.kind)));
        throw SettingsError(messages);
    }
    return *read;
}

Settings fromJson(const nlohmann::json& json, const std::string& sourceName) {
    if (!json.is_object()) {
        throw SettingsError(sourceName + ": (top level): expected an object, got " + describe(json));
    }
    // A JSON Schema given as a preset (schema/preset.schema.json, say): one message, not a list
    // of its keywords as unknown keys.
    if (const auto it = json.find("$schema"); it != json.end() && it->is_string() &&
                                              it->get_ref<const std::string&>().find("json-schema.org/") != std::string::npos) {
        throw SettingsError(sourceName + ": $schema: " + it->dump() +
                            " makes this a JSON Schema, not a preset (a preset's \"$schema\" names preset.schema.json)");
    }
    Issues issues;
    checkVersion(json, issues);
    checkKeys(json, "", issues);
    Settings settings;
    PathSet unread;  // present but unusable: keep the default and skip the rules that read it
    for (const FieldInfo& field : fieldTable()) {
        const Json* value = lookup(json, field.path);
        if (!value) continue;
        if (auto read = readValue(field, *value, issues)) {
            field.set(settings, *read);
        } else {
            unread.emplace(field.path);
        }
    }
    const auto ruleIssues = findIssues(settings, unread);
    issues.insert(issues.end(), ruleIssues.begin(), ruleIssues.end());
    if (!issues.empty()) throw SettingsError(withSource(issues, sourceName));
    return settings;
}

}  // namespace st
