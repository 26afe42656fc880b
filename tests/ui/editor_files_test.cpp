// Saves that load and scenes that fail to load (issue 13 #1), under ImGui's null backend.
#include "renderer/settings/settings_json.h"
#include "tests/ui/ui_driver.h"
#include "tests/ui/ui_test_data.h"

#include <gtest/gtest.h>

namespace fs = std::filesystem;
using namespace st;
using namespace st::test;

namespace {

class EditorFilesTest : public ::testing::Test {
protected:
    void SetUp() override {
        d.in.stats = &stats;
        // Stands in for the app's loader: only files that exist load.
        d.in.checkScene = [this](const std::string& scene, bool, const fs::path& base) -> std::string {
            ++checks;
            if (scene.starts_with("builtin:") || fs::exists(base / scene)) return {};
            return "scene file not found: " + (base / scene).string();
        };
        fs::create_directories(scratch.path / "presets" / "scenes");
        fs::create_directories(scratch.path / "assets");
        scratch.write("assets/s.gltf", "{}");
        d.frames(2);
    }
    void typeInto(const char* key, const std::string& text) {
        d.click(key);
        d.pressKey(65, true);  // Ctrl+A, then type over it
        d.typeText(text.c_str());
    }
    FrameStats stats = fakeFrameStats();
    ScratchFolder scratch;
    UiDriver d;
    int checks = 0;
};

}  // namespace

TEST_F(EditorFilesTest, SaveAsIntoAnotherFolderRewritesTheScenePathEverywhere) {
    d.s.scene = "../../assets/s.gltf";
    d.ui().setDocument(d.s, scratch.path / "presets" / "scenes" / "a.json");
    d.s.light.elevation = 20.0f;  // an edit in the history, made while the scene path was the old one
    d.frame();
    fs::create_directories(scratch.path / "out" / "x");
    typeInto("presets.saveAsPath", (scratch.path / "out" / "x" / "b").string());
    d.click("presets.saveAs");
    ASSERT_TRUE(d.ui().errors().empty()) << d.ui().errors().front();
    const Settings saved = loadPreset(scratch.path / "out" / "x" / "b.json");
    EXPECT_EQ(saved.scene, "../../assets/s.gltf");  // two levels under the scratch folder again
    EXPECT_EQ(d.s.scene, saved.scene);
    EXPECT_FALSE(d.ui().dirty());
    typeInto("presets.saveAsPath", (scratch.path / "c").string());
    d.click("presets.saveAs");
    EXPECT_EQ(loadPreset(scratch.path / "c.json").scene, "assets/s.gltf");
    EXPECT_EQ(d.s.scene, "assets/s.gltf");
    EXPECT_TRUE(fs::exists(scratch.path / d.s.scene));
}

TEST_F(EditorFilesTest, ASceneThatFailsToLoadLeavesEverythingAsItWas) {
    d.ui().setDocument(d.s, scratch.path / "presets" / "a.json");
    const Settings before = d.s;
    typeInto("scene.gltf", "missing.gltf");
    d.pressKey(kKeyEnter);
    d.frame();
    EXPECT_GT(checks, 0);
    EXPECT_EQ(d.s, before);
    EXPECT_FALSE(d.ui().dirty());
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "presets" / "a.json");
    ASSERT_TRUE(d.drawn("scene.error")) << "the reason is shown next to the field";
    d.click("presets.undo");  // disabled: nothing was recorded
    EXPECT_EQ(d.s, before);
    d.frames(3);
    EXPECT_TRUE(d.drawn("scene.error")) << "it stays until the field changes";
    typeInto("scene.gltf", "../assets/s.gltf");
    EXPECT_FALSE(d.drawn("scene.error"));
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.s.scene, "../assets/s.gltf");
}

TEST_F(EditorFilesTest, APresetWhoseSceneFailsToLoadIsRefusedWhole) {
    Settings other;
    other.scene = "nowhere.gltf";
    other.cascades.lambda = 0.9f;
    savePresetAtomic(other, scratch.path / "presets" / "other.json");
    d.in.presetFiles = {scratch.path / "presets" / "other.json"};
    d.ui().setDocument(d.s, scratch.path / "presets" / "a.json");
    const Settings before = d.s;
    d.frame();
    d.click("preset:other.json");
    EXPECT_EQ(d.s, before);
    EXPECT_FALSE(d.last.presetLoaded);
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "presets" / "a.json");
    ASSERT_EQ(d.ui().errors().size(), 1u);
    EXPECT_NE(d.ui().errors().front().find("scene file not found"), std::string::npos) << d.ui().errors().front();
}

