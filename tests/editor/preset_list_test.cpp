// The preset list includes sub-folders but not sweeps (issue 13 #9).
#include "app/editor/preset_list.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace fs = std::filesystem;

TEST(PresetListTest, SubFoldersAreListedAndSweepsAreNot) {
    const fs::path root = fs::temp_directory_path() / ("st-preset-list-" + std::to_string(::getpid()));
    for (const char* sub : {"scenes", "scenarios", "engines", "sweeps", "engines/old"}) fs::create_directories(root / sub);
    for (const char* file : {"b.json", "a.json", "README.md", "scenes/fox.json", "scenarios/x.json",
                             "engines/unity.json", "engines/old/u4.json", "sweeps/s.json"})
        std::ofstream(root / file) << "{}";
    const std::vector<fs::path> expected{root / "a.json", root / "b.json", root / "engines/unity.json",
                                         root / "scenarios/x.json", root / "scenes/fox.json",
                                         root / "engines/old/u4.json"};
    EXPECT_EQ(st::app::listPresetFiles(root), expected);
    EXPECT_TRUE(st::app::listPresetFiles(root / "missing").empty());
    fs::remove_all(root);
}

TEST(PresetListTest, TheRepositoryPresetsIncludeScenesScenariosAndEngines) {
    const auto files = st::app::listPresetFiles(ST_PRESET_DIR);
    const auto has = [&](const char* rel) { return std::find(files.begin(), files.end(), fs::path(ST_PRESET_DIR) / rel) != files.end(); };
    EXPECT_TRUE(has("default.json"));
    EXPECT_TRUE(has("scenes/fox.json"));
    EXPECT_TRUE(has("engines/unity.json"));
    EXPECT_TRUE(has("scenarios/sun-overhead.json"));
    for (const auto& f : files) EXPECT_EQ(f.string().find("/sweeps/"), std::string::npos) << f;
}
