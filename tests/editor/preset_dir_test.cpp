#include "app/preset_dir.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace fs = std::filesystem;
using st::app::presetDirFor;

namespace {
class PresetDirTest : public testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("st-preset-dir-" + std::to_string(::getpid()));
        fs::create_directories(root / "cwd");
        fs::create_directories(root / "prefix/bin");
    }
    void TearDown() override { fs::remove_all(root); }
    fs::path exe() const { return root / "prefix/bin/shadowtune"; }
    fs::path installed() const { return root / "prefix/share/shadowtune/presets"; }
    fs::path root;
};
}  // namespace

TEST_F(PresetDirTest, PresetsInTheCurrentFolderWin) {
    fs::create_directories(root / "cwd/presets");
    fs::create_directories(installed());
    EXPECT_EQ(presetDirFor(root / "cwd", exe()), fs::path("presets"));
}

TEST_F(PresetDirTest, InstalledPresetsNextToTheBinaryAreTheFallback) {
    fs::create_directories(installed());
    EXPECT_EQ(presetDirFor(root / "cwd", exe()), installed());
}

TEST_F(PresetDirTest, NeitherGivesTheRelativeDefault) {
    EXPECT_EQ(presetDirFor(root / "cwd", exe()), fs::path("presets"));
    EXPECT_EQ(presetDirFor(root / "cwd", fs::path()), fs::path("presets"));
}

// A scenario preset opened by its path from another folder listed "(no presets found)".
TEST_F(PresetDirTest, APresetOpenedFromElsewhereListsThePresetsFolderHoldingIt) {
    fs::create_directories(root / "repo/presets/scenarios");
    fs::create_directories(installed());
    EXPECT_EQ(presetDirFor(root / "cwd", exe(), root / "repo/presets/scenarios/x.json"), root / "repo/presets");
    EXPECT_EQ(presetDirFor(root / "repo/presets", exe(), "scenarios/x.json"), root / "repo/presets") << "relative to cwd";
    EXPECT_EQ(presetDirFor(root / "cwd", exe(), root / "elsewhere/x.json"), installed()) << "no presets folder above it";
    fs::create_directories(root / "cwd/presets");
    EXPECT_EQ(presetDirFor(root / "cwd", exe(), root / "repo/presets/scenarios/x.json"), fs::path("presets"))
        << "the current folder's presets still come first";
}
