// Document: load/save as messages, never exceptions; the dirty marker and the title.
#include "renderer/settings/settings_json.h"
#include "ui/document.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace st;
using namespace st::ui;

namespace {
class DocumentTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::path(::testing::TempDir()) / ("document_test_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    void write(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }
    fs::path dir;
};
}  // namespace

TEST_F(DocumentTest, SaveThenLoadRoundTripsAndMarksClean) {
    Document doc;
    Settings s;
    s.cascades.lambda = 0.8f;
    ASSERT_TRUE(saveDocument(doc, s, dir / "a.json")) << doc.errors.front();
    EXPECT_FALSE(isDirty(doc, s));
    EXPECT_EQ(doc.file, dir / "a.json");
    s.cascades.lambda = 0.1f;
    EXPECT_TRUE(isDirty(doc, s));
    Document other;
    Settings loaded;
    ASSERT_TRUE(loadDocument(other, dir / "a.json", loaded));
    EXPECT_EQ(loaded.cascades.lambda, 0.8f);
    EXPECT_FALSE(isDirty(other, loaded));
}

TEST_F(DocumentTest, AnInvalidPresetGivesMessagesAndLeavesSettingsAlone) {
    write(dir / "bad.json", R"({"version": 1, "cascades": {"count": 12}})");
    Document doc;
    Settings s;
    s.light.elevation = 12.0f;
    const Settings before = s;
    EXPECT_FALSE(loadDocument(doc, dir / "bad.json", s));
    EXPECT_EQ(s, before);
    ASSERT_FALSE(doc.errors.empty());
    EXPECT_NE(doc.errors.front().find("cascades.count"), std::string::npos) << doc.errors.front();
    EXPECT_TRUE(doc.file.empty());
}

TEST_F(DocumentTest, BrokenJsonAndMissingFilesAreMessagesToo) {
    write(dir / "broken.json", "{\"version\": 1,,}");
    Document doc;
    Settings s;
    EXPECT_FALSE(loadDocument(doc, dir / "broken.json", s));
    ASSERT_FALSE(doc.errors.empty());
    EXPECT_NE(doc.errors.front().find("invalid JSON"), std::string::npos);
    EXPECT_FALSE(loadDocument(doc, dir / "missing.json", s));
    EXPECT_NE(doc.errors.front().find("no such file"), std::string::npos);
}

TEST_F(DocumentTest, SavingInvalidSettingsFailsWithMessagesAndWritesNothing) {
    Document doc;
    Settings s;
    s.camera.nearPlane = 50.0f;
    s.camera.farPlane = 10.0f;
    EXPECT_FALSE(saveDocument(doc, s, dir / "x.json"));
    EXPECT_FALSE(doc.errors.empty());
    EXPECT_FALSE(fs::exists(dir / "x.json"));
}

// Issue 21 #8: Save As into a missing folder failed with "cannot create mine/tuned.json.tmp-25083:
// No such file or directory", and the file saved dropped "$schema".
TEST_F(DocumentTest, SaveAsIntoAMissingFolderCreatesItAndKeepsTheSchemaReference) {
    fs::create_directories(dir / "presets");
    write(dir / "presets" / "a.json", R"({"$schema": "../schema/preset.schema.json", "version": 1})");
    Document doc;
    Settings s;
    ASSERT_TRUE(loadDocument(doc, dir / "presets" / "a.json", s));
    ASSERT_TRUE(saveDocument(doc, s, dir / "presets" / "mine" / "tuned.json")) << doc.errors.front();
    EXPECT_NE(doc.status.find("created the folder"), std::string::npos) << doc.status;
    const nlohmann::json saved = loadJsonFile(dir / "presets" / "mine" / "tuned.json");
    EXPECT_EQ(saved.value("$schema", ""), "../../schema/preset.schema.json") << "rebased for the new folder";
    ASSERT_TRUE(saveDocument(doc, s, dir / "presets" / "b.json"));
    EXPECT_EQ(loadJsonFile(dir / "presets" / "b.json").value("$schema", ""), "../schema/preset.schema.json");
    EXPECT_EQ(doc.status, "Saved " + (dir / "presets" / "b.json").string());

    // A folder that cannot be made (a file is in the way): the reason, and no temporary name.
    write(dir / "plain", "x");
    EXPECT_FALSE(saveDocument(doc, s, dir / "plain" / "x.json"));
    ASSERT_FALSE(doc.errors.empty());
    EXPECT_EQ(doc.errors.front().find(".tmp"), std::string::npos) << doc.errors.front();
    EXPECT_NE(doc.errors.front().find((dir / "plain" / "x.json").string()), std::string::npos) << doc.errors.front();
}

TEST_F(DocumentTest, SaveAsPathsAreResolvedAgainstThePresetFolder) {
    EXPECT_EQ(resolveSavePath("/p", "mine"), fs::path("/p/mine.json"));
    EXPECT_EQ(resolveSavePath("/p", "sub/mine.json"), fs::path("/p/sub/mine.json"));
    EXPECT_EQ(resolveSavePath("/p", "/abs/x.json"), fs::path("/abs/x.json"));
    EXPECT_TRUE(resolveSavePath("/p", "").empty());
}

TEST_F(DocumentTest, TitleShowsTheFileAndTheDirtyMarker) {
    Document doc;
    EXPECT_EQ(documentTitle(doc, false), "shadowtune - untitled");
    doc.file = "/x/presets/default.json";
    EXPECT_EQ(documentTitle(doc, true), "shadowtune - default.json *");
}
