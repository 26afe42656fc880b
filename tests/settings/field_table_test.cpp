// The field table: complete, consistent with the JSON writer, and the change classes.
#include "renderer/settings/enum_names.h"
#include "renderer/settings/field_table.h"
#include "renderer/settings/settings_json.h"
#include "renderer/settings/validation.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

namespace st {
namespace {

// Leaf paths of a JSON object: "cascades.count", ... (arrays are leaves).
void leafPaths(const nlohmann::json& json, const std::string& prefix, std::set<std::string>& out) {
    for (const auto& [key, value] : json.items()) {
        const std::string path = prefix.empty() ? key : prefix + "." + key;
        if (value.is_object()) {
            leafPaths(value, path, out);
        } else {
            out.insert(path);
        }
    }
}

TEST(FieldTableTest, EveryKeyTheWriterWritesHasARow) {
    std::set<std::string> paths;
    leafPaths(toJson(Settings{}), "", paths);
    paths.erase("version");
    for (const auto& path : paths) EXPECT_NE(findField(path), nullptr) << path;
}

TEST(FieldTableTest, EveryRowIsWritten) {
    std::set<std::string> paths;
    leafPaths(toJson(Settings{}), "", paths);
    for (const FieldInfo& field : fieldTable()) EXPECT_TRUE(paths.contains(std::string(field.path))) << field.path;
    EXPECT_EQ(paths.size(), fieldTable().size() + 1);  // + "version"
}

TEST(FieldTableTest, PathsAreUnique) {
    std::set<std::string_view> paths;
    for (const FieldInfo& field : fieldTable()) EXPECT_TRUE(paths.insert(field.path).second) << field.path;
}

TEST(FieldTableTest, EveryFieldOfTheTestSettingsDiffersFromDefault) {
    const Settings changed = test::everyFieldChanged();
    EXPECT_TRUE(validate(changed).empty());
    for (const FieldInfo& field : fieldTable()) EXPECT_NE(field.get(changed), field.get(Settings{})) << field.path;
}

TEST(FieldTableTest, SettingEveryFieldThroughTheTableCopiesTheWholeStruct) {
    const Settings changed = test::everyFieldChanged();
    Settings copy;
    for (const FieldInfo& field : fieldTable()) field.set(copy, field.get(changed));
    EXPECT_EQ(copy, changed);  // fails if a Settings member has no row
}

TEST(FieldTableTest, ValueAlternativeMatchesKind) {
    const auto expectedIndex = [](FieldKind kind) -> std::size_t {
        switch (kind) {
            case FieldKind::Float: return 0;
            case FieldKind::Int:
            case FieldKind::Enum: return 1;
            case FieldKind::Bool: return 2;
            case FieldKind::String: return 3;
            case FieldKind::Vec3: return 4;
            case FieldKind::FloatList: return 5;
            case FieldKind::KeyframeList: return 6;
            case FieldKind::IntList: return 7;
        }
        return 99;
    };
    for (const FieldInfo& field : fieldTable()) {
        EXPECT_EQ(field.get(Settings{}).index(), expectedIndex(field.kind)) << field.path;
    }
}

TEST(FieldTableTest, RowsAreDescribed) {
    for (const FieldInfo& field : fieldTable()) {
        SCOPED_TRACE(std::string(field.path));
        EXPECT_FALSE(field.label.empty());
        ASSERT_FALSE(field.help.empty());
        EXPECT_EQ(field.help.back(), '.');  // one sentence
        EXPECT_LE(field.help.size(), 120u);
    }
}

TEST(FieldTableTest, NumericRowsHaveARangeAndAStep) {
    for (const FieldInfo& field : fieldTable()) {
        const bool numeric = field.kind == FieldKind::Float || field.kind == FieldKind::Int ||
                             field.kind == FieldKind::Vec3 || field.kind == FieldKind::FloatList ||
                             field.kind == FieldKind::IntList;
        if (!numeric) continue;
        EXPECT_LT(field.min, field.max) << field.path;
        EXPECT_GT(field.step, 0.0) << field.path;
    }
}

TEST(FieldTableTest, EnumNamesAreLowercaseKebab) {
    const std::regex kebab("[a-z0-9]+(-[a-z0-9]+)*");
    for (const FieldInfo& field : fieldTable()) {
        EXPECT_EQ(field.kind == FieldKind::Enum, !field.enumNames.empty()) << field.path;
        for (const auto name : field.enumNames) EXPECT_TRUE(std::regex_match(std::string(name), kebab)) << name;
    }
}

TEST(FieldTableTest, RangesOfTheBrief) {
    EXPECT_EQ(findField("cascades.count")->max, 8);
    EXPECT_TRUE(findField("cascades.mapSize")->powerOfTwo);
    EXPECT_TRUE(findField("filter.size")->odd);
    EXPECT_EQ(findField("camera.fovY")->unit, "deg");
    EXPECT_EQ(findField("cascades.mapSize")->unit, "texels");
    EXPECT_EQ(findField("nope"), nullptr);
}

TEST(FieldTableTest, DefaultsAreValid) { EXPECT_EQ(validate(Settings{}), std::vector<std::string>{}); }

TEST(EnumNamesTest, NamesRoundTrip) {
    for (const auto name : enumNames<ZExtension>()) EXPECT_EQ(enumName(*parseEnum<ZExtension>(name)), name);
    EXPECT_EQ(enumName(SplitScheme::Practical), "practical");
    EXPECT_EQ(enumName(FilterKind::PcfNxN), "pcf-nxn");
    EXPECT_EQ(enumName(ZExtension::SceneBounds), "scene-bounds");
    EXPECT_EQ(parseEnum<FitMode>("sphere"), FitMode::Sphere);
    EXPECT_EQ(parseEnum<View>("Shaded"), std::nullopt);  // case-sensitive
    EXPECT_EQ(enumName(static_cast<Selection>(7)), "<invalid 7>");
}

TEST(ClassifyChangeTest, EqualSettingsCostNothing) {
    EXPECT_EQ(classifyChange(Settings{}, Settings{}), ChangeClass::None);
    EXPECT_TRUE(changedFields(Settings{}, Settings{}).empty());
}

TEST(ClassifyChangeTest, NotesCostNothing) {
    Settings b;
    b.notes = "edited";
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::None);
    ASSERT_EQ(changedFields(Settings{}, b).size(), 1u);
    EXPECT_EQ(changedFields(Settings{}, b)[0]->path, "notes");
}

TEST(ClassifyChangeTest, CameraLightBiasAndFilterAreUniforms) {
    Settings b;
    b.camera.fovY = 30.0f;
    b.light.elevation = 10.0f;
    b.bias.slope = 3.0f;
    b.filter.kind = FilterKind::PcfNxN;
    b.cascades.lambda = 0.9f;
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::Uniform);
}

