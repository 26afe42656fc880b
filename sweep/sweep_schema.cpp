#include "sweep/sweep_schema.h"

#include "renderer/settings/field_table.h"
#include "renderer/settings/schema.h"
#include "sweep/sweep_spec.h"

namespace st::sweep {
namespace {
using OJson = nlohmann::ordered_json;

// One branch per field: {"field": const, "values": [its schema...]} or a range for numbers.
OJson axisSchema(const FieldInfo& f) {
    OJson props{{"field", {{"const", std::string(f.path)}}},
                {"values", {{"type", "array"}, {"minItems", 1}, {"items", fieldValueSchema(f)}}}};
    if (f.kind == FieldKind::Float || f.kind == FieldKind::Int)
        props["range"] = {{"type", "object"},
                          {"properties", {{"from", {{"type", "number"}}}, {"to", {{"type", "number"}}}, {"step", {{"type", "number"}, {"exclusiveMinimum", 0}}}}},
                          {"required", {"from", "to", "step"}},
                          {"additionalProperties", false}};
    return {{"type", "object"}, {"title", std::string(f.label)}, {"properties", props}, {"required", {"field"}},
            {"additionalProperties", false}};
}
}  // namespace

std::string sweepJsonSchemaText() {
    OJson axes = OJson::array(), setProps = OJson::object();
    for (const FieldInfo& f : fieldTable()) {
        setProps[std::string(f.path)] = fieldValueSchema(f);
        if (isSweepable(f)) axes.push_back(axisSchema(f));
    }
    OJson root{
        {"$schema", "https://json-schema.org/draft/2020-12/schema"},
        {"title", "shadowtune sweep"},
        {"description", "A base preset, axes over its settings and reference presets; `shadowtune sweep` measures every "
                        "combination. Generated from renderer/settings/field_table.cpp."},
        {"type", "object"},
        {"properties",
         {{"$schema", {{"type", "string"}}},
          {"version", {{"const", kSweepVersion}}},
          {"notes", {{"type", "string"}}},
          {"base", {{"type", "string"}, {"description", "The base preset, relative to this file."}}},
          {"set", {{"type", "object"}, {"properties", setProps}, {"additionalProperties", false},
                   {"description", "Fields set on the base before sweeping (by field path)."}}},
          {"axes", {{"type", "array"}, {"items", {{"oneOf", axes}}}}},
          {"references", {{"type", "array"}, {"items", {{"type", "string"}}},
                          {"description", "Presets whose cascades, filter and bias are measured on the base's scene, "
                                          "camera, light and size, and labelled on the charts."}}}}},
        {"required", {"version", "base"}},
        {"additionalProperties", false}};
    return root.dump(2) + "\n";
}

}  // namespace st::sweep
