// The sub-table of path.keyframes members (field_table.h KeyframeFieldInfo).
#include "renderer/settings/field_table.h"

#include <algorithm>

namespace st {
namespace {

// A member that follows the rules of camera.<key>, with its own label and help.
KeyframeFieldInfo member(std::string_view key, std::string_view label, std::string_view help, bool required) {
    KeyframeFieldInfo m;
    m.field = *findField("camera." + std::string(key));
    m.field.path = key;
    m.field.label = label;
    m.field.help = help;
    m.field.get = nullptr;
    m.field.shader = {};  // no keyframe member feeds a shader block
    m.field.set = nullptr;
    m.required = required;
    return m;
}

std::vector<KeyframeFieldInfo> buildKeyframeTable() {
    KeyframeFieldInfo position = member("position", "Position", "Cascade camera position at this keyframe.", true);
    position.get = [](const CameraKeyframe& k) { return FieldValue(k.position); };
    position.set = [](CameraKeyframe& k, const FieldValue& v) { k.position = std::get<glm::vec3>(v); };
    KeyframeFieldInfo target = member("target", "Target", "Point the cascade camera looks at.", true);
    target.get = [](const CameraKeyframe& k) { return FieldValue(k.target); };
    target.set = [](CameraKeyframe& k, const FieldValue& v) { k.target = std::get<glm::vec3>(v); };
    // Optional: a path that only moves keeps the lens (CameraKeyframe's default).
    KeyframeFieldInfo fovY = member("fovY", "Vertical FOV", "Vertical field of view at this keyframe.", false);
    fovY.get = [](const CameraKeyframe& k) { return FieldValue(k.fovY); };
    fovY.set = [](CameraKeyframe& k, const FieldValue& v) { k.fovY = std::get<float>(v); };
    return {position, target, fovY};
}

}  // namespace

const std::vector<KeyframeFieldInfo>& keyframeFieldTable() {
    static const std::vector<KeyframeFieldInfo> table = buildKeyframeTable();
    return table;
}

const KeyframeFieldInfo* findKeyframeField(std::string_view key) {
    const auto& table = keyframeFieldTable();
    const auto it = std::find_if(table.begin(), table.end(), [&](const KeyframeFieldInfo& m) { return m.field.path == key; });
    return it == table.end() ? nullptr : &*it;
}

std::string keyframeKeyList() {
    std::string list;
    for (const KeyframeFieldInfo& m : keyframeFieldTable()) list += (list.empty() ? "" : ", ") + std::string(m.field.path);
    return list;
}

}  // namespace st
