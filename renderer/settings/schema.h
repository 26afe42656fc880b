#pragma once
// The preset JSON Schema (draft 2020-12), generated from the field table, so editors can
// complete and check presets. schema/preset.schema.json holds a copy; a test keeps it from going stale.
#include "renderer/settings/field_table.h"

#include <nlohmann/json.hpp>

#include <string>

namespace st {

// The JSON Schema of one value of `field` (type, range, enum names), as the preset schema has it.
nlohmann::ordered_json fieldValueSchema(const FieldInfo& field);

nlohmann::ordered_json presetJsonSchemaOrdered();  // keys in a readable order
nlohmann::json presetJsonSchema();                 // same content, keys sorted

// The exact text of schema/preset.schema.json: presetJsonSchemaOrdered() with 2-space indent and a
// final newline.
std::string presetJsonSchemaText();

}  // namespace st
