#pragma once
// The one declarative table of settings fields (docs/architecture.md#one-declarative-settings-table):
// a row per Settings field with its JSON path, UI label, help, unit, range and what a change
// costs. ImGui widgets, JSON (de)serialisation, validation, the preset JSON Schema and the docs
// are all generated from it. Adding a field to settings.h means adding a row in field_table.cpp.
#include "renderer/settings/settings.h"

#include <glm/vec3.hpp>

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace st {

enum class FieldKind { Float, Int, Bool, Enum, String, Vec3, FloatList, KeyframeList, IntList };

// What the renderer must redo when a field changes, cheapest first. Each class includes the work
// of the ones before it, so the cost of several changes is the maximum of their classes.
enum class ChangeClass {
    None,        // nothing the renderer reads (e.g. notes)
    Uniform,     // per-frame values only: matrices, splits, bias, filter parameters
    Reallocate,  // the shadow map array must be reallocated (cascade count, map size)
    Output,      // the output framebuffer is resized (and shadow maps reallocated with it)
    Scene,       // the scene must be reloaded (and everything above redone)
};

// A field's value, by kind: Float -> float, Int -> int, Bool -> bool, Enum -> int (index into
// FieldInfo::enumNames), String -> std::string, Vec3 -> glm::vec3, FloatList -> vector<float>,
// KeyframeList -> vector<CameraKeyframe> (each element follows camera.position/target/fovY's rules),
// IntList -> vector<int> (each element follows the Int rules: range, powerOfTwo, odd).
using FieldValue = std::variant<float, int, bool, std::string, glm::vec3, std::vector<float>,
                                std::vector<CameraKeyframe>, std::vector<int>>;

struct FieldInfo {
    std::string_view path;   // JSON path, dot separated: "cascades.count"
    std::string_view label;  // UI label
    std::string_view help;   // one sentence: why you would change it
    std::string_view unit;   // "m", "deg", "texels", ... or "" for none
    FieldKind kind = FieldKind::Float;
    // Inclusive range of Float/Int fields and of each element of Vec3/FloatList/IntList fields.
    double min = 0.0;
    double max = 0.0;
    double step = 0.0;  // UI drag/slider step
    std::span<const std::string_view> enumNames;  // JSON names for Enum fields, by value
    bool powerOfTwo = false;  // Int: must be a power of two (UI steps by doubling)
    bool odd = false;         // Int: must be odd (UI steps by 2)
    bool nonEmpty = false;    // String: must not be empty
    ChangeClass change = ChangeClass::Uniform;
    // The uniform-block member of shaders/interface.h this field is copied into, by the same
    // name in C++ and GLSL (renderer/render/shader_blocks.cpp); "" when no shader reads it as is.
    std::string_view shader;
    // Exists only to reproduce a bug (a regression scenario's control, e.g. the three.js late
    // matrices): the editor keeps it out of its group, under a collapsed "Debug" heading.
    bool debug = false;
    FieldValue (*get)(const Settings&) = nullptr;
    // Stores `value` into the field; throws std::bad_variant_access if the alternative does not
    // match `kind` (see FieldValue). Does not validate: call validate() afterwards.
    void (*set)(Settings&, const FieldValue& value) = nullptr;
};

// All fields, in the order of settings.h (the order of JSON keys, UI widgets and docs).
const std::vector<FieldInfo>& fieldTable();

// The row with this JSON path, or nullptr.
const FieldInfo* findField(std::string_view path);

// The unit `field`'s value has in `s`: its row's, but for the biases whose unit is a setting of its
// own (bias.constantUnit, bias.normalOffsetUnit).
std::string_view unitIn(const FieldInfo& field, const Settings& s);

// Rows whose value differs between a and b, in table order.
std::vector<const FieldInfo*> changedFields(const Settings& a, const Settings& b);

// The maximum ChangeClass over the fields that differ; None if none differ.
ChangeClass classifyChange(const Settings& a, const Settings& b);

std::string_view changeClassName(ChangeClass change);  // "none", "uniform", ...
std::string_view fieldKindName(FieldKind kind);        // "float", "int", ...

}  // namespace st

// ---- The members of one path.keyframes element ------------------------------------------------
namespace st {

// One member of a CameraKeyframe: a sub-table the JSON reader, writer, schema and validation
// iterate, so a member's key is spelled once. `field` describes it like a row of the table (path =
// the key inside a keyframe, label, help, unit, kind, range); kind, unit and range are copied from
// the camera field of the same name, so a keyframe holds exactly what `camera` can.
struct KeyframeFieldInfo {
    FieldInfo field;       // its get/set are null: use the keyframe accessors below
    bool required = true;  // false: a missing member keeps CameraKeyframe{}'s value
    FieldValue (*get)(const CameraKeyframe&) = nullptr;
    void (*set)(CameraKeyframe&, const FieldValue& value) = nullptr;
};

// position, target, fovY: the order of the members in JSON.
const std::vector<KeyframeFieldInfo>& keyframeFieldTable();

// The member with this key, or nullptr.
const KeyframeFieldInfo* findKeyframeField(std::string_view key);

// "position, target, fovY" for messages.
std::string keyframeKeyList();

}  // namespace st
