// path.frames and path.keyframes: JSON form, strict reading, validation and schema of the camera
// path the flicker measurement moves the cascade camera along.
#include "renderer/settings/field_table.h"
#include "renderer/settings/schema.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

namespace st {
namespace {

using nlohmann::json;
using test::hasMessage;
using test::preset;
using test::readErrors;

json pose(json position, json target) { return {{"position", position}, {"target", target}}; }

TEST(CameraPathSettingsTest, NoPathByDefault) {
    EXPECT_EQ(Settings{}.path.frames, 0);
    EXPECT_TRUE(Settings{}.path.keyframes.empty());
    EXPECT_EQ(findField("path.keyframes")->kind, FieldKind::KeyframeList);
    EXPECT_EQ(fieldKindName(FieldKind::KeyframeList), "keyframe list");
}

TEST(CameraPathSettingsTest, KeyframesAreWrittenAsObjects) {
    const auto written = toOrderedJson(test::everyFieldChanged());
    const json expected = {{"position", {0.0, 2.0, 5.0}}, {"target", {0.0, 1.0, -5.0}}, {"fovY", 50.0}};
    EXPECT_EQ(json(written["path"]["keyframes"][0]), expected);
    EXPECT_EQ(written["path"]["keyframes"][1]["fovY"].dump(), "55.5");
    EXPECT_EQ(written["path"]["frames"], 12);
}

TEST(CameraPathSettingsTest, ReadsAPathWithFovDefault) {
    const Settings s = fromJson(preset({{"path", {{"frames", 8}, {"keyframes", {pose({1, 2, 3}, {1, 2, 0})}}}}}), "mem");
    ASSERT_EQ(s.path.keyframes.size(), 1u);
    EXPECT_EQ(s.path.frames, 8);
    EXPECT_EQ(s.path.keyframes[0].position, glm::vec3(1, 2, 3));
    EXPECT_EQ(s.path.keyframes[0].target, glm::vec3(1, 2, 0));
    EXPECT_EQ(s.path.keyframes[0].fovY, 60.0f);
}

TEST(CameraPathSettingsTest, KeyframeStructureErrorsNameTheElement) {
    json frames = json::array({pose({0, 0, 0}, {0, 0, 1}), {{"position", {0, 0, 0}}}, 5,
                               {{"position", {0, 0}}, {"target", {0, 0, 1}}, {"fov", 3}}});
    const auto errors = readErrors(preset({{"path", {{"keyframes", frames}}}}));
    EXPECT_TRUE(hasMessage(errors, "presets/bad.json: path.keyframes[1].target: missing"));
    EXPECT_TRUE(hasMessage(errors, "path.keyframes[2]: expected an object {position, target, fovY}, got 5"));
    EXPECT_TRUE(hasMessage(errors, "path.keyframes[3].position: expected an array of 3 numbers"));
    EXPECT_TRUE(hasMessage(errors, "path.keyframes[3].fov: unknown key, expected one of: position, target, fovY"));
    EXPECT_TRUE(hasMessage(readErrors(preset({{"path", {{"keyframes", 3}}}})),
                           "path.keyframes: expected an array of keyframe objects, got 3"));
}

TEST(CameraPathSettingsTest, KeyframeMembersFollowTheCameraRanges) {
    json frame = {{"position", {0, 0, 2e6}}, {"target", {0, 0, 1}}, {"fovY", 200}};
    const auto errors = readErrors(preset({{"path", {{"keyframes", {frame}}}}}));
    EXPECT_TRUE(hasMessage(errors, "path.keyframes[0].position[2]: must be in -1000000..1000000, got 2000000"));
    EXPECT_TRUE(hasMessage(errors, "path.keyframes[0].fovY: must be in 1..179, got 200"));
    Settings s;
    s.path.keyframes = {{.fovY = 0.5f}};
    EXPECT_TRUE(hasMessage(validate(s), "path.keyframes[0].fovY: must be in 1..179, got 0.5"));
}

TEST(CameraPathSettingsTest, FramesNeedAKeyframeAndPosesADirection) {
    Settings s;
    s.path.frames = 4;
    EXPECT_EQ(validate(s), std::vector<std::string>{
                               "path.keyframes: path.frames is 4, so the path needs at least one keyframe"});
    s.path.keyframes = {{.position = {1, 1, 1}, .target = {1, 1, 1}}};
    EXPECT_TRUE(hasMessage(validate(s), "path.keyframes[0].target: must differ from its position"));
    s.path.keyframes[0].target = {0, 0, 0};
    EXPECT_TRUE(validate(s).empty());
    s.path.frames = -1;
    EXPECT_TRUE(hasMessage(validate(s), "path.frames: must be in 0..10000, got -1"));
}

TEST(CameraPathSettingsTest, PathChangesCostTheRendererNothing) {
    Settings b;
    b.path.frames = 16;
    b.path.keyframes = {{}};
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::None);
}

TEST(CameraPathSettingsTest, SchemaDescribesKeyframeObjects) {
    const json schema = presetJsonSchema();
    const json& node = schema["properties"]["path"]["properties"]["keyframes"];
    EXPECT_EQ(node["type"], "array");
    EXPECT_EQ(node["items"]["required"], json::array({"position", "target"}));
    EXPECT_EQ(node["items"]["additionalProperties"], false);
    EXPECT_EQ(node["items"]["properties"]["fovY"]["maximum"], 179.0);
    EXPECT_EQ(node["items"]["properties"]["position"]["minItems"], 3);
    EXPECT_EQ(node["default"], json::array());
}

}  // namespace
}  // namespace st
