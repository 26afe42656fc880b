// Settings -> JSON, and SettingsError.
#include "renderer/settings/number_text.h"
#include "renderer/settings/settings_json.h"

#include <cstddef>
#include <utility>

namespace st {
namespace {

std::string joinLines(const std::vector<std::string>& lines) {
    std::string text;
    for (const auto& line : lines) text += (text.empty() ? "" : "\n") + line;
    return text;
}

nlohmann::ordered_json floatArray(const float* values, std::size_t count) {
    auto array = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < count; ++i) array.push_back(tidyFloat(values[i]));
    return array;
}

nlohmann::ordered_json keyframesToJson(const std::vector<CameraKeyframe>& frames) {
    auto array = nlohmann::ordered_json::array();
    for (const CameraKeyframe& f : frames) {
        nlohmann::ordered_json object = nlohmann::ordered_json::object();
        for (const KeyframeFieldInfo& m : keyframeFieldTable())
            object[std::string(m.field.path)] = fieldValueToJson(m.field, m.get(f));
        array.push_back(std::move(object));
    }
    return array;
}

// The object `path` ("cascades.count") lives in, created as needed; `leaf` gets "count".
nlohmann::ordered_json& parentOf(nlohmann::ordered_json& root, std::string_view path, std::string& leaf) {
    nlohmann::ordered_json* node = &root;
    for (auto dot = path.find('.'); dot != std::string_view::npos; dot = path.find('.')) {
        node = &(*node)[std::string(path.substr(0, dot))];
        path.remove_prefix(dot + 1);
    }
    leaf = std::string(path);
    return *node;
}

}  // namespace

SettingsError::SettingsError(std::vector<std::string> messages)
    : std::runtime_error(joinLines(messages)), messages_(std::move(messages)) {}

SettingsError::SettingsError(const std::string& message) : SettingsError(std::vector<std::string>{message}) {}

nlohmann::ordered_json fieldValueToJson(const FieldInfo& field, const FieldValue& value) {
    switch (field.kind) {
        case FieldKind::Float: return tidyFloat(std::get<float>(value));
        case FieldKind::Int: return std::get<int>(value);
        case FieldKind::Bool: return std::get<bool>(value);
        case FieldKind::String: return std::get<std::string>(value);
        case FieldKind::Enum: {
            const auto index = static_cast<std::size_t>(std::get<int>(value));
            if (index < field.enumNames.size()) return std::string(field.enumNames[index]);
            return "<invalid " + std::to_string(std::get<int>(value)) + ">";
        }
        case FieldKind::Vec3: return floatArray(&std::get<glm::vec3>(value).x, 3);
        case FieldKind::FloatList: {
            const auto& list = std::get<std::vector<float>>(value);
            return floatArray(list.data(), list.size());
        }
        case FieldKind::IntList: return std::get<std::vector<int>>(value);
        case FieldKind::KeyframeList: return keyframesToJson(std::get<std::vector<CameraKeyframe>>(value));
    }
    return nullptr;
}

nlohmann::ordered_json toOrderedJson(const Settings& s) {
    nlohmann::ordered_json root;
    root["version"] = kPresetVersion;
    for (const FieldInfo& field : fieldTable()) {
        std::string leaf;
        parentOf(root, field.path, leaf)[leaf] = fieldValueToJson(field, field.get(s));
    }
    return root;
}

nlohmann::json toJson(const Settings& s) { return nlohmann::json(toOrderedJson(s)); }

}  // namespace st
