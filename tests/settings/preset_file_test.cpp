// loadPreset / savePresetAtomic: files, JSON syntax errors with line:column, atomic writes.
#include "renderer/settings/settings_json.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace st {
namespace {

using test::hasMessage;

class PresetFileTest : public test::ScratchDir {
protected:
    std::filesystem::path write(const std::string& name, const std::string& text) {
        const auto file = dir / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    static std::string read(const std::filesystem::path& file) {
        std::ifstream in(file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
    // The messages loadPreset throws for `file`.
    static std::vector<std::string> loadErrors(const std::filesystem::path& file) {
        try {
            (void)loadPreset(file);
        } catch (const SettingsError& e) {
            return e.messages();
        }
        ADD_FAILURE() << "loadPreset accepted " << file;
        return {};
    }
};

TEST_F(PresetFileTest, SavedPresetLoadsBackEqual) {
    for (const Settings& s : {Settings{}, test::everyFieldChanged()}) {
        savePresetAtomic(s, dir / "p.json");
        EXPECT_EQ(loadPreset(dir / "p.json"), s);
    }
}

TEST_F(PresetFileTest, SavedTextIsPrettyAndInTableOrder) {
    savePresetAtomic(Settings{}, dir / "p.json");
    const std::string text = read(dir / "p.json");
    EXPECT_EQ(text.rfind("{\n  \"version\": 1,\n  \"scene\": \"builtin:yard\",\n  \"notes\": \"\",\n  \"ground\": false,\n  \"origin\": [\n"
                         "    0.0,\n",
                         0),
              0u)
        << text;
    EXPECT_EQ(text.back(), '\n');
}

TEST_F(PresetFileTest, ShortPresetLoads) {
    const auto file = write("short.json", R"({"version": 1, "cascades": {"count": 2, "fit": "sphere"}})");
    const Settings s = loadPreset(file);
    EXPECT_EQ(s.cascades.count, 2);
    EXPECT_EQ(s.cascades.fit, FitMode::Sphere);
}

TEST_F(PresetFileTest, ValidationErrorsNameTheFile) {
    const auto file = write("bad.json", R"({"version": 1, "cascades": {"count": 12}})");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ": cascades.count: must be in 1..8, got 12"));
}

TEST_F(PresetFileTest, InvalidJsonGivesLineAndColumn) {
    const auto file = write("syntax.json", "{\n  \"version\": 1,\n  \"scene\": tru\n}\n");
    const auto errors = loadErrors(file);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].rfind(file.string() + ":3:", 0), 0u) << errors[0];
    EXPECT_TRUE(hasMessage(errors, ": invalid JSON: syntax error while parsing value - invalid literal"));
}

TEST_F(PresetFileTest, MissingCommaPointsAtTheNextKeysLine) {
    const auto file = write("comma.json", "{\n  \"version\": 1\n  \"scene\": \"x\"\n}\n");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ":3:9: invalid JSON: syntax error while parsing object"));
}

TEST_F(PresetFileTest, UnterminatedJsonPointsAtTheEnd) {
    const auto file = write("cut.json", "{\n  \"version\": 1,\n");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ":3:1: invalid JSON: syntax error"));
    EXPECT_TRUE(hasMessage(loadErrors(write("empty.json", "")), ":1:1: invalid JSON:"));
}

TEST_F(PresetFileTest, NumberOverflowIsInvalidJsonWithAPosition) {
    // nlohmann rejects 1e999 rather than reading it as inf.
    const auto file = write("huge.json", "{\n  \"version\": 1,\n  \"camera\": {\"farPlane\": 1e999}\n}\n");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ":3:26: invalid JSON: number overflow parsing '1e999'"));
}

TEST_F(PresetFileTest, NaNLiteralIsInvalidJson) {
    const auto file = write("nan.json", "{\"version\": 1, \"light\": {\"ambient\": NaN}}");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ":1:37: invalid JSON:"));
}

// 100000 nested arrays where an object belongs: a clear message, not a stack overflow while
// quoting the value (tests/fuzz/crashes/preset).
TEST_F(PresetFileTest, DeeplyNestedValueIsQuotedOneLevelDeep) {
    const std::size_t depth = 100000;
    const auto file = write("deep.json", "{\"version\": 1, \"camera\": " + std::string(depth, '[') +
                                             std::string(depth, ']') + "}");
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ": camera: expected an object, got array [[...]]"));
}

