// File > Open's completion (issue 13 #9): pure, over a scratch folder.
#include "tests/ui/ui_test_data.h"
#include "ui/path_completion.h"

#include <gtest/gtest.h>

using namespace st::ui;

TEST(PathCompletionTest, FoldersAndJsonFilesThatContinueTheText) {
    st::test::ScratchFolder scratch;
    std::filesystem::create_directories(scratch.path / "scenes");
    std::filesystem::create_directories(scratch.path / "scenarios");
    std::filesystem::create_directories(scratch.path / ".hidden");
    scratch.write("default.json", "{}");
    scratch.write("scenes/fox.json", "{}");
    scratch.write("scenes/fox.txt", "");
    scratch.write("sun.json", "{}");
    using V = std::vector<std::string>;
    EXPECT_EQ(completePresetPath(scratch.path, "s"), (V{"scenarios/", "scenes/", "sun.json"}));
    EXPECT_EQ(completePresetPath(scratch.path, "scenes/"), (V{"scenes/fox.json"}));
    EXPECT_EQ(completePresetPath(scratch.path, ""), (V{"default.json", "scenarios/", "scenes/", "sun.json"}));
    EXPECT_EQ(completePresetPath(scratch.path, (scratch.path / "scenes/f").string()), (V{(scratch.path / "scenes/fox.json").string()}));
    EXPECT_TRUE(completePresetPath(scratch.path, "nope/").empty());
    EXPECT_EQ(commonPrefix({"scenarios/", "scenes/"}), "scen");
    EXPECT_EQ(commonPrefix({}), "");
}

// Issue 39 #2: File > Open offers the glTF scenes too (a new preset for each), not other files.
TEST(PathCompletionTest, GltfScenesAreOfferedBesidePresets) {
    st::test::ScratchFolder scratch;
    scratch.write("Fox.glb", "");
    scratch.write("ship.GLTF", "{}");
    scratch.write("ship.bin", "");
    scratch.write("fox.json", "{}");
    using V = std::vector<std::string>;
    EXPECT_EQ(completePresetPath(scratch.path, "F"), (V{"Fox.glb"}));
    EXPECT_EQ(completePresetPath(scratch.path, "s"), (V{"ship.GLTF"})) << "not the .bin beside it";
    EXPECT_TRUE(isGltfFile("a/b.glb"));
    EXPECT_FALSE(isGltfFile("a/b.json"));
}
