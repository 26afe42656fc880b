// A preset saved into another folder still names the files it named (issue 13 #1).
#include "renderer/settings/preset_paths.h"
#include "renderer/settings/settings_json.h"
#include "tests/settings/test_support.h"

#include <gtest/gtest.h>

#include <fstream>

namespace fs = std::filesystem;
using namespace st;

TEST(PresetPathsTest, RelativeReferencesAreRewrittenForTheNewFolder) {
    EXPECT_EQ(rebaseFileReference("../../shared/a.gltf", "/w/repo/presets/scenes", "/tmp/out"), "../../w/repo/shared/a.gltf");
    EXPECT_EQ(rebaseFileReference("a.gltf", "/w/p", "/w/p/sub"), "../a.gltf");
    EXPECT_EQ(rebaseFileReference("sub/a.gltf", "/w/p", "/w/p/sub"), "a.gltf");
    EXPECT_EQ(rebaseFileReference("./x/../a.gltf", "/w/p", "/w/p"), "a.gltf");
}

TEST(PresetPathsTest, BuiltinsAbsolutePathsAndEmptyAreKept) {
    EXPECT_EQ(rebaseFileReference("builtin:yard", "/a", "/b"), "builtin:yard");
    EXPECT_EQ(rebaseFileReference("/abs/a.gltf", "/a", "/b/c"), "/abs/a.gltf");
    EXPECT_EQ(rebaseFileReference("", "/a", "/b"), "");
}

TEST(PresetPathsTest, RelativeFoldersAreTakenFromTheCurrentFolder) {
    const fs::path cwd = fs::current_path();
    EXPECT_EQ(fs::path(rebaseFileReference("a.gltf", "p", cwd / "p" / "q")), fs::path("../a.gltf"));
    EXPECT_EQ(fs::path(rebaseFileReference("a.gltf", "", cwd / "q")), fs::path("../a.gltf"));
}

class PresetPathsFileTest : public test::ScratchDir {};

TEST_F(PresetPathsFileTest, SavedIntoAnotherFolderTheSceneStillResolvesToTheSameFile) {
    fs::create_directories(dir / "assets");
    fs::create_directories(dir / "presets" / "scenes");
    fs::create_directories(dir / "elsewhere" / "deep");
    Settings s;
    s.scene = "../../assets/s.gltf";  // as presets/scenes/*.json name ../shared/assets
    savePresetRebased(s, dir / "presets" / "scenes", dir / "elsewhere" / "deep" / "copy.json");
    const Settings saved = loadPreset(dir / "elsewhere" / "deep" / "copy.json");
    EXPECT_EQ(saved.scene, "../../assets/s.gltf");  // two levels deep again, from elsewhere/deep
    savePresetRebased(s, dir / "presets" / "scenes", dir / "top.json");
    EXPECT_EQ(loadPreset(dir / "top.json").scene, "assets/s.gltf");
    EXPECT_EQ(fs::weakly_canonical(dir / "elsewhere" / "deep" / saved.scene), fs::weakly_canonical(dir / "assets" / "s.gltf"));
}

// Issue 21 #8: the editor's --save-as dropped "$schema"; both saves keep it through these.
TEST_F(PresetPathsFileTest, TheSchemaAPresetNamesIsReadAndRebasedLikeTheScene) {
    fs::create_directories(dir / "presets" / "scenes");
    Settings s;
    savePresetAtomic(s, dir / "presets" / "scenes" / "a.json", "../../schema/preset.schema.json");
    savePresetAtomic(s, dir / "presets" / "none.json");
    EXPECT_EQ(presetSchemaRef(dir / "presets" / "scenes" / "a.json"), "../../schema/preset.schema.json");
    EXPECT_EQ(presetSchemaRef(dir / "presets" / "none.json"), "");
    EXPECT_EQ(presetSchemaRef(dir / "missing.json"), "") << "an unreadable file names no schema";
    EXPECT_EQ(rebaseSchemaRef("../../schema/preset.schema.json", dir / "presets" / "scenes", dir / "presets"),
              "../schema/preset.schema.json");
    EXPECT_EQ(rebaseSchemaRef("https://example.org/preset.schema.json", "/a/b", "/c"), "https://example.org/preset.schema.json");
    EXPECT_EQ(rebaseSchemaRef("", "/a/b", "/c"), "");
}

namespace st {
namespace {

// Issue 39 #10: a preset saved into another folder lacked "$schema" when the preset open had none.
TEST_F(PresetPathsFileTest, APresetWithoutASchemaGetsTheNearestOneAboveItOrAboveTheHint) {
    fs::create_directories(dir / "repo" / "schema");
    fs::create_directories(dir / "repo" / "presets" / "scenes");
    fs::create_directories(dir / "elsewhere" / "deep");
    std::ofstream(dir / "repo" / "schema" / "preset.schema.json") << "{}\n";
    EXPECT_EQ(defaultSchemaRef(dir / "repo" / "presets" / "scenes" / "a.json"), "../../schema/preset.schema.json");
    EXPECT_EQ(defaultSchemaRef(dir / "elsewhere" / "deep" / "b.json"), "") << "no schema above, no hint";
    const std::string ref = defaultSchemaRef(dir / "elsewhere" / "deep" / "b.json", dir / "repo" / "presets");
    EXPECT_EQ(ref, "../../repo/schema/preset.schema.json");
    EXPECT_TRUE(fs::exists(dir / "elsewhere" / "deep" / ref));
}

}  // namespace
}  // namespace st