// Issue 13 #9: File > Open with completion, Revert.
TEST_F(EditorFilesTest, FileOpenCompletesJsonPathsAndLoadsTheChosenPreset) {
    Settings other;
    other.cascades.lambda = 0.9f;
    savePresetAtomic(other, scratch.path / "presets" / "scenes" / "boat.json");
    scratch.write("presets/scenes/notes.txt", "not offered");
    d.click("menu.file");
    d.click("menu.open");
    ASSERT_TRUE(d.drawn("open.path"));
    const std::string folder = (scratch.path / "presets").string() + "/";
    d.frames(2);  // the new window takes the keyboard once it is shown
    EXPECT_TRUE(ImGui::GetIO().WantTextInput) << "the cursor is in the path field";
    d.typeText((folder + "sc").c_str());
    d.frame();
    EXPECT_TRUE(d.drawn("open:" + folder + "scenes/"));
    d.pressKey(kKeyTab);  // completes the folder, and does not swap the views while typing
    EXPECT_FALSE(d.last.swapSideView);
    d.frame();
    EXPECT_TRUE(d.drawn("open:" + folder + "scenes/boat.json"));
    EXPECT_FALSE(d.drawn("open:" + folder + "scenes/notes.txt"));
    d.typeText("b");
    d.pressKey(kKeyTab);  // unique: completed to the file
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "presets" / "scenes" / "boat.json");
    EXPECT_EQ(d.s, other);
    d.frame();
    EXPECT_FALSE(d.drawn("open.path")) << "the window closes once the preset is loaded";
}

// Issue 39 #2: File > Open on a .glb makes a new, untitled preset for that scene (the app's
// presetForScene: here a stand-in), its history fresh, Save as offering <name>.json in the presets
// folder; a glTF that does not load leaves everything as it was and says why.
TEST_F(EditorFilesTest, FileOpenOnAGltfMakesANewPresetForIt) {
    scratch.write("assets/Fox.glb", "");
    scratch.write("assets/Broken.glb", "");
    Settings made;
    made.scene = (scratch.path / "assets" / "s.gltf").string();  // a scene the stand-in loader takes
    made.cascades.count = 2;
    d.in.presetForScene = [&](const fs::path& gltf) -> Settings {
        if (gltf.filename() == "Broken.glb") throw std::runtime_error("glTF: no triangles");
        return made;
    };
    const Settings before = d.s;
    d.click("menu.file");
    d.click("menu.open");
    d.frames(2);
    d.typeText((scratch.path / "assets" / "Broken.glb").string().c_str());
    d.pressKey(kKeyEnter);
    d.frame();
    EXPECT_EQ(d.s, before) << "a glTF that does not load changes nothing";
    EXPECT_TRUE(d.drawn("open.path")) << "and the window stays, with the reason";
    d.pressKey(65, true);  // Ctrl+A: type over the path
    d.typeText((scratch.path / "assets" / "Fox.glb").string().c_str());
    d.pressKey(kKeyEnter);
    d.frame();
    EXPECT_EQ(d.s, made);
    EXPECT_TRUE(d.ui().presetFile().empty()) << "untitled: saving asks where";
    EXPECT_FALSE(d.ui().dirty());
    EXPECT_FALSE(d.drawn("open.path"));
}

// Issue 21 #7: typing into File > Open appended to the last path; after a failed Enter the field
// lost the keyboard and the next Tab swapped the main and side views.
TEST_F(EditorFilesTest, FileOpenSelectsTheLastPathAndKeepsTheKeyboardAfterAFailedEnter) {
    Settings other;
    other.cascades.lambda = 0.9f;
    savePresetAtomic(other, scratch.path / "presets" / "boat.json");
    d.click("menu.file");
    d.click("menu.open");
    d.frames(2);
    d.typeText((scratch.path / "presets" / "nothing-here.json").string().c_str());
    d.pressKey(kKeyEnter);
    d.frames(2);
    ASSERT_TRUE(d.drawn("open.path")) << "a failed load keeps the window";
    EXPECT_TRUE(ImGui::GetIO().WantTextInput) << "and the cursor in its field";
    d.pressKey(kKeyTab);
    EXPECT_FALSE(d.last.swapSideView);
    d.pressKey(kKeyEscape);  // leave the field, close the window
    d.click("menu.file");
    d.click("menu.open");
    d.frames(2);
    EXPECT_TRUE(ImGui::GetIO().WantTextInput);
    d.typeText((scratch.path / "presets" / "boat.json").string().c_str());  // over the last path
    d.pressKey(kKeyEnter);
    EXPECT_EQ(d.ui().presetFile(), scratch.path / "presets" / "boat.json") << (d.ui().errors().empty() ? "" : d.ui().errors()[0]);
}

TEST_F(EditorFilesTest, RevertReloadsTheFileAfterAskingAndIsOffWhenClean) {
    savePresetAtomic(d.s, scratch.path / "presets" / "a.json");
    ASSERT_TRUE(d.ui().openPreset(scratch.path / "presets" / "a.json", d.s));
    const Settings saved = d.s;
    d.s.light.elevation = 5.0f;
    d.frame();
    ASSERT_TRUE(d.ui().dirty());
    d.click("menu.file");
    d.click("menu.revert");
    d.click("confirm.discard");
    EXPECT_EQ(d.s, saved);
    EXPECT_FALSE(d.ui().dirty());
}

TEST_F(EditorFilesTest, ThePresetListShowsSubFolderFiles) {
    d.in.presetFiles = {scratch.path / "presets" / "a.json", scratch.path / "presets" / "scenes" / "fox.json"};
    d.frame();
    EXPECT_TRUE(d.drawn("preset:a.json"));
    EXPECT_TRUE(d.drawn("preset:fox.json"));
}