TEST(ClassifyChangeTest, CountAndMapSizeReallocate) {
    Settings b;
    b.cascades.mapSize = 2048;
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::Reallocate);
    Settings c;
    c.cascades.count = 2;
    c.camera.fovY = 30.0f;  // the maximum wins
    EXPECT_EQ(classifyChange(Settings{}, c), ChangeClass::Reallocate);
}

TEST(ClassifyChangeTest, OutputSizeAndScene) {
    Settings b;
    b.output.width = 1280;
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::Output);
    b.output.view = View::Cascades;  // only a uniform: still Output overall
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::Output);
    b.scene = "builtin:other";
    b.cascades.mapSize = 512;
    EXPECT_EQ(classifyChange(Settings{}, b), ChangeClass::Scene);
    EXPECT_EQ(classifyChange(b, Settings{}), ChangeClass::Scene);  // symmetric
    EXPECT_EQ(changeClassName(ChangeClass::Scene), "scene");
}

}  // namespace
}  // namespace st

namespace st {
namespace {

// A bias whose unit is a setting of its own is said in that unit (an engine-bound tune's
// explanation printed "Normal offset 0 texels -> 0.02 texels" for three.js's metres).
TEST(FieldTableTest, TheBiasesUnitFollowsTheirUnitSetting) {
    Settings s;
    const FieldInfo& offset = *findField("bias.normalOffset");
    const FieldInfo& constant = *findField("bias.constant");
    EXPECT_EQ(unitIn(offset, s), "texels");
    EXPECT_EQ(unitIn(constant, s), "m");
    s.bias.normalOffsetUnit = OffsetUnit::Metres;
    s.bias.constantUnit = BiasUnit::Depth;
    EXPECT_EQ(unitIn(offset, s), "m");
    EXPECT_EQ(unitIn(constant, s), "of the light box's depth");
    EXPECT_EQ(unitIn(*findField("cascades.mapSize"), s), "texels");
}

}  // namespace
}  // namespace st
