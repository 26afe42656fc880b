// The preset JSON Schema generated from the field table.
#include "renderer/settings/field_table.h"
#include "renderer/settings/schema.h"
#include "renderer/settings/settings_json.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace st {
namespace {

using nlohmann::json;

// The schema node of a field: properties.a.properties.b for "a.b".
const json& nodeAt(const json& schema, std::string_view path) {
    const json* node = &schema;
    for (auto dot = path.find('.'); dot != std::string_view::npos; dot = path.find('.')) {
        node = &node->at("properties").at(std::string(path.substr(0, dot)));
        path.remove_prefix(dot + 1);
    }
    return node->at("properties").at(std::string(path));
}

void expectClosedObjects(const json& node, const std::string& where) {
    if (!node.is_object()) return;
    if (node.value("type", "") == "object") {
        EXPECT_EQ(node.value("additionalProperties", true), false) << where;
    }
    for (const auto& [key, child] : node.items()) expectClosedObjects(child, where + "/" + key);
}

TEST(SchemaTest, Draft202012WithRequiredVersion) {
    const json schema = presetJsonSchema();
    EXPECT_EQ(schema["$schema"], "https://json-schema.org/draft/2020-12/schema");
    EXPECT_EQ(schema["required"], json::array({"version"}));
    EXPECT_EQ(schema["properties"]["version"]["const"], 1);
}

TEST(SchemaTest, EveryObjectIsClosed) { expectClosedObjects(presetJsonSchema(), ""); }

TEST(SchemaTest, EveryFieldIsDescribedWithItsRange) {
    const json schema = presetJsonSchema();
    for (const FieldInfo& field : fieldTable()) {
        SCOPED_TRACE(std::string(field.path));
        const json& node = nodeAt(schema, field.path);
        EXPECT_EQ(node["title"], field.label);
        EXPECT_EQ(node["description"].get<std::string>().rfind(field.help, 0), 0u);
        if (field.kind == FieldKind::Float) {
            EXPECT_EQ(node["minimum"], field.min);
            EXPECT_EQ(node["maximum"], field.max);
        }
    }
}

TEST(SchemaTest, TypesFollowTheKinds) {
    const json schema = presetJsonSchema();
    EXPECT_EQ(nodeAt(schema, "cascades.mapSize")["enum"], json::array({256, 512, 1024, 2048, 4096, 8192}));
    EXPECT_EQ(nodeAt(schema, "filter.size")["enum"], json::array({3, 5, 7, 9}));
    EXPECT_EQ(nodeAt(schema, "cascades.count")["type"], "integer");
    EXPECT_EQ(nodeAt(schema, "cascades.zExtension")["enum"],
              json::array({"none", "distance", "scene-bounds", "pancake"}));
    EXPECT_EQ(nodeAt(schema, "camera.position")["minItems"], 3);
    EXPECT_EQ(nodeAt(schema, "scene")["minLength"], 1);
    EXPECT_NE(nodeAt(schema, "camera.fovY")["description"].get<std::string>().find("Unit: deg."), std::string::npos);
}

TEST(SchemaTest, DefaultsAreThoseOfSettings) {
    const json schema = presetJsonSchema();
    json preset = {{"version", 1}};
    for (const FieldInfo& field : fieldTable()) {
        std::string pointer = "/" + std::string(field.path);
        std::replace(pointer.begin(), pointer.end(), '.', '/');
        preset[json::json_pointer(pointer)] = nodeAt(schema, field.path)["default"];
    }
    EXPECT_EQ(preset, toJson(Settings{}));
    EXPECT_EQ(fromJson(preset, "schema defaults"), Settings{});
}

TEST(SchemaTest, TextIsPrettyWithAFinalNewline) {
    const std::string text = presetJsonSchemaText();
    EXPECT_EQ(text.rfind("{\n  \"$schema\"", 0), 0u);
    EXPECT_EQ(text.back(), '\n');
    EXPECT_EQ(json::parse(text), presetJsonSchema());
}

}  // namespace
}  // namespace st