TEST_F(PresetFileTest, HugeFileIsRefusedBeforeReading) {
    const auto file = write("huge.json", "{}");
    std::filesystem::resize_file(file, 17u << 20);  // sparse: nothing is written
    EXPECT_TRUE(hasMessage(loadErrors(file), file.string() + ": cannot read preset: 17825792 bytes, more than the 16 MiB"));
}

// The schema lives in schema/, not among the presets; given as a preset it fails with one message.
TEST_F(PresetFileTest, TheSchemaGivenAsAPresetSaysWhatItIs) {
    const std::string schema = ST_PRESET_DIR "/../schema/preset.schema.json";
    const auto errors = loadErrors(schema);
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0], schema + ": $schema: \"https://json-schema.org/draft/2020-12/schema\" makes this a JSON Schema, "
                                  "not a preset (a preset's \"$schema\" names preset.schema.json)");
    EXPECT_NO_THROW(loadPreset(ST_PRESET_DIR "/default.json"));  // "$schema": "../schema/preset.schema.json"
}

TEST_F(PresetFileTest, DirectoryGivesAClearError) {
    EXPECT_TRUE(hasMessage(loadErrors(dir), dir.string() + ": cannot read preset: is a directory, not a JSON file"));
}

TEST_F(PresetFileTest, MissingFileGivesAClearError) {
    EXPECT_TRUE(hasMessage(loadErrors(dir / "nope.json"), "nope.json: cannot read preset: no such file"));
}

TEST_F(PresetFileTest, SaveLeavesNoTemporaryFile) {
    savePresetAtomic(Settings{}, dir / "p.json");
    savePresetAtomic(test::everyFieldChanged(), dir / "p.json");  // replaces
    EXPECT_EQ(entries(), std::vector<std::string>{"p.json"});
    EXPECT_EQ(loadPreset(dir / "p.json"), test::everyFieldChanged());
}

TEST_F(PresetFileTest, SaveIntoMissingDirectoryThrowsAndLeavesNothing) {
    const auto file = dir / "missing" / "p.json";
    try {
        savePresetAtomic(Settings{}, file);
        FAIL() << "saved into a missing directory";
    } catch (const SettingsError& e) {
        // The folder is named; the temporary file the user never chose is not (issue 21 #8).
        ASSERT_EQ(e.messages().size(), 1u);
        EXPECT_EQ(e.messages()[0], file.string() + ": cannot save preset: the folder " + (dir / "missing").string() +
                                       " does not exist");
    }
    EXPECT_TRUE(entries().empty());
}

TEST_F(PresetFileTest, SchemaReferenceIsWrittenFirstAndReadsBack) {
    savePresetAtomic(test::everyFieldChanged(), dir / "p.json", "../schema/preset.schema.json");
    const nlohmann::json j = loadJsonFile(dir / "p.json");
    EXPECT_EQ(j.value("$schema", ""), "../schema/preset.schema.json");
    std::ifstream in(dir / "p.json");
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    EXPECT_EQ(second, R"(  "$schema": "../schema/preset.schema.json",)");
    EXPECT_EQ(loadPreset(dir / "p.json"), test::everyFieldChanged());
}

TEST_F(PresetFileTest, SaveOverADirectoryFailsAndRemovesTheTemporaryFile) {
    std::filesystem::create_directories(dir / "p.json" / "child");
    EXPECT_THROW(savePresetAtomic(Settings{}, dir / "p.json"), SettingsError);
    EXPECT_EQ(entries(), std::vector<std::string>{"p.json"});
}

TEST_F(PresetFileTest, InvalidSettingsAreNotSaved) {
    Settings s;
    s.cascades.mapSize = 1000;
    try {
        savePresetAtomic(s, dir / "p.json");
        FAIL() << "saved invalid settings";
    } catch (const SettingsError& e) {
        EXPECT_TRUE(hasMessage(e.messages(), "p.json: cannot save invalid settings: cascades.mapSize: must be a power"));
    }
    EXPECT_TRUE(entries().empty());
}

}  // namespace
}  // namespace st
