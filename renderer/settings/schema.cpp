#include "renderer/settings/schema.h"

#include "renderer/settings/field_table.h"
#include "renderer/settings/number_text.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"

#include <cstdint>
#include <utility>

namespace st {
namespace {

using OJson = nlohmann::ordered_json;

OJson objectSchema() {
    return OJson{{"type", "object"}, {"additionalProperties", false}, {"properties", OJson::object()}};
}

OJson numberSchema(const FieldInfo& field) {
    return OJson{{"type", "number"}, {"minimum", field.min}, {"maximum", field.max}};
}

// Power-of-two and odd integers cannot be said with minimum/maximum: list them (ranges are small).
OJson intSchema(const FieldInfo& field) {
    const auto min = static_cast<std::int64_t>(field.min);
    const auto max = static_cast<std::int64_t>(field.max);
    if (!field.powerOfTwo && !field.odd) return OJson{{"type", "integer"}, {"minimum", min}, {"maximum", max}};
    auto values = OJson::array();
    for (std::int64_t v = min; v <= max; ++v) {
        if ((field.powerOfTwo && (v & (v - 1)) == 0) || (field.odd && v % 2 != 0)) values.push_back(v);
    }
    return OJson{{"type", "integer"}, {"enum", values}};
}

OJson typeSchema(const FieldInfo& field);

// A keyframe member's description: its help, the default of an optional member, its unit.
std::string keyframeMemberDescription(const KeyframeFieldInfo& m) {
    std::string text(m.field.help);  // one sentence, ending in '.'
    if (!m.required && !text.empty()) {
        const FieldValue value = m.get(CameraKeyframe{});
        const std::string shown = std::holds_alternative<float>(value) ? formatFloat(std::get<float>(value))
                                                                       : fieldValueToJson(m.field, value).dump();
        text.insert(text.size() - 1, " (default " + shown + ")");
    }
    if (!m.field.unit.empty()) text += " Unit: " + std::string(m.field.unit) + ".";
    return text;
}

// An object per keyframe (keyframeFieldTable()); its members take the schemas of the camera
// fields of the same name.
OJson keyframeListSchema() {
    OJson item = objectSchema();
    auto required = OJson::array();
    for (const KeyframeFieldInfo& m : keyframeFieldTable()) {
        const std::string key(m.field.path);
        OJson member{{"description", keyframeMemberDescription(m)}};
        member.update(typeSchema(m.field));
        item["properties"][key] = std::move(member);
        if (m.required) required.push_back(key);
    }
    item["required"] = std::move(required);
    return OJson{{"type", "array"}, {"items", std::move(item)}};
}

OJson typeSchema(const FieldInfo& field) {
    switch (field.kind) {
        case FieldKind::Float: return numberSchema(field);
        case FieldKind::Int: return intSchema(field);
        case FieldKind::Bool: return OJson{{"type", "boolean"}};
        case FieldKind::String:
            return field.nonEmpty ? OJson{{"type", "string"}, {"minLength", 1}} : OJson{{"type", "string"}};
        case FieldKind::Enum: {
            auto names = OJson::array();
            for (const auto name : field.enumNames) names.push_back(std::string(name));
            return OJson{{"type", "string"}, {"enum", names}};
        }
        case FieldKind::Vec3:
            return OJson{{"type", "array"}, {"items", numberSchema(field)}, {"minItems", 3}, {"maxItems", 3}};
        case FieldKind::FloatList: return OJson{{"type", "array"}, {"items", numberSchema(field)}};
        case FieldKind::IntList: return OJson{{"type", "array"}, {"items", intSchema(field)}};
        case FieldKind::KeyframeList: return keyframeListSchema();
    }
    return OJson::object();
}

OJson fieldSchema(const FieldInfo& field) {
    std::string description(field.help);
    if (!field.unit.empty()) description += " Unit: " + std::string(field.unit) + ".";
    OJson schema{{"title", field.label}, {"description", description}};
    schema.update(typeSchema(field));
    schema["default"] = fieldValueToJson(field, field.get(Settings{}));
    return schema;
}

// Puts `schema` at `path` ("cascades.count") under `root`'s properties, making group objects.
void place(OJson& root, std::string_view path, OJson schema) {
    OJson* node = &root;
    for (auto dot = path.find('.'); dot != std::string_view::npos; dot = path.find('.')) {
        OJson& group = (*node)["properties"][std::string(path.substr(0, dot))];
        if (group.is_null()) group = objectSchema();
        node = &group;
        path.remove_prefix(dot + 1);
    }
    (*node)["properties"][std::string(path)] = std::move(schema);
}

std::string rootDescription() {
    std::string text =
        "A shadowtune preset: every setting of a cascaded shadow map configuration. Only \"version\" is "
        "required; a missing field takes its default. Rules across fields, checked when loading:";
    for (const auto rule : crossFieldRuleDescriptions()) text += " " + std::string(rule);
    return text;
}

}  // namespace

OJson fieldValueSchema(const FieldInfo& field) { return typeSchema(field); }

OJson presetJsonSchemaOrdered() {
    OJson root{{"$schema", "https://json-schema.org/draft/2020-12/schema"},
               {"title", "shadowtune preset"},
               {"description", rootDescription()}};
    root.update(objectSchema());
    root["required"] = OJson::array({"version"});
    root["properties"]["version"] = OJson{{"description", "Preset format version; this build reads version 1."},
                                          {"const", kPresetVersion}};
    root["properties"]["$schema"] = OJson{{"description", "Optional: where editors find this schema (ignored by shadowtune)."},
                                          {"type", "string"}};
    for (const FieldInfo& field : fieldTable()) place(root, field.path, fieldSchema(field));
    return root;
}

nlohmann::json presetJsonSchema() { return nlohmann::json(presetJsonSchemaOrdered()); }

std::string presetJsonSchemaText() { return presetJsonSchemaOrdered().dump(2) + "\n"; }

}  // namespace st
